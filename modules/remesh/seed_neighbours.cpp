#include "modules/remesh/seed_neighbours.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nanoflann.hpp>

#include "framework/geometry/point_cloud.h"

namespace voroseal {

namespace {

// k nearest with ties broken by index, optionally skipping one index (the query seed itself).
class NearestSet {
 public:
  NearestSet(int capacity, std::uint32_t skip, std::uint32_t* indices, double* dists)
      : capacity_(capacity), skip_(skip), indices_(indices), dists_(dists) {}
  /// Seeds the set with known points (a warm start that tightens the search's pruning); later
  /// additions then skip points already present.
  void prefill(const int* points, int count, const Vec3* xyz, const Vec3& query) {
    for (int i = 0; i < count; ++i)
      addPoint((xyz[points[i]] - query).squaredNorm(), static_cast<std::uint32_t>(points[i]));
    check_duplicates_ = true;
  }
  size_t size() const { return count_; }
  bool full() const { return count_ == capacity_; }
  double worstDist() const {
    return capacity_ > 0 && full() ? dists_[capacity_ - 1] : std::numeric_limits<double>::max();
  }
  bool addPoint(double d, std::uint32_t index) {
    if (index == skip_) return true;
    if (capacity_ <= 0) return true;
    if (check_duplicates_)
      for (int i = 0; i < count_; ++i)
        if (indices_[i] == index) return true;
    if (full() && !less(d, index, dists_[capacity_ - 1], indices_[capacity_ - 1])) return true;
    int i = count_ < capacity_ ? count_++ : capacity_ - 1;
    while (i > 0 && less(d, index, dists_[i - 1], indices_[i - 1])) {
      dists_[i] = dists_[i - 1];
      indices_[i] = indices_[i - 1];
      --i;
    }
    dists_[i] = d;
    indices_[i] = index;
    return true;
  }

 private:
  static bool less(double d1, std::uint32_t i1, double d2, std::uint32_t i2) {
    return d1 < d2 || (d1 == d2 && i1 < i2);
  }
  int capacity_;
  int count_ = 0;
  bool check_duplicates_ = false;
  std::uint32_t skip_;
  std::uint32_t* indices_;
  double* dists_;
};

// The single nearest point, ties broken by index.
class NearestOne {
 public:
  size_t size() const { return found_ ? 1 : 0; }
  bool full() const { return found_; }
  double worstDist() const { return found_ ? dist_ : std::numeric_limits<double>::max(); }
  bool addPoint(double d, std::uint32_t index) {
    if (!found_ || d < dist_ || (d == dist_ && index < index_)) {
      dist_ = d;
      index_ = index;
      found_ = true;
    }
    return true;
  }
  std::uint32_t index() const { return index_; }

