// Regions inferred from the surfaces alone: sort the triangles radially around every line
// edge and glue the sides that face each other across the wedge between two neighbours
// (union-find over part sides). Components that share no line edge (a model made of two
// disjoint boxes, a floating surface) are placed with generalized winding numbers.
#include <algorithm>
#include <cmath>

#include "framework/core/union_find.h"
#include "framework/model/build_steps.h"

namespace voroseal {

namespace {

// Side node of part p: 2p for the positive side, 2p + 1 for the negative side.
int side_node(int part, bool positive) { return 2 * part + (positive ? 0 : 1); }

// Solid angle of triangle (a, b, c) seen from the origin (Van Oosterom & Strackee 1983).
double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double num = a.dot(b.cross(c));
  const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(num, den);
}

}  // namespace

void infer_regions(StructuralModel& model, const PartedTriangles& t) {
  const int np = static_cast<int>(model.parts.size());
  UnionFind sides(2 * np);
  UnionFind components(np);  // parts linked through line edges

  std::vector<FanBlade> fan;
  for (const EdgeTable::Edge& e : t.edges.edges) {
    if (!e.line) continue;
    radial_fan(model.vertices, t.triangles, e.a, e.b, &t.edges.incident[e.first], e.count, fan);
    for (const FanBlade& blade : fan) components.unite(t.part[blade.triangle], t.part[t.edges.incident[e.first]]);
    // Across the wedge between fan[i] and fan[i+1], the side of fan[i] facing increasing
    // angles meets the side of fan[i+1] facing decreasing angles (radial_fan).
    const size_t n = fan.size();
    for (size_t i = 0; i < n; ++i) {
      const FanBlade& lo = fan[i];
      const FanBlade& hi = fan[(i + 1) % n];
      sides.unite(side_node(t.part[lo.triangle], lo.forward), side_node(t.part[hi.triangle], !hi.forward));
    }
  }

  std::vector<int> cls;
  const int nclasses = sides.labels(cls);
  std::vector<std::vector<Side>> class_sides(nclasses);
  for (int p = 0; p < np; ++p) {
    class_sides[cls[side_node(p, true)]].push_back({p, true});
    class_sides[cls[side_node(p, false)]].push_back({p, false});
  }
  std::vector<double> volume(nclasses);
  double scale = 0.0;
  for (int k = 0; k < nclasses; ++k) {
    volume[k] = model.signed_volume(class_sides[k]);
    scale = std::max(scale, std::abs(volume[k]));
  }
  std::vector<int> comp;
  components.labels(comp);

  // A class enclosing nothing from inside (volume >= 0) is the outer shell of its component:
  // a closed component's outside, or an open one's only class. Bounded regions have volume -V.
  const double eps = 1e-9 * scale;
  std::vector<int> bounded, shells;
  for (int k = 0; k < nclasses; ++k) (volume[k] < -eps ? bounded : shells).push_back(k);

  // Each shell belongs to the innermost bounded region of another component that contains it,
  // or to the universe.
  std::vector<int> shell_owner(nclasses, -1);  // index into `bounded`, -1: universe
  if (shells.size() > 1) {
    for (int s : shells) {
      const Side& probe = class_sides[s].front();
      const SurfacePart& part = model.parts[probe.part];
      const auto f = *part.mesh.faces().begin();
      Vec3 point = Vec3::Zero();
      for (auto vh : f.vertices()) point += model.vertices[part.model_vertex[vh.idx()]] / 3.0;
      const int own = comp[probe.part];
      double best = std::numeric_limits<double>::infinity();
      for (size_t bi = 0; bi < bounded.size(); ++bi) {
        const int b = bounded[bi];
        if (comp[class_sides[b].front().part] == own) continue;
        double w = 0.0;
        for (const Side& side : class_sides[b]) {
          const SurfacePart& sp = model.parts[side.part];
          for (const auto& face : sp.mesh.faces()) {
            auto h = face.halfedge();
            const Vec3 a = model.vertices[sp.model_vertex[h.from().idx()]] - point;
            const Vec3 bb = model.vertices[sp.model_vertex[h.to().idx()]] - point;
            const Vec3 c = model.vertices[sp.model_vertex[h.next().to().idx()]] - point;
            w += (side.positive ? 1.0 : -1.0) * solid_angle(a, bb, c);
          }
        }
        w /= 4.0 * M_PI;
        // Normals point into a bounded region, so a point inside it has winding number -1.
        if (w < -0.5 && -volume[b] < best) {
          best = -volume[b];
          shell_owner[s] = static_cast<int>(bi);
        }
      }
    }
  }

  model.regions.clear();
  model.universe = Region{"Universe", {}};
  for (size_t bi = 0; bi < bounded.size(); ++bi) {
    Region r;
    r.name = "Region_" + std::to_string(bi + 1);
    r.sides = class_sides[bounded[bi]];
    model.regions.push_back(std::move(r));
  }
  for (int s : shells) {
    auto& target = shell_owner[s] < 0 ? model.universe.sides : model.regions[shell_owner[s]].sides;
    target.insert(target.end(), class_sides[s].begin(), class_sides[s].end());
  }
  for (Region& r : model.regions) std::sort(r.sides.begin(), r.sides.end());
  std::sort(model.universe.sides.begin(), model.universe.sides.end());
}

}  // namespace voroseal
