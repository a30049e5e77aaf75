#include "modules/remesh/layer_sizing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nanoflann.hpp>
#include <utility>
#include <vector>

#include "framework/core/error.h"
#include "framework/geometry/point_cloud.h"
#include "framework/model/contact_wedges.h"
#include "modules/remesh/contact_arcs.h"
#include "modules/remesh/triangle_grid.h"

namespace voroseal {

namespace {

using Neighbours = std::vector<std::pair<std::uint32_t, double>>;
const nanoflann::SearchParams kUnsorted(32, 0.0, false);

// Where the thickness is measured: a surface vertex seen from one part, or the centroid of a
// triangle (input triangles are often larger than the cells a thin layer asks for).
struct Sample {
  int part = -1, vertex = -1;  // vertex -1: a centroid
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::Zero();  // the part's area-weighted normal there
};

// `cross`: (b − a) × (c − a) of every triangle (a, b, c).
std::vector<Sample> thickness_samples(const StructuralModel& model, const ModelTriangles& flat,
                                      const std::vector<Vec3>& cross) {
  std::vector<Sample> samples;
  for (size_t t = 0; t < flat.triangles.size(); ++t)
    for (int v : flat.triangles[t]) samples.push_back({flat.part[t], v, model.vertices[v], Vec3::Zero()});
  auto key = [](const Sample& s) { return std::make_pair(s.part, s.vertex); };
  std::sort(samples.begin(), samples.end(), [&](const Sample& a, const Sample& b) { return key(a) < key(b); });
  samples.erase(std::unique(samples.begin(), samples.end(),
                            [&](const Sample& a, const Sample& b) { return key(a) == key(b); }),
                samples.end());
  for (size_t t = 0; t < flat.triangles.size(); ++t)
    for (int v : flat.triangles[t]) {
      const Sample probe{flat.part[t], v, Vec3::Zero(), Vec3::Zero()};
      auto it = std::lower_bound(samples.begin(), samples.end(), probe,
                                 [&](const Sample& a, const Sample& b) { return key(a) < key(b); });
      it->normal += cross[t];
    }
  for (Sample& s : samples) s.normal.normalize();
  for (size_t t = 0; t < flat.triangles.size(); ++t) {
    const Triangle& f = flat.triangles[t];
    const Vec3 &a = model.vertices[f[0]], &b = model.vertices[f[1]], &c = model.vertices[f[2]];
    samples.push_back({flat.part[t], -1, (a + b + c) / 3.0, cross[t].normalized()});
  }
  return samples;
}

// Lowers size[v] to s + gradation·|x_v − x| for every vertex within reach of x.
void grade_from(const PointKdTree& vertices, const Vec3& x, double s, double h, double gradation,
                std::vector<double>& size, Neighbours& found) {
  const double reach = (h - s) / gradation;
  vertices.radiusSearch(x.data(), reach * reach, found, kUnsorted);
  for (const auto& item : found) size[item.first] = std::min(size[item.first], s + gradation * std::sqrt(item.second));
}

}  // namespace

LayerSizing thin_layer_sizing(const StructuralModel& model, double h, const LayerSizingOptions& options) {
  if (!(h > 0.0) || !std::isfinite(h)) throw ParameterError("remesh: the layer sizing needs a positive edge length");
  if (!(options.ratio > 0.0) || !(options.max_refinement >= 1.0) || !(options.gradation > 0.0) ||
      !(options.facing_angle_deg >= 0.0 && options.facing_angle_deg < 90.0) || !(options.pinch_angle_deg >= 0.0) ||
      !(options.corner_ratio >= 0.0 && std::isfinite(options.corner_ratio)))
    throw ParameterError("remesh: layer sizing options out of range");
  LayerSizing result;
  result.size.assign(model.vertices.size(), h);
  const ModelTriangles flat = flatten(model);
  if (flat.triangles.empty()) return result;
  const size_t nt = flat.triangles.size();
  std::vector<Vec3> cross(nt), tri_normal(nt);
  double mean_edge = 0.0;
  for (size_t t = 0; t < nt; ++t) {
    const Triangle& f = flat.triangles[t];
    const Vec3 &a = model.vertices[f[0]], &b = model.vertices[f[1]], &c = model.vertices[f[2]];
    cross[t] = (b - a).cross(c - a);
    tri_normal[t] = cross[t].normalized();  // zero on a degenerate triangle: faces nothing
    mean_edge += ((b - a).norm() + (c - b).norm() + (a - c).norm()) / (3.0 * static_cast<double>(nt));
  }
  const std::vector<Sample> samples = thickness_samples(model, flat, cross);

  // Triangles in a grid of their bounding boxes, cells about a triangle wide (input triangles
  // vary by orders of magnitude: a radius search around centroids would have to reach as far
  // as the largest one).
  const double t_max = h / options.ratio;
  TriangleGrid grid;
  grid.reset(std::max(mean_edge, 2.0 * t_max));
  for (size_t t = 0; t < nt; ++t) {
    const Triangle& f = flat.triangles[t];
    const Vec3 &a = model.vertices[f[0]], &b = model.vertices[f[1]], &c = model.vertices[f[2]];
    grid.insert(static_cast<int>(t), a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c));
  }

