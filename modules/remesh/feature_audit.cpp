#include "modules/remesh/feature_audit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace voroseal {

int FeatureAudit::larger_than_resolution() const {
  auto large = [&](double size) { return size >= resolution ? 1 : 0; };
  int n = 0;
  for (const LostFeature& f : lost) n += large(f.size);
  for (const LostRegion& r : regions_lost) n += large(r.thickness);
  for (const LostRegionContact& c : region_contacts_lost) n += large(c.width);
  return n;
}

namespace {

// Points a lost region or region contact is refined at, per part: spread over its triangles so
// that the refinement reaches where the region thins out, wherever that is.
constexpr int kPlacesPerPart = 8;

struct PartMeasure {
  double width = 0.0;             // 2 × area / perimeter (perimeter: edges with one triangle)
  double area = 0.0;
  Vec3 somewhere = Vec3::Zero();  // centroid of its largest triangle
  std::vector<Vec3> places;       // centroids of up to kPlacesPerPart triangles, evenly strided
};

std::vector<PartMeasure> part_measures(const StructuralModel& model) {
  const ModelTriangles mt = flatten(model);
  const std::vector<Vec3>& p = model.vertices;
  std::vector<PartMeasure> out(model.parts.size());
  std::vector<double> perimeter(model.parts.size(), 0.0), largest(model.parts.size(), -1.0);
  std::vector<std::map<std::pair<int, int>, int>> edges(model.parts.size());
  for (size_t t = 0; t < mt.triangles.size(); ++t) {
    const Triangle& f = mt.triangles[t];
    const int part = mt.part[t];
    const double a = 0.5 * (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]).norm();
    if (a > largest[part]) {
      largest[part] = a;
      out[part].somewhere = (p[f[0]] + p[f[1]] + p[f[2]]) / 3.0;
    }
    out[part].area += a;
    for (int i = 0; i < 3; ++i) ++edges[part][std::minmax(f[i], f[(i + 1) % 3])];
  }
  std::vector<std::vector<int>> triangles_of(model.parts.size());
  for (size_t t = 0; t < mt.triangles.size(); ++t) triangles_of[mt.part[t]].push_back(static_cast<int>(t));
  for (size_t part = 0; part < model.parts.size(); ++part) {
    const std::vector<int>& own = triangles_of[part];
    const size_t stride = std::max<size_t>(1, own.size() / kPlacesPerPart);
    for (size_t k = stride / 2; k < own.size(); k += stride) {
      const Triangle& f = mt.triangles[static_cast<size_t>(own[k])];
      out[part].places.push_back((p[f[0]] + p[f[1]] + p[f[2]]) / 3.0);
    }
    for (const auto& [e, n] : edges[part])
      if (n == 1) perimeter[part] += (p[e.first] - p[e.second]).norm();
    // A closed part (no border) is as wide as its area allows.
    out[part].width = perimeter[part] > 0.0 ? 2.0 * out[part].area / perimeter[part] : std::sqrt(out[part].area);
  }
  return out;
}

// The input parts meeting at every contact and at every corner of `m` (parts mapped by `to_input`).
using PartSet = std::vector<int>;
std::pair<std::vector<PartSet>, std::vector<PartSet>> contact_and_corner_parts(const StructuralModel& m,
                                                                              const std::vector<int>& to_input) {
  std::vector<PartSet> contacts(m.contacts.size()), corners(m.corners.size());
  auto tidy = [](PartSet& s) {
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
  };
  for (size_t c = 0; c < m.contacts.size(); ++c) {
    for (int part : m.contacts[c].parts) contacts[c].push_back(to_input[part]);
    tidy(contacts[c]);
  }
  for (size_t k = 0; k < m.corners.size(); ++k) {
    for (int c : m.corners[k].contacts) corners[k].insert(corners[k].end(), contacts[c].begin(), contacts[c].end());
    tidy(corners[k]);
  }
  return {contacts, corners};
}

// Marks lost the input features the output has no counterpart for, largest first: an output
// feature where the same parts meet, else one where they meet with others (a part merged away
// nearby now touches it too), each output feature used once.
void match(const std::vector<PartSet>& in, const std::vector<PartSet>& out, const std::vector<double>& size,
           std::vector<char>& lost, std::vector<char>& used) {
  std::vector<int> order(in.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size[a] > size[b]; });
  used.assign(out.size(), 0);
  lost.assign(in.size(), 1);
  for (bool exact : {true, false})
    for (int i : order) {
      if (!lost[i]) continue;
      for (size_t j = 0; j < out.size(); ++j) {
        if (used[j]) continue;
        const bool same = out[j] == in[i];
        if (same || (!exact && std::includes(out[j].begin(), out[j].end(), in[i].begin(), in[i].end()))) {
          used[j] = 1;
          lost[i] = 0;
          break;
        }
      }
    }
}

