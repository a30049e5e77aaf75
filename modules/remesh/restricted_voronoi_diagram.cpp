#include "modules/remesh/restricted_voronoi_diagram.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <type_traits>
#include <unordered_map>

#include "framework/core/union_find.h"
#include "modules/remesh/seed_neighbours.h"
#include "modules/remesh/voronoi_clipping.h"

namespace voroseal {

RvdVertexTag RvdVertexTag::edge_bisector(int a, int b, int i, int j) {
  if (a > b) std::swap(a, b);
  if (i > j) std::swap(i, j);
  return {EdgeBisector, {{a, b, i, j}}};
}

RvdVertexTag RvdVertexTag::triangle_bisectors(int t, int i, int j, int k) {
  if (i > j) std::swap(i, j);
  if (j > k) std::swap(j, k);
  if (i > j) std::swap(i, j);
  return {TriangleBisectors, {{t, i, j, k}}};
}

double RestrictedVoronoiDiagram::polygon_area(int p) const {
  const RvdPolygon& poly = polygons[p];
  if (poly.size < 3) return 0.0;
  Vec3 twice = Vec3::Zero();
  const Vec3& o = vertex[poly.first];
  for (int k = 1; k + 1 < poly.size; ++k)
    twice += (vertex[poly.first + k] - o).cross(vertex[poly.first + k + 1] - o);
  return 0.5 * twice.norm();
}

namespace {

using rvd_detail::ClipVertex;

// Tag of the point where supports `in` (edge arriving at the vertex) and `out` (edge leaving
// it) of a polygon of seed s in triangle rec meet.
RvdVertexTag make_vertex_tag(int s, const TriangleRecord& rec, int in, int out) {
  if (in < 0 && out < 0) {
    // Common vertex of triangle edges e1 = (v[e1], v[e1+1]) and e2.
    const int e1 = rvd_detail::support_edge(in), e2 = rvd_detail::support_edge(out);
    const int v = (e1 + 1) % 3 == e2 ? e2 : e1;
    return RvdVertexTag::input_vertex(rec.v[v]);
  }
  if (in < 0 || out < 0) {
    const int e = rvd_detail::support_edge(in < 0 ? in : out);
    const int q = in < 0 ? out : in;
    return RvdVertexTag::edge_bisector(rec.v[e], rec.v[(e + 1) % 3], s, q);
  }
  return RvdVertexTag::triangle_bisectors(rec.id, s, in, out);
}

RvdEdgeTag make_edge_tag(const TriangleRecord& rec, int support) {
  RvdEdgeTag t;
  if (support >= 0) {
    t.neighbour = support;
    return t;
  }
  const int e = rvd_detail::support_edge(support);
  t.a = std::min(rec.v[e], rec.v[(e + 1) % 3]);
  t.b = std::max(rec.v[e], rec.v[(e + 1) % 3]);
  t.contact = rec.edge_contact[e];
  return t;
}

struct CornerHit {
  int seed, corner;
};

// Copies every polygon into thread-local arrays.
struct CollectVisitor {
  const std::vector<int>* vertex_corner = nullptr;
  std::vector<RvdPolygon> polygons;
  std::vector<Vec3> vertex;
  std::vector<RvdVertexTag> vertex_tag;
  std::vector<RvdEdgeTag> edge_tag;
  std::vector<RvdContactSegment> segments;
  std::vector<CornerHit> corners;

  // The output is sorted afterwards: chunks need no bookkeeping.
  void begin_chunk(int) {}
  void end_chunk(int) {}