  // Thickness at every sample: the nearest hit of the line along its normal, either way, on a
  // triangle of another part facing it (normals within facing_angle_deg), not incident to it.
  const double cos_facing = std::cos(options.facing_angle_deg * M_PI / 180.0);
  std::vector<double> thickness(samples.size(), std::numeric_limits<double>::infinity());
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < static_cast<long>(samples.size()); ++i) {
    const Sample& s = samples[i];
    const Vec3& p = s.position;
    const Vec3 half = t_max * s.normal.cwiseAbs();  // the segment p ± t_max n, as a box
    double t = t_max;
    bool hit = false;
    grid.query(p - half, p + half, [&](int j) {
      if (flat.part[j] == s.part) return;
      const Triangle& f = flat.triangles[j];
      if (s.vertex >= 0 && (f[0] == s.vertex || f[1] == s.vertex || f[2] == s.vertex)) return;
      const Vec3& n = tri_normal[j];
      const double cosine = s.normal.dot(n);
      if (!(std::abs(cosine) >= cos_facing)) return;
      const Vec3 &a = model.vertices[f[0]], &b = model.vertices[f[1]], &c = model.vertices[f[2]];
      const double along = (a - p).dot(n) / cosine;  // p + along·normal is on the triangle's plane
      if (!(std::abs(along) < t)) return;
      const Vec3 x = p + along * s.normal;
      if ((b - a).cross(x - a).dot(n) < 0 || (c - b).cross(x - b).dot(n) < 0 || (a - c).cross(x - c).dot(n) < 0)
        return;
      t = std::abs(along);
      hit = true;
    });
    if (hit) thickness[i] = t;
  }

  const PointCloud vertex_cloud{model.vertices.data(), model.vertices.size()};
  PointKdTree vertex_tree(3, vertex_cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  vertex_tree.buildIndex();
  Neighbours found;
  const double min_size = h / options.max_refinement;
  for (size_t i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(thickness[i])) continue;
    ++result.thin_samples;
    const double s = std::clamp(options.ratio * thickness[i], min_size, h);
    grade_from(vertex_tree, samples[i].position, s, h, options.gradation, result.size, found);
  }
  // Contacts between two corners shorter than h (but not than the finest cells: those merge
  // whatever the size), refined after the tips' rule below.
  std::vector<std::pair<int, double>> short_contacts;  // contact, size along it
  const ContactArcs arcs(model);
  for (size_t c = 0; c < model.contacts.size() && options.corner_ratio > 0.0; ++c) {
    const Contact& contact = model.contacts[c];
    if (contact.vertices.size() < 2 || contact.vertices.front() == contact.vertices.back()) continue;
    const double length = arcs.length(static_cast<int>(c));
    if (!(length < h) || length < min_size) continue;
    short_contacts.emplace_back(static_cast<int>(c), std::clamp(options.corner_ratio * length, min_size, h));
  }
  result.short_contacts = static_cast<int>(short_contacts.size());
  if (!result.refines()) return result;

  // Thin contact wedges keep the size h, falling off at the gradation rate.
  std::vector<char> tip(model.vertices.size(), 0);
  for (const ContactWedge& w : thin_contact_wedges(model, options.pinch_angle_deg)) tip[w.a] = tip[w.b] = 1;
  std::vector<Vec3> tips;
  for (size_t v = 0; v < tip.size(); ++v) {
    if (!tip[v]) continue;
    tips.push_back(model.vertices[v]);
    vertex_tree.radiusSearch(model.vertices[v].data(), std::pow((h - min_size) / options.gradation, 2), found,
                             kUnsorted);
    for (const auto& item : found)
      result.size[item.first] = std::max(result.size[item.first], h - options.gradation * std::sqrt(item.second));
  }
  result.pinch_vertices = static_cast<int>(tips.size());

  // Corners closer than a cell: two corners joined by a contact shorter than the cells fall in
  // one restricted Voronoi cell and the mesh building merges them (Algorithm 3), moving the
  // surfaces' contact lines there by up to the contact's length; a horizon whose corner slid
  // up a box edge then runs down the box side a few metres from it (modelA6 at 5000 seeds: two
  // horizons' corners 215 m apart on a box edge, 1.0 deg tets). Cells as long as the contact
  // keep its corners apart.
  for (const auto& [c, s] : short_contacts)
    for (int v : model.contacts[c].vertices)
      grade_from(vertex_tree, model.vertices[v], s, h, options.gradation, result.size, found);

  // The thinnest layer away from the tips (at a tip every layer is as thin as one likes).
  const PointCloud tip_cloud{tips.data(), tips.size()};
  PointKdTree tip_tree(3, tip_cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  if (!tips.empty()) tip_tree.buildIndex();
  for (size_t i = 0; i < samples.size(); ++i) {
    if (!(thickness[i] < result.thinnest)) continue;
    if (!tips.empty()) {
      std::uint32_t nearest = 0;
      double d2 = 0.0;
      tip_tree.knnSearch(samples[i].position.data(), 1, &nearest, &d2);
      if (d2 < h * h) continue;
    }
    result.thinnest = thickness[i];
    result.thinnest_at = samples[i].position;
  }
  return result;
}

std::vector<double> density_from_sizing(const std::vector<double>& size, double h) {
  std::vector<double> rho(size.size());
  for (size_t i = 0; i < size.size(); ++i) {
    const double r = h / size[i];
    rho[i] = r * r * r * r;
  }
  return rho;
}

}  // namespace voroseal
