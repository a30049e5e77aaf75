#include "modules/remesh/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "framework/core/sorted_key_map.h"
#include "framework/core/union_find.h"
#include "framework/geometry/triangle_quality.h"

namespace voroseal {

const char* to_string(FeatureMerge::Reason reason) {
  switch (reason) {
    case FeatureMerge::CornersInOneCell: return "corners linked by a contact inside one cell";
    case FeatureMerge::ManyContactPoints: return "cell component touching more than two contact pieces";
    case FeatureMerge::CloseFeatures: return "features closer than the minimum feature size";
    case FeatureMerge::Repair: return "features closer than the resolution merged to resolve a crossing";
  }
  return "?";
}

namespace {

std::uint64_t key2(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

int rank(const VertexFeature& f) { return static_cast<int>(f.kind); }

// An edge of the boundary of a cell component, directed with the component on its left.
struct BoundaryEdge {
  int from = -1, to = -1;  // restricted Voronoi vertex ids
  int component = -1;
  int neighbour = -1;      // seed across a bisector edge, -1 on a contact
  int contact = -1;        // contact under a contact edge, -1 on a bisector
  double length = 0.0;
  int rep_start = -1;      // output point of the component on the first half of the edge
  int rep_end = -1;        // ... and on the second half (differs on a split edge)
  int corner = -1;         // its polygon vertex index in the diagram (the edge starts there)
};

// A connected component of one seed's restriction to the contacts.
struct ContactComponent {
  int seed = -1;
  double length = 0.0;
  Vec3 weighted = Vec3::Zero();  // sum of segment midpoints times lengths
  int contact = -1;              // contact of the longest segment
  double longest = -1.0;
  std::vector<int> corners;
  int sharpest_vertex = -1;      // model vertex of the sharpest bend of the contact in it
  double sharpest = 0.0;         // its turning angle (degrees)
  int point = -1;
};

struct CellComponent {
  int seed = -1;
  int part = -1;
  double area = 0.0;
  Vec3 weighted = Vec3::Zero();  // sum of polygon centroids times areas
  std::vector<int> boundary;     // indices into edges_
  std::vector<int> contact_components;
  int point = -1;                // its own point when it touches no contact
};

struct Point {
  Vec3 x;
  VertexFeature feature;
  int seed;
};

class MeshBuilder {
 public:
  MeshBuilder(const StructuralModel& input, const ModelGeometry& geometry, const RestrictedVoronoiDiagram& rvd,
              const SurfaceProjector& projector, const MeshBuildOptions& options)
      : input_(input), geometry_(geometry), rvd_(rvd), projector_(projector), options_(options) {}

  MeshBuildResult run() {
    measure_sharpness();
    number_vertices();
    collect_cell_components();
    collect_contact_components();
    place_points();
    merge_points();
    assign_representatives();
    emit_polygons();
    assemble();
    return std::move(result_);
  }

 private:
  // ---- turning angle of every contact at every vertex, at the scale of the remesh ----
  void measure_sharpness() {
    if (options_.sharp_scale <= 0.0) return;
    for (const Contact& c : input_.contacts) {
      const std::vector<int>& line = c.vertices;
      const int n = static_cast<int>(line.size());
      if (n < 3) continue;
      const bool closed = c.is_closed();
      std::vector<double> arc(n, 0.0);
      for (int i = 1; i < n; ++i) arc[i] = arc[i - 1] + (input_.vertices[line[i]] - input_.vertices[line[i - 1]]).norm();
      const double total = arc[n - 1];
      // Point at arc length t along the polyline (wrapping for closed contacts).
      auto at = [&](double t) -> Vec3 {
        if (closed) t = std::fmod(std::fmod(t, total) + total, total);
        if (t <= 0.0) return input_.vertices[line[0]];
        if (t >= total) return input_.vertices[line[n - 1]];
        const int k = static_cast<int>(std::upper_bound(arc.begin(), arc.end(), t) - arc.begin()) - 1;
        const double len = arc[k + 1] - arc[k];
        const double w = len > 0 ? (t - arc[k]) / len : 0.0;
        return (1 - w) * input_.vertices[line[k]] + w * input_.vertices[line[k + 1]];
      };
      const double s = options_.sharp_scale;
      for (int i = closed ? 0 : 1; i < n - 1; ++i) {
        if (!closed && (arc[i] < 0.25 * s || total - arc[i] < 0.25 * s)) continue;  // near a corner
        const Vec3& x = input_.vertices[line[i]];
        const Vec3 before = x - at(arc[i] - s), after = at(arc[i] + s) - x;
        if (before.norm() == 0 || after.norm() == 0) continue;
        const double angle =
            std::atan2(before.cross(after).norm(), before.dot(after)) * 180.0 / M_PI;
        auto& slot = sharpness_[line[i]];
        slot = std::max(slot, angle);
      }
    }
  }

  // ---- restricted Voronoi vertices: one id per tag ----
  void number_vertices() {
    gid_.resize(rvd_.vertex_tag.size());
    ids_.reserve(rvd_.vertex_tag.size() / 2);
    for (size_t m = 0; m < rvd_.vertex_tag.size(); ++m) gid_[m] = id_of(rvd_.vertex_tag[m]);
  }
  int id_of(const RvdVertexTag& tag) {
    auto [it, inserted] = ids_.emplace(tag, static_cast<int>(ids_.size()));
    return it->second;
  }

  // ---- connected components of the restricted cells, and their boundaries ----
  void collect_cell_components() {
    polygon_of_.assign(rvd_.vertex.size(), -1);
    boundary_at_.assign(rvd_.vertex.size(), -1);
    int count = 0;
    const std::vector<int> component = restricted_cell_components(rvd_, &count);
    components_.resize(count);
    result_.cell_components = count;
    // At most one key per polygon edge of each kind: reserved, so the maps (and the boundary
    // edges) never reallocate.
    size_t glued = 0, bisector = 0;
    for (const RvdEdgeTag& tag : rvd_.edge_tag) {
      glued += tag.on_input_edge() && !tag.on_line();
      bisector += tag.on_bisector();
    }
    glued_at_.reserve(glued);
    edge_at_.reserve(bisector);
    edges_.reserve(rvd_.edge_tag.size() - glued);  // every other polygon edge at the most
    for (size_t p = 0; p < rvd_.polygons.size(); ++p) {
      const RvdPolygon& poly = rvd_.polygons[p];
      CellComponent& cc = components_[component[p]];
      cc.seed = poly.seed;
      cc.part = poly.part;
      if (poly.size < 3) continue;
      const double area = rvd_.polygon_area(static_cast<int>(p));
      Vec3 centroid = Vec3::Zero();
      for (int k = 0; k < poly.size; ++k) centroid += rvd_.vertex[poly.first + k];
      centroid /= poly.size;
      cc.area += area;
      cc.weighted += area * centroid;
      for (int k = 0; k < poly.size; ++k) {
        const int m = poly.first + k;
        polygon_of_[m] = static_cast<int>(p);
        const RvdEdgeTag& tag = rvd_.edge_tag[m];
        const int next = poly.first + (k + 1 == poly.size ? 0 : k + 1);
        if (tag.on_input_edge() && !tag.on_line()) {
          // Glued inside the component to the same segment, reversed, in the next triangle.
          if (gid_[m] != gid_[next]) glued_at_.add(key2(gid_[m], gid_[next]), m);
          continue;
        }
        BoundaryEdge e;
        e.from = gid_[m];
        e.to = gid_[next];
        if (e.from == e.to) continue;  // a zero-length edge of a degenerate polygon
        e.corner = m;
        boundary_at_[m] = static_cast<int>(edges_.size());
        e.component = component[p];
        e.neighbour = tag.neighbour;
        e.contact = tag.contact;
        e.length = (rvd_.vertex[next] - rvd_.vertex[poly.first + k]).norm();
        cc.boundary.push_back(static_cast<int>(edges_.size()));
        if (tag.on_bisector()) edge_at_.add(key2(e.from, e.to), static_cast<int>(edges_.size()));
        edges_.push_back(e);
      }
    }
    glued_at_.seal();
    edge_at_.seal();
  }

  // ---- connected components of each cell's restriction to the contacts ----
  void collect_contact_components() {
    const std::vector<int>& vertex_corner = geometry_.vertex_corner();
    for (int s = 0; s < rvd_.num_seeds(); ++s) {
      const int first = rvd_.seed_segments[s], last = rvd_.seed_segments[s + 1];
      if (first == last) continue;
      UnionFind uf(last - first);
      std::unordered_map<int, int> segment_at;  // end vertex id -> first segment (local index)
      for (int g = first; g < last; ++g)
        for (const RvdVertexTag& tag : rvd_.segments[g].end_tag) {
          auto [it, inserted] = segment_at.emplace(id_of(tag), g - first);
          if (!inserted) uf.unite(it->second, g - first);
        }
      std::vector<int> label;
      const int n = uf.labels(label);
      const int base = static_cast<int>(contact_components_.size());
      contact_components_.resize(base + n);
      for (int g = first; g < last; ++g) {
        const RvdContactSegment& seg = rvd_.segments[g];
        ContactComponent& bc = contact_components_[base + label[g - first]];
        bc.seed = s;
        const double length = (seg.end[1] - seg.end[0]).norm();
        bc.length += length;
        bc.weighted += length * 0.5 * (seg.end[0] + seg.end[1]);
        if (length > bc.longest) {
          bc.longest = length;
          bc.contact = seg.contact;
        }
        for (const RvdVertexTag& tag : seg.end_tag) {
          if (tag.kind == RvdVertexTag::InputVertex && vertex_corner[tag.id[0]] >= 0)
            bc.corners.push_back(vertex_corner[tag.id[0]]);
          if (tag.kind == RvdVertexTag::InputVertex) {
            auto it = sharpness_.find(tag.id[0]);
            if (it != sharpness_.end() && it->second > bc.sharpest) {
              bc.sharpest = it->second;
              bc.sharpest_vertex = tag.id[0];
            }
          }
          contact_component_at_.emplace(key2(s, id_of(tag)), base + label[g - first]);
        }
      }
      for (int k = base; k < base + n; ++k) {
        auto& corners = contact_components_[k].corners;
        std::sort(corners.begin(), corners.end());
        corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
      }
    }
    result_.contact_components = static_cast<int>(contact_components_.size());
    // Which contact components each cell component touches.
    for (CellComponent& cc : components_) {
      for (int e : cc.boundary) {
        if (edges_[e].contact < 0) continue;
        auto it = contact_component_at_.find(key2(cc.seed, edges_[e].from));
        if (it != contact_component_at_.end()) cc.contact_components.push_back(it->second);
      }
      std::sort(cc.contact_components.begin(), cc.contact_components.end());
      cc.contact_components.erase(std::unique(cc.contact_components.begin(), cc.contact_components.end()),
                                  cc.contact_components.end());
    }
  }

  // ---- output points (Algorithm 3, step 1 and the corner merging of step 2) ----
  int add_point(const Vec3& x, VertexFeature f, int seed) {
    points_.push_back({x, f, seed});
    merged_.add();
    return static_cast<int>(points_.size()) - 1;
  }
  void place_points() {
    for (ContactComponent& bc : contact_components_) {
      const Vec3 centroid = bc.length > 0 ? Vec3(bc.weighted / bc.length) : Vec3(rvd_.seeds[bc.seed]);
      if (bc.corners.empty()) {
        if (bc.sharpest >= options_.sharp_angle_deg) {
          // The contact bends sharply inside this cell: keep the bend.
          bc.point = add_point(input_.vertices[bc.sharpest_vertex], {VertexFeature::Contact, bc.contact, true}, bc.seed);
          ++result_.sharp_points;
        } else {
          bc.point = add_point(projector_.on_contact(bc.contact, centroid), {VertexFeature::Contact, bc.contact}, bc.seed);
        }
        continue;
      }
      // One point per corner, merged when the cell holds several linked by contacts (Fig. 11b):
      // the corner nearest to the middle of the contact component stays.
      int keep = bc.corners.front();
      double best = std::numeric_limits<double>::infinity();
      for (int k : bc.corners) {
        const double d = (input_.vertices[input_.corners[k].vertex] - centroid).squaredNorm();
        if (d < best) {
          best = d;
          keep = k;
        }
      }
      bc.point = add_point(input_.vertices[input_.corners[keep].vertex], {VertexFeature::Corner, keep}, bc.seed);
      if (bc.corners.size() > 1) {
        FeatureMerge merge{FeatureMerge::CornersInOneCell, bc.seed, points_[bc.point].x, {}};
        for (int k : bc.corners) merge.features.push_back({VertexFeature::Corner, k});
        result_.merges.push_back(std::move(merge));
      }
    }
    for (CellComponent& cc : components_) {
      if (!cc.contact_components.empty() || cc.area <= 0.0) continue;
      const Vec3 centroid = cc.weighted / cc.area;
      cc.point = add_point(projector_.on_part(cc.part, centroid), {VertexFeature::Surface, cc.part}, cc.seed);
    }
  }

  int find(int p) { return merged_.find(p); }
  // Merges b into a or a into b: the more constrained feature (corner > contact > surface) wins,
  // so a merged vertex stays on the feature that matters most.
  void merge(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (rank(points_[b].feature) > rank(points_[a].feature)) std::swap(a, b);
    merged_.join_into(a, b);
  }

  // ---- Algorithm 3, steps 3 and 4 ----
  void merge_points() {
    for (CellComponent& cc : components_) {
      if (!options_.merge_many_contact_points) break;
      std::vector<int> roots;
      for (int k : cc.contact_components) roots.push_back(find(contact_components_[k].point));
      std::sort(roots.begin(), roots.end());
      roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
      if (roots.size() <= 2) continue;
      FeatureMerge m{FeatureMerge::ManyContactPoints, cc.seed, Vec3::Zero(), {}};
      for (int r : roots) {
        m.features.push_back(points_[r].feature);
        merge(roots.front(), r);
      }
      m.location = points_[find(roots.front())].x;
      result_.merges.push_back(std::move(m));
    }
  }

  // ---- which output point each component uses along each piece of its boundary ----

  // Polygon vertex index after m in its polygon.
  int next_corner(int m) const {
    const RvdPolygon& poly = rvd_.polygons[polygon_of_[m]];
    return m + 1 == poly.first + poly.size ? poly.first : m + 1;
  }
  // The boundary edge that follows boundary edge e around its component (the component on the
  // left): turn around the end vertex through the polygons of the component, across the glued
  // input edges, to the next boundary edge. Walking by vertex ids alone would be ambiguous where
  // the boundary passes twice through one vertex (around the end of a contact inside a part).
  int next_boundary(int e) const {
    int k = next_corner(edges_[e].corner);
    for (int guard = 0; guard < 4096; ++guard) {
      if (boundary_at_[k] >= 0) return boundary_at_[k];
      const int after = next_corner(k);
      if (gid_[k] == gid_[after]) {  // a zero-length edge: go on in the same polygon
        k = after;
        continue;
      }
      const int* twin = glued_at_.find(key2(gid_[after], gid_[k]));
      if (twin == nullptr) return -1;
      k = next_corner(*twin);
    }
    return -1;
  }

  void assign_representatives() {
    std::vector<char> taken(edges_.size(), 0);
    for (CellComponent& cc : components_) {
      for (int start : cc.boundary) {
        if (taken[start]) continue;
        // Walk one boundary cycle.
        std::vector<int> cycle;
        int e = start;
        while (e >= 0 && !taken[e]) {
          taken[e] = 1;
          cycle.push_back(e);
          e = next_boundary(e);
        }
        if (e != start) ++result_.open_boundaries;
        assign_cycle(cc, cycle);
      }
    }
    for (const BoundaryEdge& e : edges_) {
      if (e.neighbour < 0) continue;
      const int seed = components_[e.component].seed;
      junction_rep_.emplace(key2(seed, e.from), e.rep_start);
      junction_rep_.emplace(key2(seed, e.to), e.rep_end);
    }
  }

  int default_point(const CellComponent& cc) {
    if (cc.point >= 0) return cc.point;
    if (!cc.contact_components.empty()) return contact_components_[cc.contact_components.front()].point;
    return -1;
  }

  void assign_cycle(const CellComponent& cc, std::vector<int> cycle) {
    const int n = static_cast<int>(cycle.size());
    int first_arc = -1;
    for (int i = 0; i < n && first_arc < 0; ++i)
      if (edges_[cycle[i]].contact >= 0 && edges_[cycle[(i + n - 1) % n]].contact < 0) first_arc = i;
    if (first_arc < 0) {
      // No contact on this cycle (or only contact): one point for all of it.
      const int p = default_point(cc);
      for (int e : cycle) edges_[e].rep_start = edges_[e].rep_end = p;
      return;
    }
    std::rotate(cycle.begin(), cycle.begin() + first_arc, cycle.end());
    auto point_of_arc = [&](int e) {
      auto it = contact_component_at_.find(key2(cc.seed, edges_[e].from));
      return it != contact_component_at_.end() ? contact_components_[it->second].point : default_point(cc);
    };
    // Three or more contact points around the component: the halves split off each chain meet
    // inside it, where the polygon of the points (in boundary order) closes the mesh.
    std::vector<int> around;
    for (int k = 0; k < n; ++k)
      if (edges_[cycle[k]].contact >= 0 && edges_[cycle[(k + n - 1) % n]].contact < 0) {
        const int p = point_of_arc(cycle[k]);
        if (around.empty() || find(around.back()) != find(p)) around.push_back(p);
      }
    while (around.size() > 1 && find(around.front()) == find(around.back())) around.pop_back();
    if (around.size() >= 3) center_polygons_.push_back({cc.part, around});
    int i = 0;
    while (i < n) {
      const int x = point_of_arc(cycle[i]);
      while (i < n && edges_[cycle[i]].contact >= 0) ++i;
      const int chain_begin = i;
      while (i < n && edges_[cycle[i]].contact < 0) ++i;
      const int chain_end = i;
      const int y = i < n ? point_of_arc(cycle[i]) : point_of_arc(cycle[0]);
      if (find(x) == find(y)) {
        for (int k = chain_begin; k < chain_end; ++k) edges_[cycle[k]].rep_start = edges_[cycle[k]].rep_end = x;
        continue;
      }
      // Split the chain at its middle: the first half belongs to x, the second to y.
      double total = 0.0;
      for (int k = chain_begin; k < chain_end; ++k) total += edges_[cycle[k]].length;
      double run = 0.0;
      bool switched = false;
      for (int k = chain_begin; k < chain_end; ++k) {
        BoundaryEdge& e = edges_[cycle[k]];
        if (switched) {
          e.rep_start = e.rep_end = y;
          continue;
        }
        run += e.length;
        if (run >= 0.5 * total || k + 1 == chain_end) {
          e.rep_start = x;
          e.rep_end = y;
          switched = true;
        } else {
          e.rep_start = e.rep_end = x;
        }
      }
    }
  }

  // ---- output polygons ----
  void add_polygon(std::vector<int> ring, int part) {
    for (int& v : ring) v = v >= 0 ? find(v) : -1;
    // Drop repeated consecutive points (merged features), cyclically.
    std::vector<int> clean;
    for (int v : ring)
      if (clean.empty() || clean.back() != v) clean.push_back(v);
    while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
    if (std::find(clean.begin(), clean.end(), -1) != clean.end()) {
      ++result_.inconsistencies;
      return;
    }
    if (clean.size() < 3) {
      ++result_.degenerate_dropped;
      return;
    }
    std::vector<int> sorted = clean;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      ++result_.degenerate_dropped;
      return;
    }
    if (clean.size() == 3) {
      out_triangles_.push_back({clean[0], clean[1], clean[2]});
      out_parts_.push_back(part);
      return;
    }
    if (clean.size() == 4) {
      // A quad: the diagonal that gives the larger smallest angle.
      auto angle = [&](int a, int b, int c) {
        return measure_triangle(points_[a].x, points_[b].x, points_[c].x).min_angle_deg;
      };
      const double d02 = std::min(angle(clean[0], clean[1], clean[2]), angle(clean[0], clean[2], clean[3]));
      const double d13 = std::min(angle(clean[1], clean[2], clean[3]), angle(clean[1], clean[3], clean[0]));
      if (d02 >= d13) {
        out_triangles_.push_back({clean[0], clean[1], clean[2]});
        out_triangles_.push_back({clean[0], clean[2], clean[3]});
      } else {
        out_triangles_.push_back({clean[1], clean[2], clean[3]});
        out_triangles_.push_back({clean[1], clean[3], clean[0]});
      }
      out_parts_.insert(out_parts_.end(), 2, part);
      return;
    }
    for (size_t k = 1; k + 1 < clean.size(); ++k) {
      out_triangles_.push_back({clean[0], clean[k], clean[k + 1]});
      out_parts_.push_back(part);
    }
  }

  int rep_at(int seed, int vertex) const {
    auto it = junction_rep_.find(key2(seed, vertex));
    return it == junction_rep_.end() ? -1 : it->second;
  }

  void emit_polygons() {
    // Restricted Voronoi vertices where three cells meet: one triangle each, listed once from
    // the cell of lowest seed index. Around the vertex, counter-clockwise in the orientation of
    // the triangle: this cell, the cell across its incoming edge, the one across its outgoing edge.
    for (const RvdPolygon& poly : rvd_.polygons) {
      const int a = poly.seed;
      for (int k = 0; k < poly.size; ++k) {
        const RvdEdgeTag& in = rvd_.edge_tag[poly.first + (k == 0 ? poly.size - 1 : k - 1)];
        const RvdEdgeTag& out = rvd_.edge_tag[poly.first + k];
        if (!in.on_bisector() || !out.on_bisector() || in.neighbour == out.neighbour) continue;
        const int b = in.neighbour, c = out.neighbour;
        if (a > b || a > c) continue;
        const int v = gid_[poly.first + k];
        const size_t before = out_triangles_.size();
        add_polygon({rep_at(a, v), rep_at(b, v), rep_at(c, v)}, poly.part);
        result_.junction_triangles += static_cast<int>(out_triangles_.size() - before);
      }
    }
    for (const auto& [part, ring] : center_polygons_) add_polygon(ring, part);
    // Split edges of components with two contact points.
    for (const BoundaryEdge& e : edges_) {
      if (e.neighbour < 0 || find(e.rep_start) == find(e.rep_end)) continue;
      const int* at = edge_at_.find(key2(e.to, e.from));
      if (at == nullptr) {
        ++result_.inconsistencies;
        continue;
      }
      const BoundaryEdge& twin = edges_[*at];
      const int seed = components_[e.component].seed;
      const bool twin_split = find(twin.rep_start) != find(twin.rep_end);
      if (twin_split && seed > e.neighbour) continue;  // listed from the twin's side
      const size_t before = out_triangles_.size();
      add_polygon({e.rep_end, e.rep_start, twin.rep_end, twin.rep_start}, components_[e.component].part);
      result_.split_polygons += out_triangles_.size() > before ? 1 : 0;
    }
  }

  void assemble() {
    RemeshedSurface& s = result_.surface;
    std::vector<int> index(points_.size(), -1);
    std::unordered_map<std::uint64_t, int> seen;  // (sorted triangle, part) -> kept
    for (size_t t = 0; t < out_triangles_.size(); ++t) {
      Triangle f = out_triangles_[t];
      std::array<int, 3> key = f;
      std::sort(key.begin(), key.end());
      const std::uint64_t h = (static_cast<std::uint64_t>(key[0]) * 0x9E3779B97F4A7C15ULL) ^
                              (static_cast<std::uint64_t>(key[1]) * 0xC2B2AE3D27D4EB4FULL) ^
                              (static_cast<std::uint64_t>(key[2]) * 0x165667B19E3779F9ULL) ^
                              static_cast<std::uint64_t>(out_parts_[t]);
      auto [it, inserted] = seen.emplace(h, static_cast<int>(t));
      if (!inserted) {
        std::array<int, 3> other = out_triangles_[it->second];
        std::sort(other.begin(), other.end());
        if (other == key && out_parts_[it->second] == out_parts_[t]) {
          ++result_.degenerate_dropped;
          continue;
        }
      }
      for (int& v : f) {
        if (index[v] < 0) {
          index[v] = static_cast<int>(s.vertices.size());
          s.vertices.push_back(points_[v].x);
          s.features.push_back(points_[v].feature);
        }
        v = index[v];
      }
      s.triangles.push_back(f);
      s.triangle_part.push_back(out_parts_[t]);
    }
  }

  const StructuralModel& input_;
  const ModelGeometry& geometry_;
  const RestrictedVoronoiDiagram& rvd_;
  const SurfaceProjector& projector_;
  MeshBuildOptions options_;
  MeshBuildResult result_;

  std::unordered_map<int, double> sharpness_;   // model vertex -> turning angle (degrees)
  std::unordered_map<RvdVertexTag, int, RvdVertexTagHash> ids_;
  std::vector<int> gid_;                       // per diagram polygon vertex
  std::vector<CellComponent> components_;
  std::vector<BoundaryEdge> edges_;
  SortedKeyMap edge_at_;   // (from, to) -> bisector edge
  SortedKeyMap glued_at_;  // (from, to) -> glued polygon edge
  std::vector<int> polygon_of_;                                   // polygon of each polygon vertex
  std::vector<int> boundary_at_;                                  // boundary edge starting there
  std::vector<ContactComponent> contact_components_;
  std::unordered_map<std::uint64_t, int> contact_component_at_;  // (seed, vertex) -> BC
  std::unordered_map<std::uint64_t, int> junction_rep_;          // (seed, vertex) -> point
  std::vector<Point> points_;
  UnionFind merged_;  // points merged together; a root is the point that stays
  std::vector<std::pair<int, std::vector<int>>> center_polygons_;  // (part, points in order)
  std::vector<Triangle> out_triangles_;
  std::vector<int> out_parts_;
};

}  // namespace

MeshBuildResult build_remeshed_surface(const StructuralModel& input, const ModelGeometry& geometry,
                                       const RestrictedVoronoiDiagram& rvd, const SurfaceProjector& projector,
                                       const MeshBuildOptions& options) {
  return MeshBuilder(input, geometry, rvd, projector, options).run();
}

}  // namespace voroseal
