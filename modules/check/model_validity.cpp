#include "modules/check/model_validity.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <unordered_map>

#include "framework/core/edge_key.h"
#include "framework/core/error.h"
#include "framework/core/union_find.h"
#include "framework/geometry/self_intersections.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/model/border_gaps.h"
#include "framework/model/contact_wedges.h"

namespace voroseal {

const char* to_string(Severity severity) { return severity == Severity::Error ? "error" : "warning"; }

bool ValidityReport::valid() const { return errors() == 0; }

int ValidityReport::errors() const {
  return static_cast<int>(std::count_if(
      checks.begin(), checks.end(), [](const CheckEntry& c) { return c.severity == Severity::Error && !c.passed(); }));
}

int ValidityReport::warnings() const {
  return static_cast<int>(std::count_if(checks.begin(), checks.end(), [](const CheckEntry& c) {
    return c.severity == Severity::Warning && !c.passed();
  }));
}

const CheckEntry* ValidityReport::find(const std::string& name) const {
  for (const CheckEntry& c : checks)
    if (c.name == name) return &c;
  return nullptr;
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string plural(long n, const std::string& word) {
  if (n == 1) return "1 " + word;
  if (word.size() > 2 && word.compare(word.size() - 2, 2, "ex") == 0)
    return std::to_string(n) + " " + word.substr(0, word.size() - 2) + "ices";  // vertex -> vertices
  return std::to_string(n) + " " + word + "s";
}

std::string join(const std::vector<std::string>& names, size_t max = 8) {
  std::string s;
  for (size_t i = 0; i < names.size() && i < max; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > max) s += ", ... (" + std::to_string(names.size()) + " in all)";
  return s;
}


// Undirected edges of the flattened triangles with their incident triangles (CSR).
struct EdgeIncidence {
  std::vector<uint64_t> keys;  // sorted, unique
  std::vector<int> start;      // incident triangles of edge e: tri[start[e], start[e + 1])
  std::vector<int> tri;

  explicit EdgeIncidence(const std::vector<Triangle>& triangles) {
    std::vector<std::pair<uint64_t, int>> refs;
    refs.reserve(3 * triangles.size());
    for (size_t f = 0; f < triangles.size(); ++f)
      for (int i = 0; i < 3; ++i)
        refs.emplace_back(edge_key(triangles[f][i], triangles[f][(i + 1) % 3]), static_cast<int>(f));
    std::sort(refs.begin(), refs.end());
    tri.reserve(refs.size());
    for (size_t i = 0; i < refs.size(); ++i) {
      if (i == 0 || refs[i].first != refs[i - 1].first) {
        keys.push_back(refs[i].first);
        start.push_back(static_cast<int>(i));
      }
      tri.push_back(refs[i].second);
    }
    start.push_back(static_cast<int>(refs.size()));
  }
  size_t size() const { return keys.size(); }
  int count(size_t e) const { return start[e + 1] - start[e]; }
  int find(uint64_t key) const {
    auto it = std::lower_bound(keys.begin(), keys.end(), key);
    return it != keys.end() && *it == key ? static_cast<int>(it - keys.begin()) : -1;
  }
};

class ValidityChecker {
 public:
  ValidityChecker(const StructuralModel& model, const CheckOptions& options) : m_(model), o_(options) {}

  ValidityReport run() {
    const auto start = Clock::now();
    r_.checks.reserve(kChecks);
    r_.model = m_.name;
    r_.vertices = static_cast<int>(m_.vertices.size());
    r_.surfaces = static_cast<int>(m_.parts.size());
    r_.contacts = static_cast<int>(m_.contacts.size());
    r_.corners = static_cast<int>(m_.corners.size());
    r_.regions = static_cast<int>(m_.regions.size());
    // Everything else reads indices: a model whose indices are broken stops here.
    if (check_structure()) {
      close_timer();
      const auto prepare = Clock::now();
      t_ = flatten(m_);
      r_.triangles = static_cast<int>(t_.triangles.size());
      diag_ = m_.bbox().diagonal();
      edges_ = std::make_unique<EdgeIncidence>(t_.triangles);
      part_regions_ = m_.part_regions();
      r_.prepare_seconds = seconds_since(prepare);
      timer_ = Clock::now();
      check_boundary_incidence();
      check_finite_extension();
      check_free_borders();
      check_contacts();
      check_region_orientation();
      check_surface_orientation();
      check_cracks();
      check_colocated_vertices();
      check_triangles();
      check_short_edges();
      check_self_intersections();
      check_small_angles();
      check_thin_wedges();
      check_thin_border_gaps();
      check_split_vertices();
      check_disconnected_surfaces();
      check_input_repairs();
      check_unused_vertices();
    }
    close_timer();
    r_.seconds = seconds_since(start);
    return std::move(r_);
  }

 private:
  // References returned stay valid: the list is reserved for every check up front.
  CheckEntry& add(const std::string& name, Severity severity) {
    close_timer();
    r_.checks.push_back(CheckEntry{name, severity, 0, "", {}, nlohmann::json::object(), 0.0});
    timing_ = true;
    return r_.checks.back();
  }
  void close_timer() {
    const auto now = Clock::now();
    if (timing_) r_.checks.back().seconds = std::chrono::duration<double>(now - timer_).count();
    timing_ = false;
    timer_ = now;
  }
  bool room(const CheckEntry& e) const { return static_cast<int>(e.examples.size()) < o_.max_examples; }
  Vec3 file(const Vec3& local) const { return local + m_.frame.origin; }
  const std::string& part_name(int p) const { return m_.parts[p].name; }
  Vec3 midpoint(uint64_t key) const { return 0.5 * (m_.vertices[edge_key_first(key)] + m_.vertices[edge_key_second(key)]); }
  Vec3 centroid(int f) const {
    const Triangle& t = t_.triangles[f];
    return (m_.vertices[t[0]] + m_.vertices[t[1]] + m_.vertices[t[2]]) / 3.0;
  }
  std::vector<std::string> edge_parts(size_t e) const {
    std::set<int> parts;
    for (int i = edges_->start[e]; i < edges_->start[e + 1]; ++i) parts.insert(t_.part[edges_->tri[i]]);
    std::vector<std::string> names;
    for (int p : parts) names.push_back(part_name(p));
    return names;
  }
  std::string edge_text(uint64_t key) const {
    return "edge " + std::to_string(edge_key_first(key)) + "-" + std::to_string(edge_key_second(key));
  }
  void add_edge_example(CheckEntry& c, size_t e, const std::string& what) {
    if (room(c))
      c.examples.push_back(
          {what + " (" + edge_text(edges_->keys[e]) + ")", file(midpoint(edges_->keys[e])), edge_parts(e)});
  }
  std::string region_name(int r) const {
    if (r < 0) return m_.universe.name.empty() ? "Universe" : m_.universe.name;
    return m_.regions[r].name.empty() ? "region " + std::to_string(r) : m_.regions[r].name;
  }

  // ---- structure: every index in range, meshes agree with the model vertices.
  bool check_structure() {
    CheckEntry& c = add("structure", Severity::Error);
    const int nv = static_cast<int>(m_.vertices.size());
    const int np = static_cast<int>(m_.parts.size());
    const int nc = static_cast<int>(m_.contacts.size());
    const int nk = static_cast<int>(m_.corners.size());
    const int nr = static_cast<int>(m_.regions.size());
    const int ni = static_cast<int>(m_.interfaces.size());
    auto bad = [&](const std::string& what) {
      ++c.count;
      if (room(c)) c.examples.push_back({what, Vec3::Zero(), {}});
    };
    auto in = [](int i, int n) { return i >= 0 && i < n; };
    for (int v = 0; v < nv; ++v)
      if (!m_.vertices[v].allFinite()) bad("vertex " + std::to_string(v) + " has a non-finite coordinate");
    BoundingBox box;
    for (const Vec3& v : m_.vertices)
      if (v.allFinite()) box.extend(v);
    const double tolerance = 1e-9 * std::max(box.diagonal(), 1e-300);
    for (int p = 0; p < np; ++p) {
      const SurfacePart& part = m_.parts[p];
      const std::string name = "surface " + part.name;
      if (part.model_vertex.size() != part.mesh.n_vertices()) {
        bad(name + ": " + std::to_string(part.model_vertex.size()) + " model vertex ids for " +
            std::to_string(part.mesh.n_vertices()) + " mesh vertices");
        continue;
      }
      if (part.mesh.n_faces() == 0) bad(name + " has no triangle");
      if (!in(part.interface, ni)) bad(name + " has no valid interface");
      for (size_t i = 0; i < part.model_vertex.size(); ++i) {
        const int mv = part.model_vertex[i];
        if (!in(mv, nv)) {
          bad(name + ": mesh vertex " + std::to_string(i) + " maps to model vertex " + std::to_string(mv));
          continue;
        }
        const auto& q = part.mesh.point(SurfaceMesh::VertexHandle(static_cast<int>(i)));
        if ((Vec3(q[0], q[1], q[2]) - m_.vertices[mv]).norm() > tolerance)
          bad(name + ": mesh vertex " + std::to_string(i) + " is not at model vertex " + std::to_string(mv));
      }
      for (int k : part.contacts)
        if (!in(k, nc)) bad(name + " lists contact " + std::to_string(k));
    }
    for (int i = 0; i < ni; ++i)
      for (int p : m_.interfaces[i].parts)
        if (!in(p, np)) bad("interface " + m_.interfaces[i].name + " lists surface part " + std::to_string(p));
    for (int k = 0; k < nc; ++k) {
      const Contact& ct = m_.contacts[k];
      const std::string name = "contact " + std::to_string(k);
      if (ct.vertices.size() < 2) bad(name + " has fewer than 2 vertices");
      for (int v : ct.vertices)
        if (!in(v, nv)) bad(name + " has vertex " + std::to_string(v));
      for (int p : ct.parts)
        if (!in(p, np)) bad(name + " lists surface part " + std::to_string(p));
      for (int q : ct.corners)
        if (q != -1 && !in(q, nk)) bad(name + " ends at corner " + std::to_string(q));
    }
    for (int q = 0; q < nk; ++q) {
      if (!in(m_.corners[q].vertex, nv))
        bad("corner " + std::to_string(q) + " is at vertex " + std::to_string(m_.corners[q].vertex));
      for (int k : m_.corners[q].contacts)
        if (!in(k, nc)) bad("corner " + std::to_string(q) + " lists contact " + std::to_string(k));
    }
    auto check_sides = [&](const Region& region, const std::string& name) {
      for (const Side& s : region.sides)
        if (!in(s.part, np)) bad("region " + name + " has a side on surface part " + std::to_string(s.part));
    };
    check_sides(m_.universe, "Universe");
    for (int r = 0; r < nr; ++r) check_sides(m_.regions[r], m_.regions[r].name);
    for (const Layer& l : m_.layers)
      for (int r : l.regions)
        if (!in(r, nr)) bad("layer " + l.name + " lists region " + std::to_string(r));
    c.message = c.count ? plural(c.count, "broken reference") + " in the model; the other checks were skipped"
                        : "indices in range, surface meshes on their model vertices";
    return c.count == 0;
  }

  // ---- boundary_incidence: the adjacency lists agree both ways; sides belong to one region.
  void check_boundary_incidence() {
    CheckEntry& c = add("boundary_incidence", Severity::Error);
    auto bad = [&](const std::string& what, const Vec3& at, std::vector<std::string> surfaces) {
      ++c.count;
      if (room(c)) c.examples.push_back({what, file(at), std::move(surfaces)});
    };
    const int np = static_cast<int>(m_.parts.size());
    long list_mismatches = 0;
    for (int p = 0; p < np; ++p) {
      std::set<int> listed(m_.parts[p].contacts.begin(), m_.parts[p].contacts.end());
      for (int k : listed) {
        const auto& parts = m_.contacts[k].parts;
        if (std::find(parts.begin(), parts.end(), p) == parts.end()) {
          ++list_mismatches;
          bad("surface " + part_name(p) + " lists contact " + std::to_string(k) + ", which does not list it",
              m_.vertices[m_.contacts[k].vertices.front()], {part_name(p)});
        }
      }
    }
    for (size_t k = 0; k < m_.contacts.size(); ++k) {
      const Contact& ct = m_.contacts[k];
      for (int p : ct.parts) {
        const auto& listed = m_.parts[p].contacts;
        if (std::find(listed.begin(), listed.end(), static_cast<int>(k)) == listed.end()) {
          ++list_mismatches;
          bad("contact " + std::to_string(k) + " lists surface " + part_name(p) + ", which does not list it",
              m_.vertices[ct.vertices.front()], {part_name(p)});
        }
      }
      for (int q : ct.corners) {
        if (q < 0) continue;
        const auto& listed = m_.corners[q].contacts;
        if (std::find(listed.begin(), listed.end(), static_cast<int>(k)) == listed.end()) {
          ++list_mismatches;
          bad("contact " + std::to_string(k) + " ends at corner " + std::to_string(q) + ", which does not list it",
              m_.vertices[m_.corners[q].vertex], {});
        }
      }
    }
    for (size_t q = 0; q < m_.corners.size(); ++q)
      for (int k : m_.corners[q].contacts) {
        const auto& ends = m_.contacts[k].corners;
        if (ends[0] != static_cast<int>(q) && ends[1] != static_cast<int>(q)) {
          ++list_mismatches;
          bad("corner " + std::to_string(q) + " lists contact " + std::to_string(k) + ", which does not end there",
              m_.vertices[m_.corners[q].vertex], {});
        }
      }
    for (size_t i = 0; i < m_.interfaces.size(); ++i)
      for (int p : m_.interfaces[i].parts)
        if (m_.parts[p].interface != static_cast<int>(i)) {
          ++list_mismatches;
          bad("interface " + m_.interfaces[i].name + " lists surface " + part_name(p) + " of another interface",
              Vec3::Zero(), {part_name(p)});
        }
    // Every side of every part in exactly one region, the universe included.
    std::vector<int> uses(2 * m_.parts.size(), 0);
    for (const Side& s : m_.universe.sides) ++uses[2 * s.part + (s.positive ? 0 : 1)];
    for (const Region& region : m_.regions)
      for (const Side& s : region.sides) ++uses[2 * s.part + (s.positive ? 0 : 1)];
    long unassigned = 0, repeated = 0;
    for (int p = 0; p < np; ++p)
      for (int side = 0; side < 2; ++side) {
        const int n = uses[2 * p + side];
        if (n == 1) continue;
        (n == 0 ? unassigned : repeated) += 1;
        const auto& mesh = m_.parts[p].mesh;
        const auto fh = *mesh.faces_begin();
        const Vec3 at = m_.vertices[m_.parts[p].model_vertex[fh.halfedge().from().idx()]];
        bad(std::string(side == 0 ? "positive" : "negative") + " side of surface " + part_name(p) +
                (n == 0 ? " is in no region" : " is in " + std::to_string(n) + " regions"),
            at, {part_name(p)});
      }
    c.details = {{"list_mismatches", list_mismatches},
                 {"sides_in_no_region", unassigned},
                 {"sides_in_several_regions", repeated}};
    if (c.count == 0)
      c.message = "adjacency lists agree both ways; every surface side is in exactly one region";
    else
      c.message = plural(list_mismatches, "one-way adjacency reference") + ", " + plural(unassigned, "surface side") +
                  " in no region, " + plural(repeated, "surface side") + " in several regions";
  }

  // ---- finite_extension: bounded regions exist; the model boundary is closed and connected.
  void check_finite_extension() {
    CheckEntry& c = add("finite_extension", Severity::Error);
    const bool no_region = m_.regions.empty();
    // The model boundary: parts with exactly one side on the universe.
    std::vector<char> on_boundary(m_.parts.size(), 0);
    int boundary_parts = 0;
    for (size_t p = 0; p < m_.parts.size(); ++p) {
      const auto [plus, minus] = part_regions_[p];
      if ((plus == -1) != (minus == -1)) {
        on_boundary[p] = 1;
        ++boundary_parts;
      }
    }
    const int nt = static_cast<int>(t_.triangles.size());
    UnionFind components(nt);
    long open_edges = 0;
    for (size_t e = 0; e < edges_->size(); ++e) {
      int first = -1, n = 0;
      for (int i = edges_->start[e]; i < edges_->start[e + 1]; ++i) {
        const int f = edges_->tri[i];
        if (!on_boundary[t_.part[f]]) continue;
        ++n;
        if (first < 0)
          first = f;
        else
          components.unite(first, f);
      }
      if (n % 2 == 1) {
        ++open_edges;
        add_edge_example(c, e, "model boundary open along an edge");
      }
    }
    std::set<int> roots;
    for (int f = 0; f < nt; ++f)
      if (on_boundary[t_.part[f]]) roots.insert(components.find(f));
    const long pieces = static_cast<long>(roots.size());
    c.count =
        (no_region ? 1 : 0) + (boundary_parts == 0 && !no_region ? 1 : 0) + open_edges + (pieces > 1 ? pieces - 1 : 0);
    c.details = {{"bounded_regions", m_.regions.size()},
                 {"boundary_surfaces", boundary_parts},
                 {"boundary_open_edges", open_edges},
                 {"boundary_components", pieces}};
    std::vector<std::string> problems;
    if (no_region) problems.push_back("no bounded region: the surfaces enclose no volume (not sealed)");
    if (boundary_parts == 0 && !no_region) problems.push_back("no surface separates a region from the universe");
    if (open_edges) problems.push_back("the model boundary is open along " + plural(open_edges, "edge"));
    if (pieces > 1) {
      problems.push_back("the model boundary is in " + std::to_string(pieces) + " connected components");
      // One example per component.
      std::set<int> shown;
      for (int f = 0; f < nt && room(c); ++f) {
        if (!on_boundary[t_.part[f]] || !shown.insert(components.find(f)).second) continue;
        c.examples.push_back(
            {"boundary component " + std::to_string(shown.size()), file(centroid(f)), {part_name(t_.part[f])}});
      }
    }
    c.message = problems.empty() ? "the model boundary (" + plural(boundary_parts, "surface") +
                                       ") is closed and in one piece around " + plural(m_.regions.size(), "region")
                                 : join(problems, 10);
  }

  // ---- free_borders: a surface may end freely only inside one bounded region (a fault tip).
  void check_free_borders() {
    CheckEntry& c = add("free_borders", Severity::Error);
    long tips = 0;
    std::set<std::string> surfaces;
    for (size_t e = 0; e < edges_->size(); ++e) {
      if (edges_->count(e) != 1) continue;
      const int p = t_.part[edges_->tri[edges_->start[e]]];
      const auto [plus, minus] = part_regions_[p];
      if (plus == minus && plus >= 0) {
        ++tips;
        continue;
      }
      ++c.count;
      surfaces.insert(part_name(p));
      add_edge_example(c, e, std::string("free border between ") + region_name(plus) + " and " + region_name(minus));
    }
    c.details = {{"fault_tip_edges", tips}, {"open_edges", c.count}};
    c.message = c.count ? plural(c.count, "free border edge") + " open a region (not sealed), on " +
                              join(std::vector<std::string>(surfaces.begin(), surfaces.end()))
                        : (tips ? plural(tips, "free border edge") + ", all fault tips inside one region"
                                : std::string("no free border edge"));
  }

  // ---- contact_conformity, border_edges_off_contacts, non_manifold_edges_off_contacts.
  void check_contacts() {
    CheckEntry& c = add("contact_conformity", Severity::Error);
    std::vector<int> contact_of(edges_->size(), -1);
    long missing = 0, wrong_incidence = 0, twice = 0, bad_ends = 0;
    for (size_t k = 0; k < m_.contacts.size(); ++k) {
      const Contact& ct = m_.contacts[k];
      std::vector<std::string> names;
      for (int p : ct.parts) names.push_back(part_name(p));
      for (size_t i = 0; i + 1 < ct.vertices.size(); ++i) {
        const uint64_t key = edge_key(ct.vertices[i], ct.vertices[i + 1]);
        const int e = edges_->find(key);
        if (e < 0 || ct.vertices[i] == ct.vertices[i + 1]) {
          ++missing;
          ++c.count;
          if (room(c))
            c.examples.push_back({"contact " + std::to_string(k) + ": " + edge_text(key) + " is no triangle edge",
                                  file(midpoint(key)), names});
          continue;
        }
        if (contact_of[e] >= 0 && contact_of[e] != static_cast<int>(k)) {
          ++twice;
          ++c.count;
          add_edge_example(c, e, "edge on contacts " + std::to_string(contact_of[e]) + " and " + std::to_string(k));
        }
        contact_of[e] = static_cast<int>(k);
        std::set<int> parts;
        for (int j = edges_->start[e]; j < edges_->start[e + 1]; ++j) parts.insert(t_.part[edges_->tri[j]]);
        if (edges_->count(e) != ct.incidence || std::vector<int>(parts.begin(), parts.end()) != ct.parts) {
          ++wrong_incidence;
          ++c.count;
          add_edge_example(c, e,
                           "contact " + std::to_string(k) + " claims " + std::to_string(ct.incidence) +
                               " triangles on " + plural(ct.parts.size(), "surface") + ", the edge has " +
                               std::to_string(edges_->count(e)) + " on " + plural(parts.size(), "surface"));
        }
      }
      // A contact runs between its corners; a closed one may have none.
      const bool closed = ct.vertices.size() > 2 && ct.vertices.front() == ct.vertices.back();
      for (int end = 0; end < 2; ++end) {
        const int q = ct.corners[end];
        const int v = end == 0 ? ct.vertices.front() : ct.vertices.back();
        if ((q < 0 && !closed) || (q >= 0 && m_.corners[q].vertex != v)) {
          ++bad_ends;
          ++c.count;
          if (room(c))
            c.examples.push_back(
                {"contact " + std::to_string(k) + " does not end at its corner", file(m_.vertices[v]), names});
        }
      }
    }
    c.details = {{"contact_edges_not_triangle_edges", missing},
                 {"edges_with_other_incidence", wrong_incidence},
                 {"edges_on_two_contacts", twice},
                 {"ends_off_corners", bad_ends}};
    c.message = c.count ? plural(c.count, "contact inconsistency") + " with the triangles"
                        : plural(m_.contacts.size(), "contact") + " conformal to the surfaces, ending at their corners";

    CheckEntry& border = add("border_edges_off_contacts", Severity::Error);
    CheckEntry& non_manifold = add("non_manifold_edges_off_contacts", Severity::Error);
    long free_edges = 0, line_edges = 0;
    for (size_t e = 0; e < edges_->size(); ++e) {
      const int n = edges_->count(e);
      bool line = n != 2;
      if (n == 2) line = t_.part[edges_->tri[edges_->start[e]]] != t_.part[edges_->tri[edges_->start[e] + 1]];
      if (!line) continue;
      (n == 1 ? free_edges : line_edges) += 1;
      if (contact_of[e] >= 0) continue;
      CheckEntry& entry = n == 1 ? border : non_manifold;
      ++entry.count;
      add_edge_example(
          entry, e,
          n == 1 ? "free border edge on no contact" : "edge with " + std::to_string(n) + " triangles on no contact");
    }
    border.details = {{"free_border_edges", free_edges}};
    border.message = border.count ? plural(border.count, "free border edge") + " on no contact"
                                  : "all " + plural(free_edges, "free border edge") + " on contacts";
    non_manifold.details = {{"line_edges", line_edges}};
    non_manifold.message = non_manifold.count
                               ? plural(non_manifold.count, "non-manifold or between-surface edge") + " on no contact"
                               : "all " + plural(line_edges, "non-manifold or between-surface edge") + " on contacts";
  }

  // ---- region_orientation: signed sides close up; volumes have the right signs and add up.
  void check_region_orientation() {
    CheckEntry& c = add("region_orientation", Severity::Error);
    const int nr = static_cast<int>(m_.regions.size());
    const int universe = nr;  // index of the universe in the per-region arrays
    // Regions holding each side (normally exactly one; boundary_incidence reports the rest).
    std::vector<std::vector<int>> side_regions(2 * m_.parts.size());
    for (int r = 0; r <= nr; ++r)
      for (const Side& s : (r == universe ? m_.universe : m_.regions[r]).sides)
        side_regions[2 * s.part + (s.positive ? 0 : 1)].push_back(r);
    // The boundary of each region's 2-chain of sides, edge by edge: orient every side so that
    // the region lies on its positive side (a positive side keeps the triangle's orientation);
    // the traversals of every edge must then cancel.
    std::vector<long> unbalanced(nr + 1, 0);
    std::vector<long> first_bad(nr + 1, -1);
    std::vector<std::pair<int, int>> sums;  // (region, signed count) at one edge
    for (size_t e = 0; e < edges_->size(); ++e) {
      const int a = edge_key_first(edges_->keys[e]), b = edge_key_second(edges_->keys[e]);
      sums.clear();
      for (int i = edges_->start[e]; i < edges_->start[e + 1]; ++i) {
        const int f = edges_->tri[i];
        const Triangle& t = t_.triangles[f];
        const int s = (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b) ? 1 : -1;
        const int p = t_.part[f];
        for (int side = 0; side < 2; ++side)
          for (int r : side_regions[2 * p + side]) {
            const int delta = side == 0 ? s : -s;
            auto it =
                std::find_if(sums.begin(), sums.end(), [r](const std::pair<int, int>& x) { return x.first == r; });
            if (it == sums.end())
              sums.emplace_back(r, delta);
            else
              it->second += delta;
          }
      }
      for (const auto& [r, sum] : sums)
        if (sum != 0 && unbalanced[r]++ == 0) first_bad[r] = static_cast<long>(e);
    }
    // Triangles of each part, for example locations.
    std::vector<int> first_triangle(m_.parts.size(), -1);
    for (size_t f = t_.triangles.size(); f-- > 0;) first_triangle[t_.part[f]] = static_cast<int>(f);
    long open_regions = 0, wrong_sign = 0;
    double sum_bounded = 0, sum_abs = 0, universe_volume = 0;
    nlohmann::json volumes = nlohmann::json::array();
    for (int r = -1; r < nr; ++r) {
      const Region& region = r < 0 ? m_.universe : m_.regions[r];
      if (r < 0 && region.sides.empty() && nr == 0) continue;  // nothing to orient
      const int k = r < 0 ? universe : r;
      const double volume = m_.signed_volume(region.sides);
      const bool sign_ok = r < 0 ? volume > 0 : volume < 0;
      volumes.push_back({{"region", region_name(r)}, {"signed_volume", volume}, {"open_edges", unbalanced[k]}});
      if (r < 0)
        universe_volume = volume;
      else
        sum_bounded += volume;
      sum_abs += std::abs(volume);
      if (unbalanced[k]) {
        ++open_regions;
        ++c.count;
        add_edge_example(c, static_cast<size_t>(first_bad[k]),
                         region_name(r) + ": sides do not close up consistently along " +
                             plural(unbalanced[k], "edge") + " (wrong side signs or a hole)");
      }
      if (!sign_ok) {
        ++wrong_sign;
        ++c.count;
        if (room(c)) {
          std::vector<std::string> names;
          Vec3 at = Vec3::Zero();
          for (const Side& s : region.sides) {
            names.push_back((s.positive ? "+" : "-") + part_name(s.part));
            if (at == Vec3::Zero() && first_triangle[s.part] >= 0) at = centroid(first_triangle[s.part]);
          }
          c.examples.push_back({region_name(r) + ": signed volume " + number(volume) + ", expected " +
                                    (r < 0 ? "positive (universe)" : "negative (bounded region)"),
                                file(at), names});
        }
      }
    }
    // With each side in one region, the sum vanishes identically; a mismatch means sides missing
    // or repeated, which boundary_incidence details.
    const double mismatch = std::abs(universe_volume + sum_bounded);
    const bool adds_up = mismatch <= o_.volume_tolerance * std::max(sum_abs, 1e-300);
    if (!adds_up && nr > 0) ++c.count;
    c.details = {{"regions_not_closed", open_regions}, {"regions_with_wrong_sign", wrong_sign},
                 {"universe_volume", universe_volume}, {"sum_of_region_volumes", -sum_bounded},
                 {"volumes_add_up", adds_up},          {"regions", volumes}};
    if (c.count == 0)
      c.message = "every region closed and negatively oriented (universe positive), volumes add up";
    else
      c.message = plural(open_regions, "region") + " whose sides do not close up, " + plural(wrong_sign, "region") +
                  " with a wrong volume sign" + (adds_up || nr == 0 ? "" : ", region volumes do not add up");
  }

  // ---- surface_orientation: what the builder could not orient.
  void check_surface_orientation() {
    CheckEntry& c = add("surface_orientation", Severity::Error);
    c.count = m_.build.inconsistent_orientation_edges;
    c.message = c.count ? plural(c.count, "edge") + " where triangles of one surface disagree in orientation"
                        : "every surface consistently oriented";
  }

  // ---- cracks: colocated duplicates inside one surface (BuildReport).
  void check_cracks() {
    CheckEntry& c = add("cracks", Severity::Error);
    const BuildReport& b = m_.build;
    c.count = b.crack_vertices + b.sewn_edges_within_group;
    c.details = {{"crack_vertices", b.crack_vertices},
                 {"sewn_edges", b.sewn_edges_within_group},
                 {"colocated_points_in_group", b.colocated_points_in_group},
                 {"cracked_surfaces", b.cracked_groups},
                 {"groups_not_searched", b.multi_surface_groups}};
    const std::string not_searched =
        b.multi_surface_groups.empty()
            ? ""
            : "; not searched in " + join(b.multi_surface_groups) + " (several surfaces in one group)";
    if (c.count == 0) {
      c.message = (b.colocated_points_in_group ? plural(b.colocated_points_in_group, "colocated point") +
                                                     " inside surfaces, none a crack (RINGMesh's rule)"
                                               : std::string("no colocated duplicated vertices inside a surface")) +
                  not_searched;
      return;
    }
    c.message = plural(b.crack_vertices, "vertex") + " duplicated off any internal border and " +
                plural(b.sewn_edges_within_group, "edge") + " sewn by welding inside " + join(b.cracked_groups) +
                not_searched;
    // Surfaces at each example location: the parts through that vertex, or that edge.
    for (const Vec3& at : b.crack_locations) {
      if (!room(c)) break;
      std::set<int> parts;
      for (size_t f = 0; f < t_.triangles.size(); ++f)
        for (int i = 0; i < 3; ++i) {
          const Triangle& t = t_.triangles[f];
          if (m_.vertices[t[i]] == at || 0.5 * (m_.vertices[t[i]] + m_.vertices[t[(i + 1) % 3]]) == at)
            parts.insert(t_.part[f]);
        }
      std::vector<std::string> names;
      for (int p : parts) names.push_back(part_name(p));
      c.examples.push_back({"colocated duplicated vertices", file(at), names});
    }
  }

  // ---- colocated_vertices: distinct model vertices closer than the welding tolerance.
  void check_colocated_vertices() {
    CheckEntry& c = add("colocated_vertices", Severity::Error);
    const double tolerance = o_.colocated_relative * diag_;
    if (!(tolerance > 0)) {
      c.message = "not tested (zero tolerance)";
      return;
    }
    // Cells of size 2 * tolerance: a vertex can only be that close to vertices of its own cell
    // or of the nearer neighbour cell along each axis (8 cells). Cells are sorted by a hash of
    // their coordinates; a collision only costs a distance test.
    const double size = 2 * tolerance;
    const int nv = static_cast<int>(m_.vertices.size());
    auto hash = [](long long x, long long y, long long z) {
      return static_cast<uint64_t>(x) * 0x9E3779B97F4A7C15ull ^ static_cast<uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^
             static_cast<uint64_t>(z) * 0x165667B19E3779F9ull;
    };
    auto cell_of = [&](const Vec3& p, int d) { return static_cast<long long>(std::floor(p[d] / size)); };
    std::vector<std::pair<uint64_t, int>> cells(nv);
#pragma omp parallel for schedule(static)
    for (int v = 0; v < nv; ++v) {
      const Vec3& p = m_.vertices[v];
      cells[v] = {hash(cell_of(p, 0), cell_of(p, 1), cell_of(p, 2)), v};
    }
    std::sort(cells.begin(), cells.end());
    // Open-addressing table: key -> first index in `cells`; one probe per lookup, not a binary
    // search (the 8 lookups per vertex dominate on a million vertices).
    size_t capacity = 16;
    while (capacity < 2 * cells.size()) capacity *= 2;
    std::vector<std::pair<uint64_t, int>> table(capacity, {0, -1});
    auto slot_of = [&](uint64_t key) {
      size_t i = static_cast<size_t>((key ^ (key >> 29)) * 0xBF58476D1CE4E5B9ull) & (capacity - 1);
      while (table[i].second >= 0 && table[i].first != key) i = (i + 1) & (capacity - 1);
      return i;
    };
    for (size_t i = 0; i < cells.size(); ++i)
      if (i == 0 || cells[i].first != cells[i - 1].first)
        table[slot_of(cells[i].first)] = {cells[i].first, static_cast<int>(i)};
    std::vector<std::pair<int, int>> pairs;
    for (int v = 0; v < nv; ++v) {
      const Vec3& p = m_.vertices[v];
      long long own[3], step[3];
      for (int d = 0; d < 3; ++d) {
        own[d] = cell_of(p, d);
        step[d] = p[d] / size - own[d] < 0.5 ? -1 : 1;
      }
      for (int k = 0; k < 8; ++k) {
        const uint64_t key =
            hash(own[0] + ((k & 1) ? step[0] : 0), own[1] + ((k & 2) ? step[1] : 0), own[2] + ((k & 4) ? step[2] : 0));
        const int first = table[slot_of(key)].second;
        if (first < 0) continue;
        for (size_t i = first; i < cells.size() && cells[i].first == key; ++i)
          if (cells[i].second > v && (m_.vertices[cells[i].second] - p).norm() < tolerance)
            pairs.emplace_back(v, cells[i].second);
      }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());  // after hash collisions
    c.count = static_cast<long>(pairs.size());
    for (const auto& [v, w] : pairs) {
      if (!room(c)) break;
      c.examples.push_back(
          {"vertices " + std::to_string(v) + " and " + std::to_string(w), file(m_.vertices[v]), vertex_parts(v)});
    }
    c.details = {{"tolerance", tolerance}};
    c.message = c.count ? plural(c.count, "pair") + " of distinct vertices closer than " + number(tolerance)
                        : "no distinct vertices closer than " + number(tolerance);
  }

  std::vector<std::string> vertex_parts(int v) const {
    std::set<int> parts;
    for (size_t p = 0; p < m_.parts.size(); ++p)
      for (int mv : m_.parts[p].model_vertex)
        if (mv == v) {
          parts.insert(static_cast<int>(p));
          break;
        }
    std::vector<std::string> names;
    for (int p : parts) names.push_back(part_name(p));
    return names;
  }

  static std::string number(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
  }

  // ---- degenerate_triangles (error: collinear, exact) and near_degenerate_triangles (warning:
  // tiny area). The quality of every triangle is kept for small_angles.
  void check_triangles() {
    CheckEntry& c = add("degenerate_triangles", Severity::Error);
    quality_ = triangle_qualities(m_.vertices, t_.triangles);
    const long nt = static_cast<long>(t_.triangles.size());
    std::vector<char> collinear(nt, 0);
#pragma omp parallel for schedule(static)
    for (long f = 0; f < nt; ++f) collinear[f] = is_degenerate(m_.vertices, t_.triangles[f]);
    const double min_area = o_.degenerate_area_relative * diag_ * diag_;
    std::vector<int> flat, tiny;
    for (long f = 0; f < nt; ++f) {
      if (collinear[f])
        flat.push_back(static_cast<int>(f));
      else if (quality_[f].area < min_area)
        tiny.push_back(static_cast<int>(f));
    }
    auto by_area = [&](int a, int b) { return quality_[a].area < quality_[b].area; };
    std::sort(tiny.begin(), tiny.end(), by_area);
    auto list = [&](CheckEntry& e, const std::vector<int>& triangles) {
      e.count = static_cast<long>(triangles.size());
      for (int f : triangles) {
        if (!room(e)) break;
        e.examples.push_back({"triangle " + std::to_string(f) + ": area " + number(quality_[f].area) + ", min angle " +
                                  number(quality_[f].min_angle_deg) + " deg",
                              file(centroid(f)),
                              {part_name(t_.part[f])}});
      }
    };
    list(c, flat);
    c.message = c.count ? plural(c.count, "collinear triangle") + " (no normal, no orientation)"
                        : "no collinear triangle (exact test)";
    CheckEntry& near = add("near_degenerate_triangles", Severity::Warning);
    list(near, tiny);
    near.details = {{"area_threshold", min_area}};
    near.message =
        near.count ? plural(near.count, "triangle") + " with area < " + number(min_area) + " (a remesher removes them)"
                   : "no triangle with area < " + number(min_area);
  }

  // ---- short_edges.
  void check_short_edges() {
    CheckEntry& c = add("short_edges", Severity::Error);
    const double min_length = o_.short_edge_relative * diag_;
    double shortest = std::numeric_limits<double>::infinity();
    std::vector<std::pair<double, size_t>> bad;
    for (size_t e = 0; e < edges_->size(); ++e) {
      const double l = (m_.vertices[edge_key_first(edges_->keys[e])] - m_.vertices[edge_key_second(edges_->keys[e])]).norm();
      shortest = std::min(shortest, l);
      if (l < min_length) bad.emplace_back(l, e);
    }
    std::sort(bad.begin(), bad.end());
    c.count = static_cast<long>(bad.size());
    for (const auto& [l, e] : bad) add_edge_example(c, e, "length " + number(l));
    c.details = {{"length_threshold", min_length}, {"shortest_edge", edges_->size() ? shortest : 0.0}};
    c.message = c.count ? plural(c.count, "edge") + " shorter than " + number(min_length)
                        : "shortest edge " + number(shortest) + " (threshold " + number(min_length) + ")";
  }

  // ---- self_intersections (exact predicates).
  void check_self_intersections() {
    CheckEntry& c = add("self_intersections", Severity::Error);
    if (!o_.intersections) {
      c.message = "not tested (disabled)";
      c.details = {{"tested", false}};
      return;
    }
    const auto start = Clock::now();
    const std::vector<std::pair<int, int>> pairs = find_self_intersections(m_.vertices, t_.triangles);
    r_.intersection_seconds = seconds_since(start);
    c.count = static_cast<long>(pairs.size());
    std::map<std::pair<int, int>, long> by_parts;
    std::set<int> triangles;
    for (const auto& [a, b] : pairs) {
      triangles.insert(a);
      triangles.insert(b);
      const int pa = t_.part[a], pb = t_.part[b];
      ++by_parts[{std::min(pa, pb), std::max(pa, pb)}];
      if (room(c))
        c.examples.push_back({"triangles " + std::to_string(a) + " and " + std::to_string(b),
                              file(centroid(a)),
                              {part_name(pa), part_name(pb)}});
    }
    nlohmann::json surfaces = nlohmann::json::array();
    for (const auto& [key, n] : by_parts)
      surfaces.push_back({{"surfaces", {part_name(key.first), part_name(key.second)}}, {"pairs", n}});
    c.details = {{"tested", true},
                 {"triangles", triangles.size()},
                 {"by_surfaces", surfaces},
                 {"seconds", r_.intersection_seconds}};
    c.message = c.count ? plural(c.count, "intersecting triangle pair") + " (" + plural(triangles.size(), "triangle") +
                              ", " + plural(by_parts.size(), "surface pair") + ")"
                        : "no intersecting triangles among " + std::to_string(t_.triangles.size());
  }

  // ---- small_angles (warning): needles a remesher removes.
  void check_small_angles() {
    CheckEntry& c = add("small_angles", Severity::Warning);
    std::vector<int> bad;
    double smallest = std::numeric_limits<double>::infinity();
    for (size_t f = 0; f < quality_.size(); ++f) {
      smallest = std::min(smallest, quality_[f].min_angle_deg);
      if (quality_[f].min_angle_deg < o_.min_angle_warning_deg) bad.push_back(static_cast<int>(f));
    }
    std::sort(bad.begin(), bad.end(),
              [&](int a, int b) { return quality_[a].min_angle_deg < quality_[b].min_angle_deg; });
    c.count = static_cast<long>(bad.size());
    for (int f : bad) {
      if (!room(c)) break;
      c.examples.push_back({"triangle " + std::to_string(f) + ": min angle " + number(quality_[f].min_angle_deg) +
                                " deg, area " + number(quality_[f].area),
                            file(centroid(f)),
                            {part_name(t_.part[f])}});
    }
    c.details = {{"angle_threshold_deg", o_.min_angle_warning_deg},
                 {"min_angle_deg", quality_.empty() ? 0.0 : smallest}};
    c.message = c.count ? plural(c.count, "triangle") + " with an angle below " + number(o_.min_angle_warning_deg) +
                              " deg (smallest " + number(smallest) + " deg)"
                        : "no angle below " + number(o_.min_angle_warning_deg) + " deg";
  }

  // ---- thin_wedges (warning): surfaces meeting at a few degrees inside a region; no tet
  // mesh keeping them has a larger dihedral angle there (contact_wedges.h).
  void check_thin_wedges() {
    CheckEntry& c = add("thin_wedges", Severity::Warning);
    const std::vector<ContactWedge> wedges = thin_contact_wedges(m_, o_.thin_wedge_warning_deg);
    c.count = static_cast<long>(wedges.size());
    for (const ContactWedge& w : wedges) {
      if (!room(c)) break;
      std::string what =
          "edge " + std::to_string(w.a) + "-" + std::to_string(w.b) + ": " + number(w.angle_deg) + " deg";
      if (w.region >= 0) what += " in " + region_name(w.region);
      c.examples.push_back({what, file(0.5 * (m_.vertices[w.a] + m_.vertices[w.b])),
                            {part_name(w.lower_part), part_name(w.upper_part)}});
    }
    c.details = {{"angle_threshold_deg", o_.thin_wedge_warning_deg}};
    if (!wedges.empty()) c.details["min_wedge_deg"] = wedges.front().angle_deg;
    c.message = c.count ? plural(c.count, "contact edge") + " where surfaces meet at less than " +
                              number(o_.thin_wedge_warning_deg) + " deg inside a region (thinnest " +
                              number(wedges.front().angle_deg) +
                              " deg): a tet mesh keeping these surfaces has a dihedral angle this small there"
                        : "no surfaces meeting at less than " + number(o_.thin_wedge_warning_deg) + " deg";
  }

  // ---- thin_border_gaps (warning): a free border leaving another surface at a few degrees
  // past the corner where they meet (border_gaps.h).
  void check_thin_border_gaps() {
    CheckEntry& c = add("thin_border_gaps", Severity::Warning);
    const std::vector<BorderGap> gaps = thin_border_gaps(m_, o_.thin_wedge_warning_deg);
    c.count = static_cast<long>(gaps.size());
    for (const BorderGap& g : gaps) {
      if (!room(c)) break;
      c.examples.push_back({"border of " + part_name(g.border_part) + " from corner vertex " +
                                std::to_string(g.apex) + ": " + number(g.angle_deg) + " deg off " +
                                part_name(g.surface_part) + " at vertex " +
                                std::to_string(g.vertex),
                            file(m_.vertices[g.vertex]),
                            {part_name(g.border_part), part_name(g.surface_part)}});
    }
    c.details = {{"angle_threshold_deg", o_.thin_wedge_warning_deg}};
    if (!gaps.empty()) c.details["min_gap_deg"] = gaps.front().angle_deg;
    c.message =
        c.count ? plural(c.count, "free border") + " leaving a surface at less than " +
                      number(o_.thin_wedge_warning_deg) + " deg past the corner where they meet " +
                      "(narrowest " + number(gaps.front().angle_deg) +
                      " deg): tets across such a gap are flat unless its surfaces are meshed "
                      "finer than it is thick"
                : "no free border leaving a surface at less than " +
                      number(o_.thin_wedge_warning_deg) + " deg";
  }

  // ---- split_vertices (warning): a surface touching itself at a vertex.
  void check_split_vertices() {
    CheckEntry& c = add("split_vertices", Severity::Warning);
    for (size_t p = 0; p < m_.parts.size(); ++p) {
      std::vector<int> ids = m_.parts[p].model_vertex;
      std::sort(ids.begin(), ids.end());
      for (size_t i = 1; i < ids.size(); ++i)
        if (ids[i] == ids[i - 1] && (i < 2 || ids[i - 2] != ids[i])) {
          ++c.count;
          if (room(c))
            c.examples.push_back({"vertex " + std::to_string(ids[i]), file(m_.vertices[ids[i]]), {part_name(p)}});
        }
    }
    c.message = c.count ? plural(c.count, "vertex") + " where a surface touches itself (split in its mesh)"
                        : "no surface touches itself at a vertex";
  }

  // ---- disconnected_surfaces (warning).
  void check_disconnected_surfaces() {
    CheckEntry& c = add("disconnected_surfaces", Severity::Warning);
    for (size_t p = 0; p < m_.parts.size(); ++p) {
      const SurfaceMesh& mesh = m_.parts[p].mesh;
      UnionFind uf(mesh.n_faces());
      for (const auto& eh : mesh.edges()) {
        if (eh.is_boundary()) continue;
        uf.unite(eh.h0().face().idx(), eh.h1().face().idx());
      }
      std::set<int> roots;
      for (const auto& fh : mesh.faces()) roots.insert(uf.find(fh.idx()));
      if (roots.size() > 1) {
        ++c.count;
        if (room(c)) {
          const auto fh = *mesh.faces_begin();
          c.examples.push_back({"surface " + part_name(p) + " in " + std::to_string(roots.size()) + " pieces",
                                file(m_.vertices[m_.parts[p].model_vertex[fh.halfedge().from().idx()]]),
                                {part_name(p)}});
        }
      }
    }
    c.message =
        c.count ? plural(c.count, "surface part") + " made of several pieces" : "every surface part in one piece";
  }

  // ---- input_repairs (warning): what the builder changed in the file's triangles.
  void check_input_repairs() {
    CheckEntry& c = add("input_repairs", Severity::Warning);
    const BuildReport& b = m_.build;
    // Flips matter only where the file's orientation carries meaning (explicit region sides);
    // the triangles of an OBJ or Medit soup have no orientation to keep.
    const long flipped = b.explicit_regions ? b.flipped_triangles : 0;
    c.count = b.degenerate_triangles_dropped + b.duplicate_triangles_dropped + flipped;
    c.details = {{"degenerate_triangles_dropped", b.degenerate_triangles_dropped},
                 {"duplicate_triangles_dropped", b.duplicate_triangles_dropped},
                 {"flipped_triangles", b.flipped_triangles},
                 {"merged_points", b.merged_points}};
    c.message = c.count ? std::to_string(b.degenerate_triangles_dropped) + " degenerate and " +
                              std::to_string(b.duplicate_triangles_dropped) + " duplicated triangles dropped, " +
                              std::to_string(flipped) + " flipped to agree with their surface"
                        : "no triangle dropped or flipped when building the model";
  }

  // ---- unused_vertices (warning).
  void check_unused_vertices() {
    CheckEntry& c = add("unused_vertices", Severity::Warning);
    std::vector<char> used(m_.vertices.size(), 0);
    for (const Triangle& t : t_.triangles)
      for (int v : t) used[v] = 1;
    for (size_t v = 0; v < used.size(); ++v)
      if (!used[v]) {
        ++c.count;
        if (room(c)) c.examples.push_back({"vertex " + std::to_string(v), file(m_.vertices[v]), {}});
      }
    c.message = c.count ? plural(c.count, "vertex") + " on no triangle" : "every vertex on a triangle";
  }

  static constexpr size_t kChecks = 32;  // more than the checks of the header list
  const StructuralModel& m_;
  const CheckOptions& o_;
  ValidityReport r_;
  Clock::time_point timer_ = Clock::now();
  bool timing_ = false;  // the last entry's time is still running
  ModelTriangles t_;
  double diag_ = 0;
  std::unique_ptr<EdgeIncidence> edges_;
  std::vector<std::pair<int, int>> part_regions_;
  std::vector<TriangleQuality> quality_;
};

}  // namespace

ValidityReport check_model(const StructuralModel& model, const CheckOptions& options) {
  auto nonnegative = [](double x, const char* name) {
    if (!(x >= 0)) throw ParameterError(std::string("check: ") + name + " must be >= 0");
  };
  nonnegative(options.short_edge_relative, "short edge threshold");
  nonnegative(options.degenerate_area_relative, "degenerate area threshold");
  nonnegative(options.min_angle_warning_deg, "min angle warning");
  nonnegative(options.thin_wedge_warning_deg, "thin wedge warning");
  nonnegative(options.colocated_relative, "colocated tolerance");
  nonnegative(options.volume_tolerance, "volume tolerance");
  if (options.max_examples < 0) throw ParameterError("check: max examples must be >= 0");
  return ValidityChecker(model, options).run();
}

nlohmann::json to_json(const ValidityReport& report) {
  nlohmann::json checks = nlohmann::json::array();
  for (const CheckEntry& c : report.checks) {
    nlohmann::json examples = nlohmann::json::array();
    for (const CheckExample& e : c.examples)
      examples.push_back(
          {{"what", e.what}, {"location", {e.location.x(), e.location.y(), e.location.z()}}, {"surfaces", e.surfaces}});
    checks.push_back({{"name", c.name},
                      {"severity", to_string(c.severity)},
                      {"count", c.count},
                      {"passed", c.passed()},
                      {"message", c.message},
                      {"details", c.details},
                      {"seconds", c.seconds},
                      {"examples", examples}});
  }
  return {{"model", report.model},
          {"valid", report.valid()},
          {"errors", report.errors()},
          {"warnings", report.warnings()},
          {"counts",
           {{"vertices", report.vertices},
            {"triangles", report.triangles},
            {"surfaces", report.surfaces},
            {"contacts", report.contacts},
            {"corners", report.corners},
            {"regions", report.regions}}},
          {"checks", checks},
          {"timing_s",
           {{"total", report.seconds},
            {"prepare", report.prepare_seconds},
            {"self_intersections", report.intersection_seconds}}}};
}

std::string to_text(const ValidityReport& report) {
  std::ostringstream out;
  out << "check " << report.model << "\n"
      << "  " << report.vertices << " vertices, " << report.triangles << " triangles, " << report.surfaces
      << " surfaces, " << report.contacts << " contacts, " << report.corners << " corners, " << report.regions
      << " regions\n";
  for (const CheckEntry& c : report.checks) {
    const char* status = c.passed() ? "ok     " : (c.severity == Severity::Error ? "ERROR  " : "warning");
    char name[40];
    std::snprintf(name, sizeof name, "%-32s", c.name.c_str());
    out << "  " << status << " " << name << " " << c.message << "\n";
    if (c.passed()) continue;
    for (const CheckExample& e : c.examples) {
      char at[128];
      std::snprintf(at, sizeof at, "(%.10g, %.10g, %.10g)", e.location.x(), e.location.y(), e.location.z());
      out << "            " << e.what;
      if (e.location != Vec3::Zero() || !e.surfaces.empty()) out << " at " << at;
      if (!e.surfaces.empty()) out << " [" << join(e.surfaces, 6) << "]";
      out << "\n";
    }
  }
  char time[64];
  std::snprintf(time, sizeof time, "%.3f s", report.seconds);
  out << (report.valid() ? "VALID" : "INVALID") << ": " << plural(report.errors(), "error") << ", "
      << plural(report.warnings(), "warning") << " (" << time << ")\n";
  return out.str();
}

}  // namespace voroseal
