// Contacts and corners from line edges (design.md, "Data layer").
#include <algorithm>
#include <map>

#include "framework/model/build_steps.h"

namespace voroseal {

namespace {

struct LineEdge {
  int a, b;
  std::vector<int> signature;  // sorted unique parts of the incident triangles
  int incidence;
  /// The signature without the parts that cross the edge in the file (see
  /// PartedTriangles::crossed_line_edges): what decides corners.
  std::vector<int> border;
};

}  // namespace

void build_contacts(StructuralModel& model, const PartedTriangles& t, CornerRule rule) {
  const int nv = static_cast<int>(model.vertices.size());
  std::vector<LineEdge> lines;
  for (const EdgeTable::Edge& e : t.edges.edges) {
    if (!e.line) continue;
    LineEdge l{e.a, e.b, {}, e.count, {}};
    for (int i = e.first; i < e.first + e.count; ++i) l.signature.push_back(t.part[t.edges.incident[i]]);
    std::sort(l.signature.begin(), l.signature.end());
    l.signature.erase(std::unique(l.signature.begin(), l.signature.end()), l.signature.end());
    for (int p : l.signature)
      if (!std::binary_search(t.crossed_line_edges.begin(), t.crossed_line_edges.end(), std::array<int, 3>{e.a, e.b, p}))
        l.border.push_back(p);
    lines.push_back(std::move(l));
  }

  // Line edges around each vertex (CSR).
  std::vector<int> start(nv + 1, 0);
  for (const LineEdge& l : lines) {
    ++start[l.a + 1];
    ++start[l.b + 1];
  }
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<int> around(start[nv]);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (size_t i = 0; i < lines.size(); ++i) {
      around[fill[lines[i].a]++] = static_cast<int>(i);
      around[fill[lines[i].b]++] = static_cast<int>(i);
    }
  }
  auto degree = [&](int v) { return start[v + 1] - start[v]; };

  // Parts touching each line vertex (for the Incidence rule: a part touching the line at one
  // vertex only makes that vertex a corner).
  std::vector<std::vector<int>> vertex_parts;
  if (rule == CornerRule::Incidence) {
    vertex_parts.resize(nv);
    for (size_t f = 0; f < t.triangles.size(); ++f)
      for (int v : t.triangles[f])
        if (degree(v) > 0) vertex_parts[v].push_back(t.part[f]);
    for (auto& p : vertex_parts) {
      std::sort(p.begin(), p.end());
      p.erase(std::unique(p.begin(), p.end()), p.end());
    }
  }

  std::vector<int> corner_of(nv, -1);
  auto make_corner = [&](int v) {
    if (corner_of[v] < 0) {
      corner_of[v] = static_cast<int>(model.corners.size());
      model.corners.push_back(Corner{v, {}});
    }
    return corner_of[v];
  };
  for (int v = 0; v < nv; ++v) {
    const int d = degree(v);
    if (d == 0) continue;
    bool corner = d != 2;
    if (!corner) {
      const LineEdge& e1 = lines[around[start[v]]];
      const LineEdge& e2 = lines[around[start[v] + 1]];
      corner = e1.border != e2.border || e1.incidence != e2.incidence;
      if (!corner && rule == CornerRule::Incidence) corner = vertex_parts[v] != e1.border;
    }
    if (corner) make_corner(v);
  }

  // Walk from corners along line edges; what is left are closed loops without a corner.
  std::vector<char> used(lines.size(), 0);
  auto other = [&](const LineEdge& l, int v) { return l.a == v ? l.b : l.a; };
  auto walk = [&](int v0, int first_edge) {
    Contact c;
    c.vertices.push_back(v0);
    c.parts = lines[first_edge].signature;
    c.incidence = lines[first_edge].incidence;
    int e = first_edge, v = v0;
    for (;;) {
      used[e] = 1;
      v = other(lines[e], v);
      c.vertices.push_back(v);
      if (corner_of[v] >= 0 || v == v0) break;
      int next = -1;
      for (int k = start[v]; k < start[v + 1]; ++k)
        if (!used[around[k]]) next = around[k];
      if (next < 0) break;  // cannot happen for a degree-2 non-corner vertex
      e = next;
    }
    const int id = static_cast<int>(model.contacts.size());
    c.corners = {corner_of[c.vertices.front()], corner_of[c.vertices.back()]};
    for (int k : c.corners)
      if (k >= 0) model.corners[k].contacts.push_back(id);
    model.contacts.push_back(std::move(c));
  };
  for (size_t k = 0; k < model.corners.size(); ++k) {
    const int v = model.corners[k].vertex;
    for (int i = start[v]; i < start[v + 1]; ++i)
      if (!used[around[i]]) walk(v, around[i]);
  }
  for (size_t i = 0; i < lines.size(); ++i) {
    if (used[i]) continue;
    // A closed contact (every vertex has degree 2 and none is a corner): start at its smallest
    // vertex so the result does not depend on the edge order.
    int vmin = lines[i].a;
    int e = static_cast<int>(i), v = lines[i].a;
    do {
      vmin = std::min(vmin, v);
      v = other(lines[e], v);
      e = around[start[v]] == e ? around[start[v] + 1] : around[start[v]];
    } while (e != static_cast<int>(i));
    if (rule == CornerRule::Incidence) make_corner(vmin);
    walk(vmin, around[start[vmin]]);
  }

  for (auto& part : model.parts) part.contacts.clear();
  for (size_t c = 0; c < model.contacts.size(); ++c)
    for (int p : model.contacts[c].parts) model.parts[p].contacts.push_back(static_cast<int>(c));
}

}  // namespace voroseal
