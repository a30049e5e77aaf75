// Clipping of input triangles by Voronoi cells, and the traversal that computes the restricted
// Voronoi diagram one triangle at a time (Lévy & Bonneel 2013, as used in paper §3.1).
// Internal to modules/remesh: the full diagram (restricted_voronoi_diagram.h) and the lean
// energy path (seed_energy.h) are two visitors of the same traversal.
//
// Clipping is Sutherland–Hodgman of the triangle by the bisector half-spaces of the seed and its
// nearest neighbours, in two alternating buffers, stopped by the security radius. Every vertex
// carries the *support* of the edge leaving it (a neighbour seed for a bisector edge, or a
// triangle edge), so each vertex is known symbolically as the intersection of two supports.
//
// Robustness and consistency rules (what makes the combinatorics exact across triangles):
//  - side(x; s, q) = |x − p_s|² − |x − p_q|², each squared distance computed by the same
//    expression, so side(x; q, s) = −side(x; s, q) bit for bit;
//  - a point with side 0 belongs to the seed of lower index (symbolic tie-break), so every
//    point of the model belongs to exactly one seed, also for coincident seeds (the higher
//    index gets an empty cell), and a seed's copy is not clipped by again (the same bisector,
//    whose edge must name the seed that owns the cell beyond);
//  - a bisector crossing a triangle edge (a, b) is computed from the original end points in the
//    order of increasing model vertex id, so the polygons of the two (or more) triangles
//    sharing the edge get the very same point.
#pragma once

#include <omp.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "modules/remesh/model_geometry.h"
#include "modules/remesh/seed_neighbours.h"

namespace voroseal::rvd_detail {

/// A vertex of a clipped polygon.
struct ClipVertex {
  Vec3 x;         // position
  double d2;      // |x − p_seed|²
  double w;       // density at x
  double side;    // scratch: side of x with respect to the current bisector
  int support;    // what the edge from this vertex to the next lies on (see below)
};

/// Support codes: >= 0 is the bisector of the polygon's seed and that seed; < 0 is triangle
/// edge k = (v[k], v[k+1 mod 3]) encoded as −1 − k.
constexpr int edge_support(int k) { return -1 - k; }
constexpr int support_edge(int support) { return -1 - support; }

/// A longer neighbour list fetched for one seed whose list ran out.
struct ExtendedList {
  int seed = -1;
  int size = 0;
  std::vector<int> list;
};

/// Extended lists a thread keeps during one traversal, by seed index modulo this: the flood
/// through a triangle alternates between a few seeds, so keeping one list would fetch the same
/// one again and again.
constexpr int kExtendedSlots = 64;

/// Scratch space of one thread; reused across triangles and evaluations (no allocation in the
/// inner loop once warm).
struct ClipWorkspace {
  std::vector<ClipVertex> buffer[2];
  ExtendedList extended[kExtendedSlots];
  long extended_queries = 0;

