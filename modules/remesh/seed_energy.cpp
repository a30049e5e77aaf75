#include "modules/remesh/seed_energy.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "modules/remesh/boundary_energy.h"
#include "modules/remesh/cvt_energy.h"
#include "modules/remesh/seed_neighbours.h"
#include "modules/remesh/voronoi_clipping.h"

namespace voroseal {

namespace {

using rvd_detail::ClipVertex;

constexpr int kMinListSize = 10;  // a hexagonal cell needs 7 neighbours
constexpr int kListMargin = 6;    // room for the seeds to move before the lists are rebuilt
constexpr double kReuseMotion = 0.25;  // largest seed motion (in seed spacings) keeping the lists

// The sums of one chunk of triangles for one seed.
struct ChunkEntry {
  int seed;
  double mass;
  double energy;
  Vec3 moment;             // ∫ρ (y − p)
  Vec3 boundary_gradient;  // dF_B/dp contributions
};

// What the polygons of one chunk contributed. Chunks are combined in chunk order, so the
// result does not depend on which thread did which chunk.
struct ChunkResult {
  std::vector<ChunkEntry> entries;
  double boundary = 0.0;
};

// Per-thread scratch: dense per-seed sums of the chunk under way (zero between chunks) and
// the seeds they touch.
class ThreadScratch {
 public:
  ChunkEntry& at(int s) {
    if (static_cast<int>(slot_.size()) <= s) slot_.resize(s + 1, -1);
    int& k = slot_[s];
    if (k < 0) {
      k = static_cast<int>(out_->entries.size());
      out_->entries.push_back({s, 0.0, 0.0, Vec3::Zero(), Vec3::Zero()});
    }
    return out_->entries[k];
  }
  double boundary = 0.0;
  void begin(ChunkResult* out) {
    out_ = out;
    out_->entries.clear();
    boundary = 0.0;
  }
  void end() {
    for (const ChunkEntry& e : out_->entries) slot_[e.seed] = -1;
    out_->boundary = boundary;
  }

 private:
  std::vector<int> slot_;  // per seed: its entry in the chunk under way, -1 when none
  ChunkResult* out_ = nullptr;
};

template <bool kDensity>
struct EnergyVisitor {
  const Vec3* seeds = nullptr;
  ThreadScratch* acc = nullptr;
  std::vector<ChunkResult>* chunks = nullptr;
  bool with_boundary = true;

  void begin_chunk(int c) { acc->begin(&(*chunks)[c]); }
  void end_chunk(int) { acc->end(); }

  void polygon(int s, const TriangleRecord& rec, const ClipVertex* poly, int n) {
    const Vec3 ps = seeds[s];
    CellIntegrals cell;
    const Vec3 u0 = poly[0].x - ps;
    Vec3 u1 = poly[1].x - ps;
    for (int k = 1; k + 1 < n; ++k) {
      const Vec3 u2 = poly[k + 1].x - ps;
      const double area = 0.5 * rec.normal.dot((u1 - u0).cross(u2 - u0));
      if (kDensity)
        add_cvt_triangle_weighted(cell, area, u0, u1, u2, poly[0].d2, poly[k].d2, poly[k + 1].d2, poly[0].w,
                                  poly[k].w, poly[k + 1].w);
      else
        add_cvt_triangle(cell, area, u0, u1, u2, poly[0].d2, poly[k].d2, poly[k + 1].d2);
      u1 = u2;
    }
    ChunkEntry& sum = acc->at(s);
    sum.mass += cell.mass;
    sum.moment += cell.moment;
    sum.energy += cell.energy;
    if (with_boundary && rec.edge_owner != 0) boundary(s, ps, rec, poly, n);
  }

