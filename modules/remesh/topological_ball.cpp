#include "modules/remesh/topological_ball.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "framework/core/union_find.h"
#include "modules/remesh/voronoi_clipping.h"

namespace voroseal {

const char* to_string(BallViolation::Kind kind) {
  switch (kind) {
    case BallViolation::NotADisk:
      return "cell component with a hole";
    case BallViolation::PartPieces:
      return "cell meeting a surface part in several pieces";
    case BallViolation::ContactPieces:
      return "cell meeting a contact in several segments";
    case BallViolation::Corners:
      return "cell holding several corners";
    case BallViolation::Unlinked:
      return "cell on surfaces that do not meet inside it";
  }
  return "?";
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct TaggedEdge {
  int component;
  RvdVertexTag a, b;
  bool operator<(const TaggedEdge& o) const {
    if (component != o.component) return component < o.component;
    if (a != o.a) return a < o.a;
    return b < o.b;
  }
  bool operator==(const TaggedEdge& o) const {
    return component == o.component && a == o.a && b == o.b;
  }
};

// One piece of a cell: a component inside a part, or a group of pieces linked by contacts.
struct Piece {
  int part = -1;
  double area = 0.0;
  int largest_polygon = -1;
  double largest_area = -1.0;
  int vertices = 0, edges = 0, faces = 0;
};

// Scratch buffers of one thread, reused from cell to cell.
struct CellScratch {
  std::vector<Piece> pieces;
  std::vector<std::pair<int, RvdVertexTag>> tags;
  std::vector<TaggedEdge> edges;
  std::vector<std::pair<RvdVertexTag, int>> segment_of_tag;
  std::vector<double> area_of_root;
  std::vector<char> reported;
};

Vec3 polygon_centroid(const RestrictedVoronoiDiagram& rvd, int p) {
  const RvdPolygon& poly = rvd.polygons[p];
  Vec3 c = Vec3::Zero();
  for (int k = 0; k < poly.size; ++k) c += rvd.vertex[poly.first + k];
  return c / std::max(1, poly.size);
}

class CellChecker {
 public:
  CellChecker(const ModelGeometry& geometry, const RestrictedVoronoiDiagram& rvd,
              const std::vector<int>& component, const std::vector<int>& corner_vertex)
      : geometry_(geometry), rvd_(rvd), component_(component), corner_vertex_(corner_vertex) {}

  void check(int seed, CellScratch& s, std::vector<BallViolation>& out) const {
    const int p0 = rvd_.seed_polygons[seed], p1 = rvd_.seed_polygons[seed + 1];
    if (p0 == p1) return;
    const int c0 = component_[p0];
    int count = 0;
    for (int p = p0; p < p1; ++p) count = std::max(count, component_[p] - c0 + 1);
    s.pieces.assign(count, Piece{});
    s.tags.clear();
    s.edges.clear();
    double cell_area = 0.0;
    for (int p = p0; p < p1; ++p) {
      const RvdPolygon& poly = rvd_.polygons[p];
      Piece& piece = s.pieces[component_[p] - c0];
      const double area = rvd_.polygon_area(p);
      cell_area += area;
      piece.part = poly.part;
      piece.area += area;
      ++piece.faces;
      if (area > piece.largest_area) {
        piece.largest_area = area;
        piece.largest_polygon = p;
      }
      for (int k = 0; k < poly.size; ++k) {
        const RvdVertexTag& a = rvd_.vertex_tag[poly.first + k];
        const RvdVertexTag& b = rvd_.vertex_tag[poly.first + (k + 1) % poly.size];
        s.tags.push_back({component_[p] - c0, a});
        if (a != b) s.edges.push_back({component_[p] - c0, std::min(a, b), std::max(a, b)});
      }
    }
    std::sort(s.tags.begin(), s.tags.end(), [](const auto& x, const auto& y) {
      return x.first != y.first ? x.first < y.first : x.second < y.second;
    });
    s.tags.erase(std::unique(s.tags.begin(), s.tags.end()), s.tags.end());
    for (const auto& t : s.tags) ++s.pieces[t.first].vertices;
    std::sort(s.edges.begin(), s.edges.end());
    s.edges.erase(std::unique(s.edges.begin(), s.edges.end()), s.edges.end());
    for (const TaggedEdge& e : s.edges) ++s.pieces[e.component].edges;

    BallViolation base;
    base.seed = seed;
    base.cell_size = std::sqrt(cell_area / (0.5 * std::sqrt(3.0)));

    // A component inside a part is a disk when it is connected (it is, by construction) and
    // has Euler characteristic V - E + F = 1.
    for (int k = 0; k < count; ++k) {
      const Piece& piece = s.pieces[k];
      if (piece.faces == 0 || piece.vertices - piece.edges + piece.faces == 1) continue;
      BallViolation v = base;
      v.kind = BallViolation::NotADisk;
      v.separation = kInf;
      v.where = farthest_polygon_centroid(seed, c0 + k);
      out.push_back(v);
    }

    // Contact segments: grouped per contact by their shared end points.
    const int s0 = rvd_.seed_segments[seed], s1 = rvd_.seed_segments[seed + 1];
    UnionFind segments(s1 - s0);
    for (int a = s0; a < s1; ++a)
      for (int b = a + 1; b < s1 && rvd_.segments[b].contact == rvd_.segments[a].contact; ++b)
        if (shares_end(rvd_.segments[a], rvd_.segments[b])) segments.unite(a - s0, b - s0);
    for (int a = s0; a < s1;) {
      int b = a;
      while (b < s1 && rvd_.segments[b].contact == rvd_.segments[a].contact) ++b;
      report_contact_pieces(base, a, b, s0, segments, out);
      a = b;
    }

    // Corners: every corner but the one nearest the seed asks for a cell of its own.
    const int k0 = rvd_.seed_corners[seed], k1 = rvd_.seed_corners[seed + 1];
    if (k1 - k0 >= 2) {
      const Vec3& x = rvd_.seeds[seed];
      int nearest = k0;
      for (int k = k0; k < k1; ++k)
        if ((corner(k) - x).squaredNorm() < (corner(nearest) - x).squaredNorm()) nearest = k;
      for (int k = k0; k < k1; ++k) {
        if (k == nearest) continue;
        double d = kInf;
        for (int m = k0; m < k1; ++m)
          if (m != k) d = std::min(d, (corner(k) - corner(m)).norm());
        BallViolation v = base;
        v.kind = BallViolation::Corners;
        v.where = corner(k);
        v.separation = d;
        out.push_back(v);
      }
    }

    if (count < 2) return;
    // Link the components through the contact segments their boundaries run along.
    s.segment_of_tag.clear();
    for (int a = s0; a < s1; ++a)
      for (const RvdVertexTag& t : rvd_.segments[a].end_tag)
        s.segment_of_tag.push_back({t, segments.find(a - s0)});
    std::sort(s.segment_of_tag.begin(), s.segment_of_tag.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    UnionFind linked(count + (s1 - s0));
    for (int p = p0; p < p1; ++p) {
      const RvdPolygon& poly = rvd_.polygons[p];
      for (int k = 0; k < poly.size; ++k) {
        if (!rvd_.edge_tag[poly.first + k].on_line()) continue;
        const RvdVertexTag& t = rvd_.vertex_tag[poly.first + k];
        auto it =
            std::lower_bound(s.segment_of_tag.begin(), s.segment_of_tag.end(), t,
                             [](const auto& x, const RvdVertexTag& y) { return x.first < y; });
        if (it != s.segment_of_tag.end() && it->first == t)
          linked.unite(component_[p] - c0, count + it->second);
      }
    }
    // The linked group of largest area is the cell; every other group is a piece that the dual
    // would glue to it.
    int main_component = 0;
    std::vector<double>& area_of_root = s.area_of_root;
    area_of_root.assign(count + (s1 - s0), 0.0);
    for (int k = 0; k < count; ++k) area_of_root[linked.find(k)] += s.pieces[k].area;
    for (int k = 0; k < count; ++k)
      if (area_of_root[linked.find(k)] > area_of_root[linked.find(main_component)])
        main_component = k;
    const int main_root = linked.find(main_component);
    std::vector<char>& reported = s.reported;
    reported.assign(count + (s1 - s0), 0);
    for (int k = 0; k < count; ++k) {
      const int root = linked.find(k);
      if (root == main_root || reported[root]) continue;
      reported[root] = 1;
      int largest = k;
      for (int m = 0; m < count; ++m)
        if (linked.find(m) == root && s.pieces[m].area > s.pieces[largest].area) largest = m;
      BallViolation v = base;
      v.kind = BallViolation::Unlinked;
      v.part = s.pieces[largest].part;
      v.other_part = s.pieces[main_component].part;
      v.where = polygon_centroid(rvd_, s.pieces[largest].largest_polygon);
      v.separation = distance_between(p0, p1, c0, linked, root, main_root);
      out.push_back(v);
    }
    // Several components on one part, inside one linked group (a cell that wraps round a fold
    // or crosses a narrow strip twice).
    for (int k = 0; k < count; ++k) {
      int largest = -1;
      for (int m = 0; m < count; ++m)
        if (s.pieces[m].part == s.pieces[k].part && linked.find(m) == linked.find(k) &&
            (largest < 0 || s.pieces[m].area > s.pieces[largest].area))
          largest = m;
      if (largest == k) continue;
      BallViolation v = base;
      v.kind = BallViolation::PartPieces;
      v.where = polygon_centroid(rvd_, s.pieces[k].largest_polygon);
      v.separation = distance_between_components(p0, p1, c0 + k, c0 + largest);
      out.push_back(v);
    }
  }

 private:
  Vec3 corner(int k) const { return geometry_.vertices()[corner_vertex_[rvd_.corners[k]]]; }

  static bool shares_end(const RvdContactSegment& a, const RvdContactSegment& b) {
    for (const RvdVertexTag& x : a.end_tag)
      for (const RvdVertexTag& y : b.end_tag)
        if (x == y) return true;
    return false;
  }

  void report_contact_pieces(const BallViolation& base, int a, int b, int s0, UnionFind& segments,
                             std::vector<BallViolation>& out) const {
    // The group holding the longest segment stays; each other group asks for a seed.
    int longest = a;
    for (int k = a; k < b; ++k)
      if (length(k) > length(longest)) longest = k;
    const int main_root = segments.find(longest - s0);
    for (int k = a; k < b; ++k) {
      const int root = segments.find(k - s0);
      if (root == main_root) continue;
      bool first = true;
      for (int m = a; m < k; ++m) first = first && segments.find(m - s0) != root;
      if (!first) continue;
      int pick = k;
      double d = kInf;
      for (int m = a; m < b; ++m) {
        if (segments.find(m - s0) != root) continue;
        if (length(m) > length(pick)) pick = m;
        for (int n = a; n < b; ++n)
          if (segments.find(n - s0) == main_root)
            for (const Vec3& x : rvd_.segments[m].end)
              for (const Vec3& y : rvd_.segments[n].end) d = std::min(d, (x - y).norm());
      }
      BallViolation v = base;
      v.kind = BallViolation::ContactPieces;
      v.where = 0.5 * (rvd_.segments[pick].end[0] + rvd_.segments[pick].end[1]);
      v.separation = d;
      out.push_back(v);
    }
  }

  double length(int segment) const {
    return (rvd_.segments[segment].end[1] - rvd_.segments[segment].end[0]).norm();
  }

  Vec3 farthest_polygon_centroid(int seed, int comp) const {
    Vec3 best = Vec3::Zero();
    double far = -1.0;
    for (int p = rvd_.seed_polygons[seed]; p < rvd_.seed_polygons[seed + 1]; ++p) {
      if (component_[p] != comp) continue;
      const Vec3 c = polygon_centroid(rvd_, p);
      const double d = (c - rvd_.seeds[seed]).squaredNorm();
      if (d > far) {
        far = d;
        best = c;
      }
    }
    return best;
  }

  // Smallest distance between the polygon vertices of two sets of polygons of one cell.
  template <class InA, class InB>
  double distance_between_sets(int p0, int p1, InA in_a, InB in_b) const {
    double d2 = kInf;
    for (int p = p0; p < p1; ++p) {
      if (!in_a(p)) continue;
      const RvdPolygon& a = rvd_.polygons[p];
      for (int q = p0; q < p1; ++q) {
        if (!in_b(q)) continue;
        const RvdPolygon& b = rvd_.polygons[q];
        for (int i = 0; i < a.size; ++i)
          for (int j = 0; j < b.size; ++j)
            d2 = std::min(d2, (rvd_.vertex[a.first + i] - rvd_.vertex[b.first + j]).squaredNorm());
      }
    }
    return std::sqrt(d2);
  }

  double distance_between(int p0, int p1, int c0, UnionFind& linked, int root_a, int root_b) const {
    return distance_between_sets(
        p0, p1, [&](int p) { return linked.find(component_[p] - c0) == root_a; },
        [&](int p) { return linked.find(component_[p] - c0) == root_b; });
  }

  double distance_between_components(int p0, int p1, int a, int b) const {
    return distance_between_sets(
        p0, p1, [&](int p) { return component_[p] == a; },
        [&](int p) { return component_[p] == b; });
  }

  const ModelGeometry& geometry_;
  const RestrictedVoronoiDiagram& rvd_;
  const std::vector<int>& component_;
  const std::vector<int>& corner_vertex_;
};

}  // namespace

std::vector<BallViolation> find_ball_violations(const ModelGeometry& geometry,
                                                const RestrictedVoronoiDiagram& rvd, int threads) {
  const std::vector<int> component = restricted_cell_components(rvd);
  int corners = 0;
  for (int c : geometry.vertex_corner()) corners = std::max(corners, c + 1);
  std::vector<int> corner_vertex(corners, -1);
  for (size_t v = 0; v < geometry.vertex_corner().size(); ++v)
    if (geometry.vertex_corner()[v] >= 0)
      corner_vertex[geometry.vertex_corner()[v]] = static_cast<int>(v);
  const CellChecker checker(geometry, rvd, component, corner_vertex);
  const int n = rvd.num_seeds();
  std::vector<BallViolation> all;
  const int nthreads = rvd_detail::active_threads(rvd_detail::resolve_threads(threads),
                                                  static_cast<long>(rvd.polygons.size()));
#pragma omp parallel num_threads(nthreads)
  {
    CellScratch scratch;
    std::vector<BallViolation> local;
#pragma omp for schedule(dynamic, 256)
    for (int i = 0; i < n; ++i) checker.check(i, scratch, local);
#pragma omp critical
    all.insert(all.end(), local.begin(), local.end());
  }
  std::stable_sort(all.begin(), all.end(), [](const BallViolation& a, const BallViolation& b) {
    if (a.seed != b.seed) return a.seed < b.seed;
    if (a.kind != b.kind) return a.kind < b.kind;
    return std::lexicographical_compare(a.where.data(), a.where.data() + 3, b.where.data(),
                                        b.where.data() + 3);
  });
  return all;
}

}  // namespace voroseal
