#include "modules/remesh/model_geometry.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>

#include "framework/core/edge_key.h"
#include "framework/core/error.h"

namespace voroseal {

namespace {

std::uint64_t spread_bits(std::uint64_t x) {
  // Inserts two zero bits between consecutive bits of the low 21 bits of x.
  x &= 0x1fffffULL;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// ∫√ρ over a triangle: the edge-midpoint rule (exact for quadratics) on the square root of the
// linear density.
double root_mass_of(const TriangleRecord& rec) {
  double root = 0.0;
  for (int k = 0; k < 3; ++k) root += std::sqrt(0.5 * (rec.density[k] + rec.density[(k + 1) % 3]));
  return rec.area * root / 3.0;
}

}  // namespace

std::uint64_t morton_code(const Vec3& x, const BoundingBox& box) {
  const Vec3 extent = (box.max - box.min).cwiseMax(Vec3::Constant(1e-300));
  std::uint64_t code = 0;
  for (int k = 0; k < 3; ++k) {
    double u = (x[k] - box.min[k]) / extent[k];
    u = std::min(std::max(u, 0.0), 1.0);
    const auto q = static_cast<std::uint64_t>(u * 2097151.0);
    code |= spread_bits(q) << k;
  }
  return code;
}

ModelGeometry::ModelGeometry(const StructuralModel& model, const std::vector<double>& vertex_density) {
  const ModelTriangles flat = flatten(model);
  const int nt = static_cast<int>(flat.triangles.size());
  if (nt == 0) throw ModelError("remesh: the model has no triangle");
  vertices_ = model.vertices;
  num_parts_ = static_cast<int>(model.parts.size());
  num_contacts_ = static_cast<int>(model.contacts.size());
  has_density_ = !vertex_density.empty();
  if (has_density_) {
    if (vertex_density.size() != vertices_.size())
      throw ParameterError("remesh: the density has " + std::to_string(vertex_density.size()) +
                           " values for " + std::to_string(vertices_.size()) + " model vertices");
    for (double r : vertex_density)
      if (!(r >= 0.0) || !std::isfinite(r)) throw ParameterError("remesh: the density must be finite and >= 0");
  }

  vertex_corner_.assign(vertices_.size(), -1);
  for (size_t c = 0; c < model.corners.size(); ++c) vertex_corner_[model.corners[c].vertex] = static_cast<int>(c);

  // Line edges of the model: consecutive vertices of every contact.
  std::unordered_map<std::uint64_t, int> line_contact;
  for (size_t c = 0; c < model.contacts.size(); ++c) {
    const std::vector<int>& cv = model.contacts[c].vertices;
    for (size_t k = 0; k + 1 < cv.size(); ++k) line_contact.emplace(edge_key(cv[k], cv[k + 1]), static_cast<int>(c));
  }

  for (const Vec3& x : vertices_) bbox_.extend(x);

  // Morton order of the triangle centroids.
  std::vector<std::uint64_t> code(nt);
  for (int t = 0; t < nt; ++t) {
    const Triangle& f = flat.triangles[t];
    code[t] = morton_code((vertices_[f[0]] + vertices_[f[1]] + vertices_[f[2]]) / 3.0, bbox_);
  }
  std::vector<int> order(nt);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return code[a] < code[b]; });

  records_.resize(nt);
  record_of_.resize(nt);
  std::unordered_map<std::uint64_t, int> owner;  // line edge -> record reporting it
  for (int r = 0; r < nt; ++r) {
    const int t = order[r];
    const Triangle& f = flat.triangles[t];
    TriangleRecord& rec = records_[r];
    rec.id = t;
    rec.part = flat.part[t];
    record_of_[t] = r;
    for (int k = 0; k < 3; ++k) {
      rec.v[k] = f[k];
      rec.p[k] = vertices_[f[k]];
      rec.density[k] = has_density_ ? vertex_density[f[k]] : 1.0;
    }
    const Vec3 n = (rec.p[1] - rec.p[0]).cross(rec.p[2] - rec.p[0]);
    const double len = n.norm();
    rec.area = 0.5 * len;
    rec.normal = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
    area_ += rec.area;
    mass_ += rec.area * (rec.density[0] + rec.density[1] + rec.density[2]) / 3.0;
    root_mass_ += root_mass_of(rec);
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t key = edge_key(f[k], f[(k + 1) % 3]);
      const auto it = line_contact.find(key);
      if (it == line_contact.end()) continue;
      rec.edge_contact[k] = it->second;
      if (owner.emplace(key, r).second) {
        rec.edge_owner |= static_cast<std::uint8_t>(1u << k);
        ++num_line_edges_;
      }
    }
  }
  if (!(area_ > 0.0)) throw ModelError("remesh: the model has zero area");
  if (has_density_ && !(mass_ > 0.0)) throw ParameterError("remesh: the density is zero everywhere");
  if (!has_density_) root_mass_ = area_;  // the same bits as the area (edge lengths derive from it)
}

ModelGeometry ModelGeometry::piece(const ModelGeometry& whole, const std::vector<int>& records) {
  ModelGeometry g;
  g.vertices_ = whole.vertices_;
  g.vertex_corner_ = whole.vertex_corner_;
  g.num_contacts_ = whole.num_contacts_;
  g.num_parts_ = whole.num_parts_;
  g.has_density_ = whole.has_density_;
  g.records_.reserve(records.size());
  g.record_of_.assign(whole.record_of_.size(), -1);
  for (int r : records) {
    g.record_of_[whole.records_[r].id] = static_cast<int>(g.records_.size());
    g.records_.push_back(whole.records_[r]);
  }
  // A line edge whose reporting record was left out is reported by the first record kept.
  std::unordered_map<std::uint64_t, bool> reported;  // line edge -> reported in the piece
  for (const TriangleRecord& rec : g.records_)
    for (int k = 0; k < 3; ++k)
      if (rec.edge_contact[k] >= 0) {
        bool& r = reported[edge_key(rec.v[k], rec.v[(k + 1) % 3])];
        r = r || ((rec.edge_owner >> k) & 1u) != 0;
      }
  for (TriangleRecord& rec : g.records_) {
    for (int k = 0; k < 3; ++k) {
      if (rec.edge_contact[k] < 0 || ((rec.edge_owner >> k) & 1u) != 0) continue;
      bool& r = reported[edge_key(rec.v[k], rec.v[(k + 1) % 3])];
      if (r) continue;
      r = true;
      rec.edge_owner |= static_cast<std::uint8_t>(1u << k);
    }
    for (int k = 0; k < 3; ++k) {
      if (((rec.edge_owner >> k) & 1u) != 0) ++g.num_line_edges_;
      g.bbox_.extend(rec.p[k]);
    }
    g.area_ += rec.area;
    g.mass_ += rec.area * (rec.density[0] + rec.density[1] + rec.density[2]) / 3.0;
    g.root_mass_ += root_mass_of(rec);
  }
  if (!(g.area_ > 0.0)) throw ModelError("remesh: the piece of the model has zero area");
  if (!g.has_density_) g.root_mass_ = g.area_;
  return g;
}

}  // namespace voroseal