  // Contact segments of this polygon: its edges on line edges this triangle reports.
  void boundary(int s, const Vec3& ps, const TriangleRecord& rec, const ClipVertex* poly, int n) {
    for (int k = 0; k < n; ++k) {
      const int support = poly[k].support;
      if (support >= 0) continue;
      const int e = rvd_detail::support_edge(support);
      if (((rec.edge_owner >> e) & 1u) == 0) continue;
      const ClipVertex& a = poly[k];
      const ClipVertex& b = poly[k + 1 == n ? 0 : k + 1];
      SegmentEnergy se = boundary_segment_energy(a.x - ps, b.x - ps);
      if (kDensity) {
        // rho at the line edge's middle: F_B scales like F_CVT (boundary_energy.h).
        const double w = 0.5 * (rec.density[e] + rec.density[e == 2 ? 0 : e + 1]);
        se.energy *= w;
        se.d_seed *= w;
        se.d_c1 *= w;
        se.d_c2 *= w;
      }
      acc->boundary += se.energy;
      Vec3 gs = se.d_seed;
      const Vec3 d = rec.p[e == 2 ? 0 : e + 1] - rec.p[e];
      const int qa = poly[k == 0 ? n - 1 : k - 1].support;  // a = bisector(s, qa) ∩ edge when qa >= 0
      if (qa >= 0) add_bisector_end_gradient(se.d_c1, a.x, d, ps, seeds[qa], gs, acc->at(qa).boundary_gradient);
      const int qb = poly[k + 1 == n ? 0 : k + 1].support;  // b = bisector(s, qb) ∩ edge when qb >= 0
      if (qb >= 0) add_bisector_end_gradient(se.d_c2, b.x, d, ps, seeds[qb], gs, acc->at(qb).boundary_gradient);
      acc->at(s).boundary_gradient += gs;
    }
  }
};

}  // namespace

struct SeedEnergy::Impl {
  SeedNeighbours neighbours;
  int list_size = 16;
  // Neighbour list length per seed: what the previous evaluation needed plus a margin for the
  // seeds' motion (a list found too short is lengthened on the fly, so this is only speed).
  std::vector<int> list_sizes;
  bool lists_reusable = false;
  std::vector<int> hint;
  std::vector<rvd_detail::TraversalState> states;
  std::vector<ThreadScratch> scratch;
  std::vector<ChunkResult> chunks;
  // Per-seed totals.
  std::vector<double> mass, energy;
  std::vector<Vec3> moment, boundary_gradient;
  std::vector<EnergyVisitor<false>> plain;
  std::vector<EnergyVisitor<true>> weighted;
};

SeedEnergy::SeedEnergy(const ModelGeometry& geometry, int threads, int neighbours)
    : geometry_(geometry), threads_(rvd_detail::resolve_threads(threads)), impl_(std::make_unique<Impl>()) {
  impl_->list_size = std::max(1, neighbours);
  impl_->states.resize(threads_);
  impl_->scratch.resize(threads_);
  impl_->plain.resize(threads_);
  impl_->weighted.resize(threads_);
}

SeedEnergy::~SeedEnergy() = default;

void SeedEnergy::evaluate(const std::vector<Vec3>& seeds, EnergyEvaluation& out, bool boundary) {
  Impl& m = *impl_;
  const int n = static_cast<int>(seeds.size());
  const int threads = rvd_detail::active_threads(threads_, n + static_cast<long>(geometry_.triangles().size()));
  if (static_cast<int>(m.list_sizes.size()) != n) m.list_sizes.assign(n, m.list_size);
  // Keep the neighbour lists while the seeds move little (re-sorted, with bounds lowered by
  // the motion); rebuild them otherwise, with the lengths the last evaluation needed.
  const double spacing = std::sqrt(geometry_.area() / std::max(1, n));
  const bool reused =
      reuse_lists_ && m.lists_reusable && m.neighbours.update(seeds.data(), n, kReuseMotion * spacing, threads);
  if (!reused) m.neighbours.build(seeds.data(), n, m.list_sizes, threads);
  ++evaluations_;
  rebuilds_ += reused ? 0 : 1;
  m.chunks.resize(rvd_detail::traversal_chunks(static_cast<int>(geometry_.triangles().size())));
  for (int t = 0; t < threads_; ++t) {
    m.plain[t] = {seeds.data(), &m.scratch[t], &m.chunks, boundary};
    m.weighted[t] = {seeds.data(), &m.scratch[t], &m.chunks, boundary};
  }
  for (ChunkResult& c : m.chunks) {
    c.entries.clear();
    c.boundary = 0.0;
  }

  if (geometry_.has_density())
    rvd_detail::traverse_restricted_polygons<true>(geometry_, seeds.data(), n, m.neighbours, m.hint, m.states,
                                                   m.weighted, threads);
  else
    rvd_detail::traverse_restricted_polygons<false>(geometry_, seeds.data(), n, m.neighbours, m.hint, m.states,
                                                    m.plain, threads);

  // Combine the chunks in chunk order (deterministic whatever the threads did).
  m.mass.assign(n, 0.0);
  m.energy.assign(n, 0.0);
  m.moment.assign(n, Vec3::Zero());
  m.boundary_gradient.assign(n, Vec3::Zero());
  out.boundary = 0.0;
  for (const ChunkResult& c : m.chunks) {
    out.boundary += c.boundary;
    for (const ChunkEntry& e : c.entries) {
      m.mass[e.seed] += e.mass;
      m.energy[e.seed] += e.energy;
      m.moment[e.seed] += e.moment;
      m.boundary_gradient[e.seed] += e.boundary_gradient;
    }
  }
  out.cvt_gradient.resize(n);
  out.boundary_gradient.resize(n);
  out.mass.resize(n);
  out.centroid.resize(n);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (int s = 0; s < n; ++s) {
    const double mass = m.mass[s];
    out.mass[s] = mass;
    out.centroid[s] = mass > 0.0 ? Vec3(seeds[s] + m.moment[s] / mass) : seeds[s];
    out.cvt_gradient[s] = cvt_gradient(CellIntegrals{mass, m.moment[s], m.energy[s]});
    out.boundary_gradient[s] = boundary ? m.boundary_gradient[s] : Vec3::Zero();
    int needed = 0;
    for (int t = 0; t < threads; ++t) needed = std::max(needed, m.states[t].needed[s]);
    m.list_sizes[s] = std::max(kMinListSize, needed + kListMargin);
  }
  // Summed in seed order so the result does not depend on the thread schedule.
  out.cvt = 0.0;
  for (double e : m.energy) out.cvt += e;
  out.polygons = out.fallbacks = out.extended_queries = out.skipped_triangles = 0;
  out.lists_rebuilt = !reused;
  for (rvd_detail::TraversalState& st : m.states) {
    out.polygons += st.polygons;
    out.fallbacks += st.fallbacks;
    out.extended_queries += st.clip.extended_queries;
    out.skipped_triangles += st.skipped;
    st.polygons = st.fallbacks = st.skipped = 0;
    st.clip.extended_queries = 0;
  }
  // Lists that needed many extensions are rebuilt (longer) at the next evaluation.
  m.lists_reusable = out.extended_queries * 200 <= n;
}

}  // namespace voroseal