 private:
  bool found_ = false;
  double dist_ = 0.0;
  std::uint32_t index_ = 0;
};

}  // namespace

struct SeedNeighbours::Tree {
  PointCloud cloud;
  std::unique_ptr<PointKdTree> index;
};

SeedNeighbours::SeedNeighbours() = default;
SeedNeighbours::~SeedNeighbours() = default;

const SeedNeighbours::Tree& SeedNeighbours::tree() const {
  if (const Tree* t = tree_ready_.load(std::memory_order_acquire)) return *t;
  std::lock_guard<std::mutex> lock(tree_mutex_);
  if (!tree_) {
    auto t = std::make_unique<Tree>();
    t->cloud.points = seeds_;
    t->cloud.count = static_cast<size_t>(n_);
    t->index = std::make_unique<PointKdTree>(3, t->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(12));
    if (n_ > 0) t->index->buildIndex();
    tree_ = std::move(t);
  }
  tree_ready_.store(tree_.get(), std::memory_order_release);
  return *tree_;
}

void SeedNeighbours::build(const Vec3* seeds, int n, int k, int threads) {
  build(seeds, n, std::vector<int>(n, k), threads);
}

void SeedNeighbours::build(const Vec3* seeds, int n, const std::vector<int>& k, int threads) {
  // The previous lists of the same seeds warm-start the searches.
  const bool warm = n == n_ && static_cast<int>(start_.size()) == n + 1 && n > 0;
  if (warm) {
    previous_start_.swap(start_);
    previous_lists_.swap(lists_);
  }
  seeds_ = seeds;
  n_ = n;
  // A new set of seeds: a new tree.
  tree_ready_.store(nullptr, std::memory_order_release);
  tree_.reset();
  start_.assign(n + 1, 0);
  bound2_.assign(n, std::numeric_limits<double>::infinity());
  int kmax = 0;
  for (int s = 0; s < n; ++s) {
    const int ks = std::max(0, std::min(k[s], n - 1));
    start_[s + 1] = start_[s] + ks;
    kmax = std::max(kmax, ks);
  }
  lists_.resize(start_[n]);
  if (n == 0) return;
  const Tree& t = tree();
  if (kmax == 0) return;
  const int nthreads = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel num_threads(nthreads)
  {
    std::vector<std::uint32_t> idx(kmax);
    std::vector<double> dist(kmax);
#pragma omp for schedule(static, 512)
    for (int s = 0; s < n; ++s) {
      const int ks = start_[s + 1] - start_[s];
      NearestSet result(ks, static_cast<std::uint32_t>(s), idx.data(), dist.data());
      if (warm)
        result.prefill(previous_lists_.data() + previous_start_[s], previous_start_[s + 1] - previous_start_[s], seeds,
                       seeds[s]);
      t.index->findNeighbors(result, seeds[s].data(), nanoflann::SearchParams());
      int* out = lists_.data() + start_[s];
      for (int j = 0; j < ks; ++j) out[j] = static_cast<int>(idx[j]);
      // Seeds left out are at least as far as the last one listed (all listed: none left out).
      if (ks < n - 1) bound2_[s] = ks > 0 ? dist[ks - 1] : 0.0;
    }
  }
  reference_.assign(seeds, seeds + n);
  built_bound_.resize(n);
  for (int s = 0; s < n; ++s) built_bound_[s] = std::sqrt(bound2_[s]);
}

bool SeedNeighbours::update(const Vec3* seeds, int n, double max_motion, int threads) {
  if (n != n_ || static_cast<int>(reference_.size()) != n || n == 0) return false;
  double motion2 = 0.0;
  for (int s = 0; s < n; ++s) motion2 = std::max(motion2, (seeds[s] - reference_[s]).squaredNorm());
  const double motion = std::sqrt(motion2);
  if (!(motion <= max_motion)) return false;
  seeds_ = seeds;
  // The tree was built on other positions: rebuild it on first use.
  tree_ready_.store(nullptr, std::memory_order_release);
  tree_.reset();
  const int nthreads = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel num_threads(nthreads)
  {
    std::vector<std::pair<double, int>> keyed;
#pragma omp for schedule(static, 512)
    for (int s = 0; s < n; ++s) {
      int* list = lists_.data() + start_[s];
      const int ks = start_[s + 1] - start_[s];
      keyed.resize(ks);
      for (int j = 0; j < ks; ++j) keyed[j] = {(seeds[list[j]] - seeds[s]).squaredNorm(), list[j]};
      // Nearly sorted already: insertion sort.
      for (int j = 1; j < ks; ++j)
        for (int i = j; i > 0 && keyed[i] < keyed[i - 1]; --i) std::swap(keyed[i], keyed[i - 1]);
      for (int j = 0; j < ks; ++j) list[j] = keyed[j].second;
      if (std::isfinite(built_bound_[s])) {
        const double b = std::max(0.0, built_bound_[s] - 2.0 * motion);
        bound2_[s] = b * b;
      }
    }
  }
  return true;
}

int SeedNeighbours::nearest(const Vec3& x) const {
  NearestOne result;
  tree().index->findNeighbors(result, x.data(), nanoflann::SearchParams());
  return static_cast<int>(result.index());
}

int SeedNeighbours::nearest_to_seed(int s, int k, int* out) const {
  k = std::max(0, std::min(k, n_ - 1));
  if (k == 0) return 0;
  thread_local std::vector<std::uint32_t> idx;
  thread_local std::vector<double> dist;
  idx.resize(k);
  dist.resize(k);
  NearestSet result(k, static_cast<std::uint32_t>(s), idx.data(), dist.data());
  tree().index->findNeighbors(result, seeds_[s].data(), nanoflann::SearchParams());
  const int found = static_cast<int>(result.size());
  for (int j = 0; j < found; ++j) out[j] = static_cast<int>(idx[j]);
  return found;
}

}  // namespace voroseal