// Distance from x to the polyline through `line`'s vertices.
double distance_to_line(const Vec3& x, const std::vector<int>& line, const std::vector<Vec3>& p) {
  double best = line.empty() ? std::numeric_limits<double>::infinity() : (x - p[line[0]]).norm();
  for (size_t i = 1; i < line.size(); ++i) {
    const Vec3 &a = p[line[i - 1]], &b = p[line[i]];
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (x - (a + t * ab)).norm());
  }
  return best;
}

// Distance from x to a box (0 inside); no larger than the distance to anything in the box.
double distance_to_box(const Vec3& x, const BoundingBox& box) {
  return std::sqrt(box.squared_distance(x));
}

// How close contact c runs along another contact: the smallest, over the other contacts, of the
// largest distance from c's vertices to it (a contact 70 m from a box edge all along: 70 m; two
// contacts meeting at a wide angle: the length of the shorter). A contact d is only walked when
// c's ends and middle all lie closer to d's box than the best so far (the box is no farther than
// the line), the one with the nearest box first: linear in the contacts, not quadratic.
double proximity(const StructuralModel& m, int c, const std::vector<BoundingBox>& boxes) {
  const std::vector<int>& line = m.contacts[c].vertices;
  if (line.empty()) return std::numeric_limits<double>::infinity();
  const int nc = static_cast<int>(m.contacts.size());
  const Vec3 probes[3] = {m.vertices[line.front()], m.vertices[line[line.size() / 2]],
                          m.vertices[line.back()]};
  std::vector<double> bound(nc, std::numeric_limits<double>::infinity());
  int first = -1;
  for (int d = 0; d < nc; ++d) {
    if (d == c) continue;
    bound[d] = 0.0;
    for (const Vec3& x : probes) bound[d] = std::max(bound[d], distance_to_box(x, boxes[d]));
    if (first < 0 || bound[d] < bound[first]) first = d;
  }
  double best = std::numeric_limits<double>::infinity();
  auto walk = [&](int d) {
    double farthest = 0.0;
    for (int v : line) {
      farthest = std::max(farthest, distance_to_line(m.vertices[v], m.contacts[d].vertices, m.vertices));
      if (farthest >= best) break;
    }
    best = std::min(best, farthest);
  };
  if (first >= 0) walk(first);
  for (int d = 0; d < nc; ++d)
    if (d != c && d != first && bound[d] < best) walk(d);
  return best;
}

}  // namespace