  ClipWorkspace() {
    buffer[0].resize(64);
    buffer[1].resize(64);
  }
  /// Forgets the extended lists (the seeds moved).
  void forget_extended() {
    for (ExtendedList& e : extended) e.seed = -1;
  }
};

/// |a − b|², by the one expression every side test uses (see the rules above).
inline double squared_distance(const Vec3& a, const Vec3& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

/// Whether seed list[j], at squared distance dq2 from p_s, is at the very place of a seed
/// listed before it (lists are ordered by distance, then index).
inline bool repeats_earlier(const int* list, int j, const Vec3* seeds, const Vec3& ps, double dq2) {
  const Vec3& pq = seeds[list[j]];
  for (int k = j - 1; k >= 0; --k) {
    const Vec3& pk = seeds[list[k]];
    if (squared_distance(pk, ps) != dq2) return false;
    if (pk == pq) return true;
  }
  return false;
}

/// Clips `rec` by the Voronoi cell of seed s. Returns the number of vertices (0: empty, else
/// >= 3) and points `out` at them (valid until the next call with the same workspace).
/// Vertices keep the orientation of the triangle. `used` receives how many neighbours of s
/// (in distance order) the result needed, so the next evaluation can fetch just that many.
template <bool kDensity>
int clip_triangle(const TriangleRecord& rec, int s, const Vec3* seeds, const SeedNeighbours& nb, ClipWorkspace& ws,
                  const ClipVertex*& out, int& used) {
  const Vec3 ps = seeds[s];
  const auto sq = squared_distance;

  // Every seed missing from `list` is at squared distance >= `bound2` from p_s.
  const int* list = nb.neighbours(s);
  int count = nb.list_size(s);
  double bound2 = nb.bound2(s);
  ExtendedList& extended = ws.extended[s % kExtendedSlots];
  auto extended_bound2 = [&]() {
    if (extended.size < static_cast<int>(extended.list.size()))
      return std::numeric_limits<double>::infinity();
    return extended.size > 0 ? sq(seeds[extended.list[extended.size - 1]], ps) : 0.0;
  };
  if (extended.seed == s) {
    list = extended.list.data();
    count = extended.size;
    bound2 = extended_bound2();
  }

  for (;;) {
    ClipVertex* cur = ws.buffer[0].data();
    int which = 0;
    int n = 3;
    double r2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      ClipVertex& v = cur[k];
      v.x = rec.p[k];
      v.d2 = sq(rec.p[k], ps);
      v.w = kDensity ? rec.density[k] : 1.0;
      v.support = edge_support(k);
      r2 = std::max(r2, v.d2);
    }
    bool certified = false;
    double previous_dq2 = -1.0;
    for (int j = 0; j < count; ++j) {
      const int q = list[j];
      const Vec3& pq = seeds[q];
      const double dq2 = sq(pq, ps);
      // Security radius: every remaining seed (listed or not) is at least min(dq2, bound2)
      // away, so its bisector is at least half that from p_s, beyond every polygon vertex.
      if (4.0 * r2 <= std::min(dq2, bound2)) {
        certified = true;
        used = j + 1;
        break;
      }
      // A copy of a seed listed before it (as far, so just before) has the same bisector,
      // already applied; clipping again could hand that edge to the copy, whose cell is empty,
      // and the flood would then miss the cell beyond.
      const bool same_distance = dq2 == previous_dq2;
      previous_dq2 = dq2;
      if (same_distance && repeats_earlier(list, j, seeds, ps, dq2)) continue;
      bool all_in = true, all_out = true;
      const bool tie_in = s < q;
      for (int i = 0; i < n; ++i) {
        ClipVertex& v = cur[i];
        v.side = v.d2 - sq(v.x, pq);
        const bool in = v.side < 0.0 || (v.side == 0.0 && tie_in);
        all_in = all_in && in;
        all_out = all_out && !in;
      }
      if (all_in) continue;
      if (all_out) {
        out = cur;
        used = j + 1;
        return 0;
      }
      std::vector<ClipVertex>& next_buffer = ws.buffer[1 - which];
      if (static_cast<int>(next_buffer.size()) < 2 * n) next_buffer.resize(2 * n);
      ClipVertex* nxt = next_buffer.data();
      int m = 0;
      r2 = 0.0;
      for (int i = 0; i < n; ++i) {
        const ClipVertex& a = cur[i];
        const ClipVertex& b = cur[i + 1 == n ? 0 : i + 1];
        const bool a_in = a.side < 0.0 || (a.side == 0.0 && tie_in);
        const bool b_in = b.side < 0.0 || (b.side == 0.0 && tie_in);
        if (a_in) {
          nxt[m++] = a;
          r2 = std::max(r2, a.d2);
        }
        if (a_in == b_in) continue;
        ClipVertex& c = nxt[m++];
        bool done = false;
        if (a.support < 0) {
          // On triangle edge e: intersect the original edge, ends in increasing vertex id.
          const int e = support_edge(a.support);
          const int e1 = e == 2 ? 0 : e + 1;
          int ia = e, ib = e1;
          if (rec.v[ia] > rec.v[ib]) std::swap(ia, ib);
          const Vec3& A = rec.p[ia];
          const Vec3& B = rec.p[ib];
          const double sa = sq(A, ps) - sq(A, pq);
          const double sb = sq(B, ps) - sq(B, pq);
          if (sa != sb) {
            double t = sa / (sa - sb);
            t = std::min(std::max(t, 0.0), 1.0);
            c.x = A + t * (B - A);
            if (kDensity) c.w = rec.density[ia] + t * (rec.density[ib] - rec.density[ia]);
            done = true;
          }
        }
        if (!done) {
          // On a bisector edge (or a degenerate edge): intersect the current polygon edge.
          double t = a.side / (a.side - b.side);
          t = std::min(std::max(t, 0.0), 1.0);
          c.x = a.x + t * (b.x - a.x);
          if (kDensity) c.w = a.w + t * (b.w - a.w);
        }
        if (!kDensity) c.w = 1.0;
        c.d2 = sq(c.x, ps);
        c.support = a_in ? q : a.support;
        r2 = std::max(r2, c.d2);
      }
      n = m;
      which = 1 - which;
      cur = nxt;
    }
    if (certified || 4.0 * r2 <= bound2) {
      if (!certified) used = count;
      out = cur;
      return n;
    }
    // The list ran out before the security radius was reached: get a longer one and redo.
    const int want = std::max(32, 2 * count);
    extended.list.resize(want);
    extended.size = nb.nearest_to_seed(s, want, extended.list.data());
    extended.seed = s;
    ++ws.extended_queries;
    list = extended.list.data();
    count = extended.size;
    bound2 = extended_bound2();
  }
}

/// Per-thread state of the traversal.
struct TraversalState {
  ClipWorkspace clip;
  std::vector<int> needed;   // per seed: longest neighbour list a clip needed
  std::vector<int> visited;  // per seed: last record index that visited it
  std::vector<int> stack;
  long fallbacks = 0;        // triangles whose start seed had to be searched in the k-d tree
  long skipped = 0;          // triangles no seed could be found for (never expected)
  long polygons = 0;
};

/// Triangles per unit of work of the traversal (Morton-contiguous records).
constexpr int kTraversalChunk = 256;
inline int traversal_chunks(int num_records) { return (num_records + kTraversalChunk - 1) / kTraversalChunk; }

/// Calls visitors[thread].polygon(seed, record, vertices, count) for every non-empty
/// (seed, triangle) polygon of the restricted Voronoi diagram. For each triangle, starts from
/// hint[record] (a seed whose cell met it last time) or from the seed nearest to its centroid,
/// and floods through the bisector edges of the clipped polygons: the cells meeting a convex
/// triangle form a connected set.
/// Records are processed in chunks of kTraversalChunk, handed to threads dynamically (so a
/// thread slowed down by other processes does less); visitors[thread].begin_chunk(c) and
/// end_chunk(c) bracket chunk c, so a visitor can keep per-chunk results and combine them in
/// chunk order: then nothing depends on the number of threads or on the schedule.
/// `nthreads` <= visitors.size() == states.size().
template <bool kDensity, class Visitor>
void traverse_restricted_polygons(const ModelGeometry& geometry, const Vec3* seeds, int num_seeds,
                                  const SeedNeighbours& nb, std::vector<int>& hint,
                                  std::vector<TraversalState>& states, std::vector<Visitor>& visitors,
                                  int nthreads) {
  const std::vector<TriangleRecord>& records = geometry.triangles();
  const int nrec = static_cast<int>(records.size());
  if (static_cast<int>(hint.size()) != nrec) hint.assign(nrec, -1);
  if (num_seeds == 0) return;
  const int nchunks = traversal_chunks(nrec);
#pragma omp parallel num_threads(nthreads)
  {
    const int tid = omp_get_thread_num();
    TraversalState& st = states[tid];
    Visitor& visitor = visitors[tid];
    st.visited.assign(num_seeds, -1);
    st.needed.assign(num_seeds, 0);
    st.clip.forget_extended();
    st.stack.reserve(64);
#pragma omp for schedule(dynamic, 1)
    for (int c = 0; c < nchunks; ++c) {
      visitor.begin_chunk(c);
      const int end = std::min(nrec, (c + 1) * kTraversalChunk);
      for (int r = c * kTraversalChunk; r < end; ++r) {
        const TriangleRecord& rec = records[r];
        const ClipVertex* poly = nullptr;
        int s0 = hint[r];
        int n = 0;
        auto clip = [&](int s) {
          int used = 0;
          const int m = clip_triangle<kDensity>(rec, s, seeds, nb, st.clip, poly, used);
          if (used > st.needed[s]) st.needed[s] = used;
          return m;
        };
        if (s0 >= 0 && s0 < num_seeds) n = clip(s0);
        if (n == 0) {
          ++st.fallbacks;
          s0 = nb.nearest((rec.p[0] + rec.p[1] + rec.p[2]) / 3.0);
          n = clip(s0);
          for (int k = 0; k < 3 && n == 0; ++k) {
            s0 = nb.nearest(rec.p[k]);
            n = clip(s0);
          }
          if (n == 0) {
            ++st.skipped;
            continue;
          }
        }
        hint[r] = s0;
        st.visited[s0] = r;
        int s = s0;
        for (;;) {
          if (n > 0) {
            ++st.polygons;
            visitor.polygon(s, rec, poly, n);
            for (int i = 0; i < n; ++i) {
              const int q = poly[i].support;
              if (q >= 0 && st.visited[q] != r) {
                st.visited[q] = r;
                st.stack.push_back(q);
              }
            }
          }
          if (st.stack.empty()) break;
          s = st.stack.back();
          st.stack.pop_back();
          n = clip(s);
        }
      }
      visitor.end_chunk(c);
    }
  }
}

/// Threads to use: `requested` when > 0, else OpenMP's default.
inline int resolve_threads(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }

/// Threads worth starting for `work` triangles + seeds: below a few thousand, the cost of
/// waking and synchronising threads (large on a loaded machine) exceeds the work.
inline int active_threads(int threads, long work) { return work < 8192 ? 1 : threads; }

/// traverse_restricted_polygons() once over the whole model, with fresh traversal states and no
/// hint, one thread per visitor, with the model's density or without.
template <class Visitor>
void traverse_once(const ModelGeometry& geometry, const std::vector<Vec3>& seeds,
                   const SeedNeighbours& nb, std::vector<Visitor>& visitors) {
  const int n = static_cast<int>(seeds.size()), threads = static_cast<int>(visitors.size());
  std::vector<int> hint;
  std::vector<TraversalState> states(visitors.size());
  if (geometry.has_density())
    traverse_restricted_polygons<true>(geometry, seeds.data(), n, nb, hint, states, visitors,
                                       threads);
  else
    traverse_restricted_polygons<false>(geometry, seeds.data(), n, nb, hint, states, visitors,
                                        threads);
}

}  // namespace voroseal::rvd_detail
