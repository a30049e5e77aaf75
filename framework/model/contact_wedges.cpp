#include "framework/model/contact_wedges.h"

#include <algorithm>
#include <cmath>

#include "framework/model/triangle_topology.h"

namespace voroseal {

std::vector<ContactWedge> thin_contact_wedges(const StructuralModel& model, double max_deg) {
  std::vector<ContactWedge> wedges;
  const ModelTriangles flat = flatten(model);
  const EdgeTable edges = EdgeTable::build(flat.triangles);
  const std::vector<std::pair<int, int>> sides = model.part_regions();
  const double max_rad = max_deg * M_PI / 180.0;
  std::vector<FanBlade> fan;
  for (size_t c = 0; c < model.contacts.size(); ++c) {
    const std::vector<int>& line = model.contacts[c].vertices;
    for (size_t k = 0; k + 1 < line.size(); ++k) {
      const int a = std::min(line[k], line[k + 1]), b = std::max(line[k], line[k + 1]);
      const int e = edges.find(a, b);
      if (e < 0 || edges.edges[e].count < 2) continue;  // a free border: no wedge
      const EdgeTable::Edge& edge = edges.edges[e];
      radial_fan(model.vertices, flat.triangles, a, b, &edges.incident[edge.first], edge.count, fan);
      const size_t n = fan.size();
      for (size_t i = 0; i < n; ++i) {
        const double gap = wedge_after(fan, i);
        if (!(gap < max_rad)) continue;
        const FanBlade& lo = fan[i];
        const FanBlade& hi = fan[(i + 1) % n];
        const int part = flat.part[lo.triangle];
        const int region = lo.forward ? sides[part].first : sides[part].second;
        if (region == -1) continue;
        wedges.push_back({a, b, static_cast<int>(c), part, flat.part[hi.triangle], region, gap * 180.0 / M_PI});
      }
    }
  }
  std::sort(wedges.begin(), wedges.end(), [](const ContactWedge& x, const ContactWedge& y) {
    return x.angle_deg != y.angle_deg ? x.angle_deg < y.angle_deg : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  return wedges;
}

}  // namespace voroseal