FeatureAudit audit_features(const StructuralModel& input, const StructuralModel& output,
                            const std::vector<int>& input_part, const std::vector<int>& regions_lost,
                            const std::vector<std::pair<int, int>>& region_contacts_lost, double resolution) {
  FeatureAudit audit;
  audit.resolution = resolution;
  const std::vector<Vec3>& p = input.vertices;

  std::vector<char> part_kept(input.parts.size(), 0);
  for (int part : input_part) part_kept[part] = 1;
  std::vector<int> identity(input.parts.size());
  for (size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<int>(i);
  const auto [in_contacts, in_corners] = contact_and_corner_parts(input, identity);
  const auto [out_contacts, out_corners] = contact_and_corner_parts(output, input_part);

  // A contact is no larger than the narrowest part it bounds (two contacts along a thin strip
  // become one when the strip goes), a corner no larger than its contacts or the distance to
  // the nearest other corner.
  const std::vector<PartMeasure> parts = part_measures(input);
  std::vector<double> length(input.contacts.size(), 0.0), spacing(input.corners.size());
  for (size_t c = 0; c < input.contacts.size(); ++c) {
    const std::vector<int>& line = input.contacts[c].vertices;
    for (size_t i = 1; i < line.size(); ++i) length[c] += (p[line[i]] - p[line[i - 1]]).norm();
    for (int part : input.contacts[c].parts) length[c] = std::min(length[c], parts[part].width);
  }
  for (size_t k = 0; k < input.corners.size(); ++k) {
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < input.corners.size(); ++j)
      if (j != k) nearest = std::min(nearest, (p[input.corners[j].vertex] - p[input.corners[k].vertex]).norm());
    for (int c : input.corners[k].contacts) nearest = std::min(nearest, length[c]);
    spacing[k] = nearest;
  }
  std::vector<char> contact_lost, corner_lost, contact_used, corner_used;
  match(in_contacts, out_contacts, length, contact_lost, contact_used);
  match(in_corners, out_corners, spacing, corner_lost, corner_used);
  // Gained: the second and later output parts of one input part, unmatched output contacts and
  // corners.
  // Output vertices in the input's local frame.
  const Vec3 shift = output.frame.origin - input.frame.origin;
  auto at = [&](int v) { return Vec3(output.vertices[v] + shift); };
  std::vector<char> part_seen(input.parts.size(), 0);
  for (size_t o = 0; o < input_part.size() && o < output.parts.size(); ++o) {
    const SurfacePart& part = output.parts[o];
    if (part_seen[input_part[o]]++ == 0 || part.model_vertex.empty()) continue;
    audit.gained.push_back({VertexFeature::Surface, static_cast<int>(o), 0.0,
                            at(part.model_vertex[part.model_vertex.size() / 2])});
  }
  for (size_t c = 0; c < contact_used.size(); ++c)
    if (!contact_used[c]) {
      const std::vector<int>& line = output.contacts[c].vertices;
      audit.gained.push_back(
          {VertexFeature::Contact, static_cast<int>(c), 0.0, at(line[line.size() / 2])});
    }
  for (size_t k = 0; k < corner_used.size(); ++k)
    if (!corner_used[k])
      audit.gained.push_back(
          {VertexFeature::Corner, static_cast<int>(k), 0.0, at(output.corners[k].vertex)});
  // A contact is also no larger than its distance to a contact it runs along (a thin wedge of a
  // wide part between them); only worked out for what is lost.
  std::vector<char> refine(input.contacts.size(), 0);
  for (size_t c = 0; c < input.contacts.size(); ++c) refine[c] = contact_lost[c];
  for (size_t k = 0; k < input.corners.size(); ++k)
    if (corner_lost[k])
      for (int c : input.corners[k].contacts) refine[c] = 1;
  std::vector<BoundingBox> boxes(input.contacts.size());
  for (size_t c = 0; c < input.contacts.size(); ++c)
    for (int v : input.contacts[c].vertices) boxes[c].extend(p[v]);
  for (size_t c = 0; c < input.contacts.size(); ++c)
    if (refine[c]) length[c] = std::min(length[c], proximity(input, static_cast<int>(c), boxes));
  for (size_t k = 0; k < input.corners.size(); ++k)
    if (corner_lost[k])
      for (int c : input.corners[k].contacts) spacing[k] = std::min(spacing[k], length[c]);

  for (size_t part = 0; part < input.parts.size(); ++part)
    if (!part_kept[part])
      audit.lost.push_back({VertexFeature::Surface, static_cast<int>(part), parts[part].width, parts[part].somewhere});
  for (size_t c = 0; c < input.contacts.size(); ++c)
    if (contact_lost[c]) {
      const std::vector<int>& line = input.contacts[c].vertices;
      audit.lost.push_back({VertexFeature::Contact, static_cast<int>(c), length[c], p[line[line.size() / 2]]});
    }
  for (size_t k = 0; k < input.corners.size(); ++k)
    if (corner_lost[k])
      audit.lost.push_back({VertexFeature::Corner, static_cast<int>(k), spacing[k], p[input.corners[k].vertex]});

  for (int r : regions_lost) {
    const Region& region = input.regions[static_cast<size_t>(r)];
    double area = 0.0;
    for (const Side& side : region.sides) area += parts[side.part].area;
    const double volume = std::abs(input.signed_volume(region.sides));
    LostRegion lost{r, area > 0.0 ? 2.0 * volume / area : 0.0, {}};
    for (const Side& side : region.sides)
      lost.places.insert(lost.places.end(), parts[side.part].places.begin(),
                         parts[side.part].places.end());
    audit.regions_lost.push_back(std::move(lost));
  }
  const auto sides = input.part_regions();
  for (const auto& [a, b] : region_contacts_lost) {
    LostRegionContact lost{a, b, 0.0, {}};
    for (size_t part = 0; part < sides.size(); ++part)
      if ((sides[part].first == a && sides[part].second == b) ||
          (sides[part].first == b && sides[part].second == a)) {
        lost.width = std::max(lost.width, parts[part].width);
        lost.places.insert(lost.places.end(), parts[part].places.begin(), parts[part].places.end());
      }
    audit.region_contacts_lost.push_back(std::move(lost));
  }
  return audit;
}

}  // namespace voroseal
