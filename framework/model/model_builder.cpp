// build_model(): from triangulated surfaces to a StructuralModel (design.md, "Data layer").
#include "framework/model/model_builder.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include "framework/core/error.h"
#include "framework/core/union_find.h"
#include "framework/model/build_steps.h"
#include "framework/model/welding.h"

namespace voroseal {

namespace {

Vec3 triangle_normal(const std::vector<Vec3>& v, const Triangle& t) {
  return (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
}

// An integer point near the box centre: local = file - origin is then exact in double.
Vec3 frame_origin(const BoundingBox& box) {
  const Vec3 c = box.center();
  return Vec3(std::round(c.x()), std::round(c.y()), std::round(c.z()));
}

class ModelBuilder {
 public:
  ModelBuilder(const SurfaceSoup& soup, const BuildOptions& options) : soup_(soup), options_(options) {}

  StructuralModel build() {
    validate_input();
    weld();
    clean_triangles();
    t_.edges = EdgeTable::build(t_.triangles);
    classify_line_edges();
    find_crack_vertices();
    find_parts();
    orient_parts();
    count_sewn_edges();
    find_crossed_line_edges();
    make_interfaces_and_parts();
    build_contacts(model_, t_, options_.corner_rule);
    if (soup_.has_explicit_parts && !soup_.regions.empty() && !options_.ignore_explicit_regions)
      explicit_regions();
    else
      infer_regions(model_, t_);
    return std::move(model_);
  }

 private:
  void validate_input() {
    const std::string& src = soup_.source;
    if (soup_.triangles.empty()) throw ModelError(src + ": no triangles");
    if (soup_.triangle_group.size() != soup_.triangles.size())
      throw ModelError(src + ": every triangle needs a group");
    const int np = static_cast<int>(soup_.points.size());
    const int ng = static_cast<int>(soup_.groups.size());
    for (size_t t = 0; t < soup_.triangles.size(); ++t) {
      for (int v : soup_.triangles[t])
        if (v < 0 || v >= np)
          throw ModelError(src + ": triangle " + std::to_string(t) + " has vertex index " + std::to_string(v) +
                           " out of range");
      if (soup_.triangle_group[t] < 0 || soup_.triangle_group[t] >= ng)
        throw ModelError(src + ": triangle " + std::to_string(t) + " has no valid group");
    }
    for (const Vec3& p : soup_.points)
      if (!p.allFinite()) throw ModelError(src + ": a vertex has a non-finite coordinate");
    model_.name = src;
    model_.build.source = src;
    model_.build.input_points = np;
    model_.build.input_triangles = static_cast<int>(soup_.triangles.size());
  }

  // Welds the points used by triangles, in the local frame.
  void weld() {
    std::vector<char> used(soup_.points.size(), 0);
    for (const Triangle& t : soup_.triangles)
      for (int v : t) used[v] = 1;
    BoundingBox box;
    for (size_t i = 0; i < soup_.points.size(); ++i)
      if (used[i]) box.extend(soup_.points[i]);
    model_.frame.origin = frame_origin(box);
    std::vector<int> used_ids;
    std::vector<Vec3> local;
    for (size_t i = 0; i < soup_.points.size(); ++i) {
      if (!used[i]) continue;
      used_ids.push_back(static_cast<int>(i));
      local.push_back(soup_.points[i] - model_.frame.origin);
    }
    const WeldResult w = weld_points(local, options_.weld_tolerance * box.diagonal());
    welded_.assign(soup_.points.size(), -1);
    for (size_t k = 0; k < used_ids.size(); ++k) welded_[used_ids[k]] = w.representative[k];
    model_.vertices.reserve(w.source.size());
    for (int s : w.source) model_.vertices.push_back(local[s]);
    model_.build.merged_points = static_cast<int>(used_ids.size() - w.source.size());
  }

  // Remaps triangles to welded vertices; drops degenerate and duplicated ones; notes points of
  // one group that welding merged (colocated vertices inside a surface).
  void clean_triangles() {
    const size_t n = soup_.triangles.size();
    auto welded = [&](size_t f) {
      const Triangle& in = soup_.triangles[f];
      return Triangle{welded_[in[0]], welded_[in[1]], welded_[in[2]]};
    };
    // A triangle on the same three vertices as an earlier one is a duplicate: the sorted
    // (vertices, triangle) keys put each set's first triangle first.
    std::vector<char> duplicate(n, 0);
    {
      std::vector<std::pair<std::array<int, 3>, int>> keys;
      keys.reserve(n);
      for (size_t f = 0; f < n; ++f) {
        std::array<int, 3> key = welded(f);
        std::sort(key.begin(), key.end());
        if (key[0] != key[1] && key[1] != key[2]) keys.emplace_back(key, static_cast<int>(f));
      }
      std::sort(keys.begin(), keys.end());
      for (size_t k = 1; k < keys.size(); ++k)
        if (keys[k].first == keys[k - 1].first) duplicate[keys[k].second] = 1;
    }
    std::unordered_map<uint64_t, int> first_point;  // (welded vertex, group) -> input point
    first_point.reserve(n / 2);
    std::vector<char> cracked(soup_.groups.size(), 0);
    for (size_t f = 0; f < n; ++f) {
      const Triangle& in = soup_.triangles[f];
      const Triangle t = welded(f);
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
        ++model_.build.degenerate_triangles_dropped;
        continue;
      }
      if (duplicate[f]) {
        ++model_.build.duplicate_triangles_dropped;
        continue;
      }
      const int g = soup_.triangle_group[f];
      for (int i = 0; i < 3; ++i) {
        const uint64_t k = (uint64_t(t[i]) << 32) | uint32_t(g);
        auto [it, inserted] = first_point.emplace(k, in[i]);
        if (!inserted && it->second != in[i]) {
          ++model_.build.colocated_points_in_group;
          it->second = in[i];  // count each further duplicate once
          cracked[g] = 1;
          colocated_keys_.insert(k);
        }
      }
      t_.triangles.push_back(t);
      input_triangle_.push_back(static_cast<int>(f));
      group_.push_back(g);
    }
    for (size_t g = 0; g < cracked.size(); ++g)
      if (cracked[g]) colocated_groups_.push_back(static_cast<int>(g));
    if (t_.triangles.empty()) throw ModelError(soup_.source + ": every triangle is degenerate");
  }

  void classify_line_edges() {
    const double cos_feature = std::cos(options_.feature_angle_deg * M_PI / 180.0);
    for (EdgeTable::Edge& e : t_.edges.edges) {
      if (e.count != 2) {
        e.line = true;
        continue;
      }
      const int f0 = t_.edges.incident[e.first], f1 = t_.edges.incident[e.first + 1];
      if (group_[f0] != group_[f1]) {
        e.line = true;
        continue;
      }
      if (options_.feature_angle_deg > 0.0) {
        Vec3 n0 = triangle_normal(model_.vertices, t_.triangles[f0]).normalized();
        Vec3 n1 = triangle_normal(model_.vertices, t_.triangles[f1]).normalized();
        // Consistently oriented neighbours traverse the edge in opposite directions.
        if (has_directed_edge(t_.triangles[f0], e.a, e.b) == has_directed_edge(t_.triangles[f1], e.a, e.b))
          n1 = -n1;
        e.line = n0.dot(n1) < cos_feature;
      }
    }
  }

  // A group may use several input points at one vertex only along an internal border: a line
  // edge with two triangles of that group (the two lips of a horizon on a fault without
  // throw). Anywhere else the copies are a crack that welding hid (RINGMesh's vertex rule).
  void find_crack_vertices() {
    // A group with an edge of 3+ of its own triangles holds several surfaces (a Medit soup with
    // all refs 0): there welding cannot tell a crack from a contact, so it is not searched.
    multi_surface_group_.assign(soup_.groups.size(), 0);
    std::vector<int> count(soup_.groups.size(), 0);
    for (const EdgeTable::Edge& e : t_.edges.edges) {
      if (e.count < 3) continue;
      for (int i = e.first; i < e.first + e.count; ++i)
        if (++count[group_[t_.edges.incident[i]]] == 3) multi_surface_group_[group_[t_.edges.incident[i]]] = 1;
      for (int i = e.first; i < e.first + e.count; ++i) count[group_[t_.edges.incident[i]]] = 0;
    }
    for (size_t g = 0; g < soup_.groups.size(); ++g)
      if (multi_surface_group_[g]) model_.build.multi_surface_groups.push_back(soup_.groups[g].name);
    if (colocated_keys_.empty()) return;
    auto key_of = [](int v, int g) { return (uint64_t(v) << 32) | uint32_t(g); };
    std::vector<std::pair<uint64_t, int>> copies;  // (vertex, group) -> input point
    for (size_t f = 0; f < t_.triangles.size(); ++f)
      for (int i = 0; i < 3; ++i) {
        const uint64_t k = key_of(t_.triangles[f][i], group_[f]);
        if (!multi_surface_group_[group_[f]] && colocated_keys_.count(k))
          copies.emplace_back(k, soup_.triangles[input_triangle_[f]][i]);
      }
    std::sort(copies.begin(), copies.end());
    copies.erase(std::unique(copies.begin(), copies.end()), copies.end());
    std::unordered_set<uint64_t> internal_border;
    std::vector<int> groups;
    for (const EdgeTable::Edge& e : t_.edges.edges) {
      if (!e.line || e.count < 2) continue;
      groups.clear();
      for (int i = e.first; i < e.first + e.count; ++i) groups.push_back(group_[t_.edges.incident[i]]);
      std::sort(groups.begin(), groups.end());
      for (size_t i = 1; i < groups.size(); ++i)
        if (groups[i] == groups[i - 1]) {
          internal_border.insert(key_of(e.a, groups[i]));
          internal_border.insert(key_of(e.b, groups[i]));
        }
    }
    std::vector<char> cracked(soup_.groups.size(), 0);
    for (size_t i = 0; i < copies.size();) {
      size_t j = i;
      while (j < copies.size() && copies[j].first == copies[i].first) ++j;
      const uint64_t k = copies[i].first;
      if (j - i > 2 || (j - i == 2 && !internal_border.count(k))) {
        ++model_.build.crack_vertices;
        cracked[k & 0xffffffffu] = 1;
        if (model_.build.crack_locations.size() < 20) model_.build.crack_locations.push_back(model_.vertices[k >> 32]);
      }
      i = j;
    }
    for (size_t g = 0; g < cracked.size(); ++g)
      if (cracked[g]) crack_groups_.push_back(static_cast<int>(g));
  }

  // Surface parts: explicit groups, or components of triangles through non-line edges.
  void find_parts() {
    const int nt = static_cast<int>(t_.triangles.size());
    t_.part.assign(nt, -1);
    if (soup_.has_explicit_parts) {
      // Every group is a part, in group order; groups left empty are dropped.
      group_part_.assign(soup_.groups.size(), -1);
      std::vector<char> nonempty(soup_.groups.size(), 0);
      for (int g : group_) nonempty[g] = 1;
      int np = 0;
      for (size_t g = 0; g < soup_.groups.size(); ++g)
        if (nonempty[g]) {
          group_part_[g] = np++;
          part_group_.push_back(static_cast<int>(g));
        }
      for (int f = 0; f < nt; ++f) t_.part[f] = group_part_[group_[f]];
      return;
    }
    UnionFind uf(nt);
    for (const EdgeTable::Edge& e : t_.edges.edges)
      if (!e.line) uf.unite(t_.edges.incident[e.first], t_.edges.incident[e.first + 1]);
    // Number parts by group, then by first triangle, for a stable and readable order.
    std::vector<int> root_part(nt, -1);
    std::vector<std::vector<int>> by_group(soup_.groups.size());
    for (int f = 0; f < nt; ++f) {
      const int r = uf.find(f);
      if (root_part[r] == -2) continue;
      if (root_part[r] == -1) {
        root_part[r] = -2;
        by_group[group_[f]].push_back(r);
      }
    }
    int np = 0;
    for (size_t g = 0; g < by_group.size(); ++g)
      for (int r : by_group[g]) {
        root_part[r] = np++;
        part_group_.push_back(static_cast<int>(g));
      }
    for (int f = 0; f < nt; ++f) t_.part[f] = root_part[uf.find(f)];
  }

  // Makes the triangles of every part agree in orientation (BFS through non-line edges from
  // the part's first triangle, which keeps the file's orientation for explicit parts).
  void orient_parts() {
    const int nt = static_cast<int>(t_.triangles.size());
    // Triangle adjacency through non-line edges.
    std::vector<std::array<int, 3>> neighbour(nt, {-1, -1, -1});
    for (const EdgeTable::Edge& e : t_.edges.edges) {
      if (e.line) continue;
      const int f0 = t_.edges.incident[e.first], f1 = t_.edges.incident[e.first + 1];
      for (int f : {f0, f1}) {
        const Triangle& t = t_.triangles[f];
        for (int i = 0; i < 3; ++i) {
          const int a = t[i], b = t[(i + 1) % 3];
          if ((a == e.a && b == e.b) || (a == e.b && b == e.a)) neighbour[f][i] = f == f0 ? f1 : f0;
        }
      }
    }
    std::vector<char> state(nt, 0);  // 0 unvisited, 1 visited
    order_.clear();
    order_.reserve(nt);
    std::vector<int> first_of_part(part_group_.size(), -1);
    for (int f = 0; f < nt; ++f)
      if (first_of_part[t_.part[f]] < 0) first_of_part[t_.part[f]] = f;
    for (int seed : first_of_part) {
      if (seed < 0) continue;
      std::queue<int> queue;
      queue.push(seed);
      state[seed] = 1;
      // Explicit parts may be disconnected: continue with the next unvisited triangle of it.
      int next_candidate = seed;
      const int part = t_.part[seed];
      for (;;) {
        while (!queue.empty()) {
          const int f = queue.front();
          queue.pop();
          order_.push_back(f);
          const Triangle& t = t_.triangles[f];
          for (int i = 0; i < 3; ++i) {
            const int g = neighbour[f][i];
            if (g < 0) continue;
            const int a = t[i], b = t[(i + 1) % 3];
            // Consistent neighbours traverse the shared edge as b -> a.
            const bool consistent = has_directed_edge(t_.triangles[g], b, a);
            if (state[g]) {
              if (!consistent) ++model_.build.inconsistent_orientation_edges;
              continue;
            }
            if (!consistent) {
              // Reversing (a, b, c) into (a, c, b) exchanges edges 0 and 2.
              std::swap(t_.triangles[g][1], t_.triangles[g][2]);
              std::swap(neighbour[g][0], neighbour[g][2]);
              ++model_.build.flipped_triangles;
            }
            state[g] = 1;
            queue.push(g);
          }
        }
        while (next_candidate < nt && (state[next_candidate] || t_.part[next_candidate] != part)) ++next_candidate;
        if (next_candidate >= nt) break;
        state[next_candidate] = 1;
        queue.push(next_candidate);
      }
    }
    // Each inconsistent edge was seen from both of its triangles.
    model_.build.inconsistent_orientation_edges /= 2;
    if (!soup_.has_explicit_parts && model_.build.inconsistent_orientation_edges > 0)
      throw ModelError(soup_.source + ": a surface part cannot be oriented consistently (non-orientable surface, " +
                       std::to_string(model_.build.inconsistent_orientation_edges) + " conflicting edges)");
  }

  // Explicit parts may continue across a line edge in the file: near a fault tip a horizon
  // TFACE is often not split where the fault meets it (its two triangles there share their
  // input points). RINGMesh's Model3d loader keeps that adjacency, so the patch is not a
  // surface of the line there and the vertices where it touches the line become corners:
  // CloudSpin_fixed.ml has 14 such edges, giving RINGMesh's 249 lines / 148 corners instead of
  // 239 / 138. Only for CornerRule::Incidence (the RINGMesh convention) and explicit parts;
  // inferred parts never cross a line edge with two triangles of a file-continuous surface
  // on purpose, so the rule would only add spurious corners there.
  void find_crossed_line_edges() {
    t_.crossed_line_edges.clear();
    if (!soup_.has_explicit_parts || options_.corner_rule != CornerRule::Incidence) return;
    auto input_point = [&](int f, int v) {
      for (int i = 0; i < 3; ++i)
        if (welded_[soup_.triangles[input_triangle_[f]][i]] == v) return soup_.triangles[input_triangle_[f]][i];
      return -1;
    };
    for (const EdgeTable::Edge& e : t_.edges.edges) {
      if (!e.line || e.count < 3) continue;
      for (int i = e.first; i < e.first + e.count; ++i) {
        const int part = t_.part[t_.edges.incident[i]];
        int same = 0, other = -1;
        for (int j = e.first; j < e.first + e.count; ++j)
          if (t_.part[t_.edges.incident[j]] == part) {
            ++same;
            if (j != i) other = t_.edges.incident[j];
          }
        // Each pair is seen from both triangles: record it from the first one only.
        if (same != 2 || other < t_.edges.incident[i]) continue;
        const int f0 = t_.edges.incident[i];
        if (input_point(f0, e.a) == input_point(other, e.a) && input_point(f0, e.b) == input_point(other, e.b))
          t_.crossed_line_edges.push_back({e.a, e.b, part});
      }
    }
    std::sort(t_.crossed_line_edges.begin(), t_.crossed_line_edges.end());
  }

  // Interior edges of one part whose two triangles do not share the input points of the edge:
  // a crack inside the surface that only welding closed.
  void count_sewn_edges() {
    std::vector<char> cracked(soup_.groups.size(), 0);
    for (int g : crack_groups_) cracked[g] = 1;
    for (const EdgeTable::Edge& e : t_.edges.edges) {
      if (e.line) continue;
      const int f0 = t_.edges.incident[e.first], f1 = t_.edges.incident[e.first + 1];
      if (multi_surface_group_[group_[f0]]) continue;
      auto input_point = [&](int f, int v) {
        for (int i = 0; i < 3; ++i)
          if (welded_[soup_.triangles[input_triangle_[f]][i]] == v) return soup_.triangles[input_triangle_[f]][i];
        return -1;
      };
      if (input_point(f0, e.a) != input_point(f1, e.a) || input_point(f0, e.b) != input_point(f1, e.b)) {
        ++model_.build.sewn_edges_within_group;
        cracked[group_[f0]] = 1;
        if (model_.build.crack_locations.size() < 20)
          model_.build.crack_locations.push_back(0.5 * (model_.vertices[e.a] + model_.vertices[e.b]));
      }
    }
    for (size_t g = 0; g < cracked.size(); ++g)
      if (cracked[g]) model_.build.cracked_groups.push_back(soup_.groups[g].name);
  }

  void make_interfaces_and_parts() {
    const int np = static_cast<int>(part_group_.size());
    // Interfaces in order of first appearance among the parts.
    std::map<std::string, int> interface_of;
    std::vector<int> parts_in_group(soup_.groups.size(), 0);
    for (int g : part_group_) ++parts_in_group[g];
    std::vector<int> index_in_group(soup_.groups.size(), 0);
    model_.parts.resize(np);
    for (int p = 0; p < np; ++p) {
      const SurfaceGroup& g = soup_.groups[part_group_[p]];
      const std::string iname = g.interface.empty() ? g.name : g.interface;
      auto [it, inserted] = interface_of.emplace(iname, static_cast<int>(model_.interfaces.size()));
      if (inserted) model_.interfaces.push_back(Interface{iname, g.kind, g.feature, {}});
      Interface& itf = model_.interfaces[it->second];
      if (itf.kind == SurfaceKind::Unknown) itf.kind = g.kind;
      itf.parts.push_back(p);
      SurfacePart& part = model_.parts[p];
      part.interface = it->second;
      part.name = parts_in_group[part_group_[p]] == 1
                      ? g.name
                      : g.name + "." + std::to_string(index_in_group[part_group_[p]]++);
      part.source_group = part_group_[p];
    }
    build_part_meshes();
  }

  // One OpenMesh per part. A vertex gets one mesh vertex per fan of triangles around it
  // (triangles linked through non-line edges of the part), so that a vertex where the part
  // touches itself becomes several mesh vertices and every mesh is manifold.
  void build_part_meshes() {
    const int nt = static_cast<int>(t_.triangles.size());
    UnionFind fans(3 * nt);  // corner (f, i) = 3f + i
    for (const EdgeTable::Edge& e : t_.edges.edges) {
      if (e.line) continue;
      const int f0 = t_.edges.incident[e.first], f1 = t_.edges.incident[e.first + 1];
      for (int v : {e.a, e.b}) {
        int c0 = -1, c1 = -1;
        for (int i = 0; i < 3; ++i) {
          if (t_.triangles[f0][i] == v) c0 = 3 * f0 + i;
          if (t_.triangles[f1][i] == v) c1 = 3 * f1 + i;
        }
        fans.unite(c0, c1);
      }
    }
    std::vector<int> mesh_vertex(3 * nt, -1);  // per fan root
    std::vector<std::unordered_map<int, int>> seen_model_vertex(model_.parts.size());
    for (int f : order_) {
      SurfacePart& part = model_.parts[t_.part[f]];
      std::array<SurfaceMesh::VertexHandle, 3> vh;
      for (int i = 0; i < 3; ++i) {
        const int root = fans.find(3 * f + i);
        if (mesh_vertex[root] < 0) {
          const int mv = t_.triangles[f][i];
          const Vec3& p = model_.vertices[mv];
          mesh_vertex[root] = part.mesh.add_vertex(SurfaceMesh::Point(p.x(), p.y(), p.z())).idx();
          part.model_vertex.push_back(mv);
          if (!seen_model_vertex[t_.part[f]].emplace(mv, mesh_vertex[root]).second) ++model_.build.split_vertices;
        }
        vh[i] = SurfaceMesh::VertexHandle(mesh_vertex[root]);
      }
      if (!part.mesh.add_face(vh[0], vh[1], vh[2]).is_valid()) {
        // OpenMesh refuses faces that would make a complex vertex; give this face its own
        // vertices so that no triangle is lost (the check module reports the split).
        for (int i = 0; i < 3; ++i) {
          const int mv = t_.triangles[f][i];
          const Vec3& p = model_.vertices[mv];
          vh[i] = part.mesh.add_vertex(SurfaceMesh::Point(p.x(), p.y(), p.z()));
          part.model_vertex.push_back(mv);
          ++model_.build.split_vertices;
        }
        part.mesh.add_face(vh[0], vh[1], vh[2]);
      }
      part.source_triangle.push_back(input_triangle_[f]);
    }
    // flatten() follows mesh face order: keep t_ in the same order for the later steps.
    ModelTriangles flat = flatten(model_);
    EdgeTable edges = EdgeTable::build(flat.triangles);
    for (EdgeTable::Edge& e : edges.edges) {
      const int k = t_.edges.find(e.a, e.b);
      e.line = t_.edges.edges[k].line;
    }
    t_.triangles = std::move(flat.triangles);
    t_.part = std::move(flat.part);
    t_.edges = std::move(edges);
  }

  void explicit_regions() {
    model_.build.explicit_regions = true;
    const int ng = static_cast<int>(soup_.groups.size());
    std::vector<Region> all;
    for (const ExplicitRegion& er : soup_.regions) {
      Region r;
      r.name = er.name;
      for (int sg : er.signed_groups) {
        const int g = std::abs(sg) - 1;
        if (sg == 0 || g >= ng)
          throw ModelError(soup_.source + ": region " + er.name + " lists surface " + std::to_string(sg) +
                           " that does not exist");
        if (group_part_[g] < 0) continue;  // all its triangles were degenerate
        r.sides.push_back({group_part_[g], sg > 0});
      }
      all.push_back(std::move(r));
    }
    // The universe is named so in GOCAD files; otherwise it is the region of largest positive
    // signed volume (its sides face away from the model).
    int universe = -1;
    for (size_t r = 0; r < all.size(); ++r) {
      std::string lower = all[r].name;
      std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
      if (lower == "universe") universe = static_cast<int>(r);
    }
    if (universe < 0) {
      double best = -std::numeric_limits<double>::infinity();
      for (size_t r = 0; r < all.size(); ++r) {
        const double v = model_.signed_volume(all[r].sides);
        if (v > best) {
          best = v;
          universe = static_cast<int>(r);
        }
      }
    }
    std::vector<int> region_index(all.size(), -1);
    for (size_t r = 0; r < all.size(); ++r) {
      if (static_cast<int>(r) == universe) {
        model_.universe = std::move(all[r]);
      } else {
        region_index[r] = static_cast<int>(model_.regions.size());
        model_.regions.push_back(std::move(all[r]));
      }
    }
    for (const auto& [name, members] : soup_.layers) {
      Layer layer{name, {}};
      for (int r : members)
        if (r >= 0 && r < static_cast<int>(region_index.size()) && region_index[r] >= 0)
          layer.regions.push_back(region_index[r]);
      model_.layers.push_back(std::move(layer));
    }
  }

  const SurfaceSoup& soup_;
  BuildOptions options_;
  StructuralModel model_;
  PartedTriangles t_;
  std::vector<int> welded_;          // input point -> welded vertex (-1: unused)
  std::vector<int> input_triangle_;  // kept triangle -> input triangle
  std::vector<int> group_;           // kept triangle -> group
  std::vector<int> part_group_;      // part -> group
  std::vector<int> group_part_;      // group -> part (explicit parts only)
  std::vector<int> colocated_groups_;
  std::unordered_set<uint64_t> colocated_keys_;  // (welded vertex, group) with several input points
  std::vector<int> crack_groups_;                // groups with crack vertices
  std::vector<char> multi_surface_group_;        // groups holding several surfaces
  std::vector<int> order_;           // triangles in BFS order per part
};

}  // namespace

StructuralModel build_model(const SurfaceSoup& soup, const BuildOptions& options) {
  if (!(options.weld_tolerance >= 0.0)) throw ParameterError("weld tolerance must be >= 0");
  if (!(options.feature_angle_deg >= 0.0 && options.feature_angle_deg <= 180.0))
    throw ParameterError("feature angle must be in [0, 180] degrees");
  return ModelBuilder(soup, options).build();
}

SurfaceGroup group_of_part(const StructuralModel& model, int part) {
  const SurfacePart& p = model.parts[static_cast<size_t>(part)];
  SurfaceGroup g;
  g.name = p.name;
  if (p.interface >= 0) {
    const Interface& itf = model.interfaces[static_cast<size_t>(p.interface)];
    g.interface = itf.name;
    g.kind = itf.kind;
    g.feature = itf.feature;
  }
  return g;
}

SurfaceSoup to_soup(const StructuralModel& model) {
  SurfaceSoup soup;
  soup.source = model.name;
  soup.points.reserve(model.vertices.size());
  for (const Vec3& v : model.vertices) soup.points.push_back(v + model.frame.origin);
  for (size_t p = 0; p < model.parts.size(); ++p) soup.groups.push_back(group_of_part(model, static_cast<int>(p)));
  const ModelTriangles t = flatten(model);
  soup.triangles = t.triangles;
  soup.triangle_group = t.part;
  soup.has_explicit_parts = true;
  auto signed_list = [](const Region& r) {
    std::vector<int> list;
    for (const Side& s : r.sides) list.push_back(s.positive ? s.part + 1 : -(s.part + 1));
    return list;
  };
  if (!model.regions.empty() || !model.universe.sides.empty()) {
    soup.regions.push_back({model.universe.name.empty() ? "Universe" : model.universe.name, signed_list(model.universe)});
    for (const Region& r : model.regions) soup.regions.push_back({r.name, signed_list(r)});
  }
  for (const Layer& l : model.layers) {
    std::vector<int> members;
    for (int r : l.regions) members.push_back(r + 1);  // the universe is region 0 of the soup
    soup.layers.emplace_back(l.name, members);
  }
  return soup;
}

}  // namespace voroseal