  void polygon(int s, const TriangleRecord& rec, const ClipVertex* poly, int n) {
    RvdPolygon p;
    p.seed = s;
    p.triangle = rec.id;
    p.part = rec.part;
    p.first = static_cast<int>(vertex.size());
    p.size = n;
    polygons.push_back(p);
    for (int k = 0; k < n; ++k) {
      const int in = poly[k == 0 ? n - 1 : k - 1].support;
      const int out = poly[k].support;
      vertex.push_back(poly[k].x);
      const RvdVertexTag tag = make_vertex_tag(s, rec, in, out);
      vertex_tag.push_back(tag);
      edge_tag.push_back(make_edge_tag(rec, out));
      if (tag.kind == RvdVertexTag::InputVertex) {
        const int c = (*vertex_corner)[tag.id[0]];
        if (c >= 0) corners.push_back({s, c});
      }
    }
    if (rec.edge_owner == 0) return;
    for (int k = 0; k < n; ++k) {
      const int support = poly[k].support;
      if (support >= 0) continue;
      const int e = rvd_detail::support_edge(support);
      if (((rec.edge_owner >> e) & 1u) == 0) continue;
      const int k1 = k + 1 == n ? 0 : k + 1;
      RvdContactSegment seg;
      seg.seed = s;
      seg.contact = rec.edge_contact[e];
      const int va = rec.v[e], vb = rec.v[(e + 1) % 3];
      seg.a = std::min(va, vb);
      seg.b = std::max(va, vb);
      seg.end = {poly[k].x, poly[k1].x};
      seg.end_tag = {vertex_tag[p.first + k], vertex_tag[p.first + k1]};
      // Polygon edge k runs from v[e] to v[e+1]; put end[0] next to the lower vertex id.
      if (va > vb) {
        std::swap(seg.end[0], seg.end[1]);
        std::swap(seg.end_tag[0], seg.end_tag[1]);
      }
      segments.push_back(seg);
    }
  }
};

}  // namespace

RestrictedVoronoiDiagram compute_restricted_voronoi_diagram(const ModelGeometry& geometry,
                                                            const std::vector<Vec3>& seeds,
                                                            const RvdOptions& options) {
  const int n = static_cast<int>(seeds.size());
  const int threads = rvd_detail::active_threads(rvd_detail::resolve_threads(options.threads),
                                                 n + static_cast<long>(geometry.triangles().size()));
  SeedNeighbours nb;
  nb.build(seeds.data(), n, std::max(1, options.neighbours), threads);
  std::vector<CollectVisitor> visitors(threads);
  for (CollectVisitor& v : visitors) v.vertex_corner = &geometry.vertex_corner();
  rvd_detail::traverse_once(geometry, seeds, nb, visitors);

  RestrictedVoronoiDiagram rvd;
  rvd.seeds = seeds;

  // Polygons sorted by (seed, triangle), their vertices gathered in that order (a seed's
  // polygons are then contiguous in memory, which the mesh builder's per-seed walks like).
  struct Ref {
    int seed, triangle, thread, index;
  };
  std::vector<Ref> refs;
  size_t nverts = 0;
  for (int t = 0; t < threads; ++t) {
    refs.reserve(refs.size() + visitors[t].polygons.size());
    for (size_t i = 0; i < visitors[t].polygons.size(); ++i) {
      const RvdPolygon& p = visitors[t].polygons[i];
      refs.push_back({p.seed, p.triangle, t, static_cast<int>(i)});
      nverts += p.size;
    }
  }
  std::sort(refs.begin(), refs.end(), [](const Ref& x, const Ref& y) {
    return x.seed != y.seed ? x.seed < y.seed : x.triangle < y.triangle;
  });
  rvd.polygons.reserve(refs.size());
  rvd.seed_polygons.assign(n + 1, 0);
  std::vector<int> from(refs.size());  // first vertex of each polygon in its thread's arrays
  int first = 0;
  for (size_t i = 0; i < refs.size(); ++i) {
    RvdPolygon p = visitors[refs[i].thread].polygons[refs[i].index];
    from[i] = p.first;
    p.first = first;
    first += p.size;
    rvd.polygons.push_back(p);
    ++rvd.seed_polygons[p.seed + 1];
  }
  for (int i = 0; i < n; ++i) rvd.seed_polygons[i + 1] += rvd.seed_polygons[i];
  // One vertex array at a time, each thread's copy freed once gathered: the diagram is never
  // held twice over.
  for (CollectVisitor& v : visitors) std::vector<RvdPolygon>().swap(v.polygons);
  auto gather = [&](auto& out, auto member) {
    out.reserve(nverts);
    for (size_t i = 0; i < refs.size(); ++i) {
      const auto& in = visitors[refs[i].thread].*member;
      out.insert(out.end(), in.begin() + from[i], in.begin() + from[i] + rvd.polygons[i].size);
    }
    for (CollectVisitor& v : visitors) std::decay_t<decltype(out)>().swap(v.*member);
  };
  gather(rvd.vertex, &CollectVisitor::vertex);
  gather(rvd.vertex_tag, &CollectVisitor::vertex_tag);
  gather(rvd.edge_tag, &CollectVisitor::edge_tag);

  // Contact segments.
  for (const CollectVisitor& v : visitors)
    rvd.segments.insert(rvd.segments.end(), v.segments.begin(), v.segments.end());
  std::sort(rvd.segments.begin(), rvd.segments.end(), [](const RvdContactSegment& x, const RvdContactSegment& y) {
    if (x.seed != y.seed) return x.seed < y.seed;
    if (x.contact != y.contact) return x.contact < y.contact;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  rvd.seed_segments.assign(n + 1, 0);
  for (const RvdContactSegment& s : rvd.segments) ++rvd.seed_segments[s.seed + 1];
  for (int i = 0; i < n; ++i) rvd.seed_segments[i + 1] += rvd.seed_segments[i];

  // Corners: a corner vertex appears in the polygons of all its triangles, all of one seed.
  std::vector<CornerHit> hits;
  for (const CollectVisitor& v : visitors) hits.insert(hits.end(), v.corners.begin(), v.corners.end());
  std::sort(hits.begin(), hits.end(), [](const CornerHit& x, const CornerHit& y) {
    return x.seed != y.seed ? x.seed < y.seed : x.corner < y.corner;
  });
  hits.erase(
      std::unique(hits.begin(), hits.end(),
                  [](const CornerHit& x, const CornerHit& y) { return x.seed == y.seed && x.corner == y.corner; }),
      hits.end());
  rvd.seed_corners.assign(n + 1, 0);
  for (const CornerHit& h : hits) {
    rvd.corners.push_back(h.corner);
    ++rvd.seed_corners[h.seed + 1];
  }
  for (int i = 0; i < n; ++i) rvd.seed_corners[i + 1] += rvd.seed_corners[i];
  return rvd;
}

std::vector<int> restricted_cell_components(const RestrictedVoronoiDiagram& rvd, int* count) {
  const int np = static_cast<int>(rvd.polygons.size());
  UnionFind uf(np);
  std::unordered_map<std::uint64_t, int> first_on_edge;
  for (int i = 0; i < rvd.num_seeds(); ++i) {
    first_on_edge.clear();
    for (int p = rvd.seed_polygons[i]; p < rvd.seed_polygons[i + 1]; ++p) {
      const RvdPolygon& poly = rvd.polygons[p];
      for (int k = 0; k < poly.size; ++k) {
        const RvdEdgeTag& e = rvd.edge_tag[poly.first + k];
        if (!e.on_input_edge() || e.on_line()) continue;
        const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(e.a)) << 32) |
                                  static_cast<std::uint32_t>(e.b);
        const auto [it, inserted] = first_on_edge.emplace(key, p);
        if (!inserted) uf.unite(it->second, p);
      }
    }
  }
  std::vector<int> component(np, -1);
  std::vector<int> id_of_root(np, -1);
  int next = 0;
  for (int p = 0; p < np; ++p) {
    const int root = uf.find(p);
    if (id_of_root[root] < 0) id_of_root[root] = next++;
    component[p] = id_of_root[root];
  }
  if (count != nullptr) *count = next;
  return component;
}

}  // namespace voroseal
