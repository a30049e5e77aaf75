// SeedNeighbours: for every seed, its nearest other seeds sorted by distance, with a certified
// bound: every seed missing from the list is at least that far. Clipping a triangle by the
// Voronoi cell of a seed walks this list and stops as soon as the security radius proves the
// cell complete (Lévy & Bonneel 2013): when 2·max|x − p_s| over the clipped polygon is at most
// the distance of the next candidate (listed or not), no farther seed can cut the polygon.
// When the list runs out first, the clipper asks nearest_to_seed() for a longer one.
//
// The lists and queries use a k-d tree (nanoflann). (A uniform grid was tried for the lists: no
// faster on surface samplings, and its fixed search radius cannot adapt to uneven cells.)
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "framework/core/types.h"

namespace voroseal {

class SeedNeighbours {
 public:
  SeedNeighbours();
  ~SeedNeighbours();
  SeedNeighbours(const SeedNeighbours&) = delete;
  SeedNeighbours& operator=(const SeedNeighbours&) = delete;

  /// Builds the lists of seeds[0..n) (the array must stay valid and unchanged while this object
  /// is queried): at most k[s] neighbours for seed s (or `k` for all), with `threads` OpenMP
  /// threads (0: default). Ties in distance are broken by seed index, so lists are
  /// deterministic. A build for the same number of seeds as the last one starts each search
  /// from the previous list (same result, much less searching when seeds moved little).
  void build(const Vec3* seeds, int n, int k, int threads);
  void build(const Vec3* seeds, int n, const std::vector<int>& k, int threads);

  /// Reuses the lists built for earlier positions of the same seeds (Verlet lists): when no
  /// seed moved more than `max_motion` since the last build(), re-sorts every list by the
  /// current distances and lowers each bound by twice the largest motion (a seed left out
  /// moved at most that much closer). Returns false, changing nothing, when the seeds moved
  /// more or their number changed: call build() then. `seeds` must stay valid as for build().
  bool update(const Vec3* seeds, int n, double max_motion, int threads);

  int num_seeds() const { return n_; }
  /// Length of the list of seed s.
  int list_size(int s) const { return start_[s + 1] - start_[s]; }
  /// The list of seed s, nearest first.
  const int* neighbours(int s) const { return lists_.data() + start_[s]; }
  /// Every seed other than s that is not in its list is at squared distance >= this from it
  /// (infinity when the list holds all other seeds). After update(), listed seeds may lie
  /// beyond it.
  double bound2(int s) const { return bound2_[s]; }

  /// The nearest seed to x (lowest index among equidistant ones). Precondition: n > 0.
  /// Thread-safe.
  int nearest(const Vec3& x) const;
  /// The k nearest other seeds of seed s, nearest first, into out[0..k); returns how many
  /// were found (fewer than k only when there are fewer other seeds). Thread-safe.
  int nearest_to_seed(int s, int k, int* out) const;

 private:
  struct Tree;
  const Tree& tree() const;  // built on first use
  mutable std::unique_ptr<Tree> tree_;
  mutable std::mutex tree_mutex_;
  mutable std::atomic<const Tree*> tree_ready_{nullptr};
  const Vec3* seeds_ = nullptr;
  int n_ = 0;
  std::vector<int> start_;  // CSR offsets into lists_
  std::vector<int> lists_;
  std::vector<double> bound2_;
  std::vector<int> previous_start_, previous_lists_;  // warm start of the next build()
  std::vector<Vec3> reference_;       // positions at the last build()
  std::vector<double> built_bound_;   // sqrt of bound2_ at the last build()
};

}  // namespace voroseal
