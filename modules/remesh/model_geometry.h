// ModelGeometry: the flat, cache-friendly view of a StructuralModel that the restricted Voronoi
// diagram and the CVT energy iterate on (paper §3.1). One record per input triangle holds what
// clipping needs without chasing pointers: the three vertex positions, the unit normal, the
// density at the vertices, the surface part, and for every edge whether it is a line edge and
// of which contact. Records are stored in Morton order of their centroids so that a thread
// working on a contiguous range touches a compact piece of the model (and of the seeds).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "framework/core/types.h"
#include "framework/model/structural_model.h"

namespace voroseal {

/// One input triangle as the hot loops see it.
struct TriangleRecord {
  std::array<Vec3, 3> p;          // vertex positions (local frame)
  Vec3 normal = Vec3::Zero();     // unit normal (right-hand rule); zero for a zero-area triangle
  std::array<double, 3> density{{1.0, 1.0, 1.0}};  // density rho at the vertices
  std::array<int, 3> v{{-1, -1, -1}};  // model vertex ids
  int id = -1;                    // index of the triangle in flatten(model) order
  int part = -1;                  // surface part
  /// Contact of edge k = (v[k], v[k+1 mod 3]), or -1 when it is not a line edge.
  std::array<int, 3> edge_contact{{-1, -1, -1}};
  /// Bit k set: this triangle is the one (of all triangles sharing line edge k) that reports
  /// the contact segments on it, so every contact segment is reported exactly once.
  std::uint8_t edge_owner = 0;
  double area = 0.0;
};

class ModelGeometry {
 public:
  ModelGeometry() = default;
  /// Flattens `model` (all surface parts) into triangle records.
  /// `vertex_density`, when not empty, gives rho >= 0 at every model vertex (linear on
  /// triangles); empty means rho = 1 everywhere.
  /// \throws ModelError when the model has no triangle or zero total area;
  ///         ParameterError when vertex_density has the wrong size or a negative/non-finite value.
  explicit ModelGeometry(const StructuralModel& model, const std::vector<double>& vertex_density = {});
  /// The records `records` (ascending indices) of `whole` as a geometry of their own, in the
  /// same order, for work on a piece of the model. Every line edge of the piece is reported by
  /// one of its records. record_of() gives -1 for the triangles left out.
  static ModelGeometry piece(const ModelGeometry& whole, const std::vector<int>& records);

  const std::vector<TriangleRecord>& triangles() const { return records_; }
  /// Index into triangles() of the triangle with flatten() index `id`.
  int record_of(int id) const { return record_of_[id]; }
  const std::vector<Vec3>& vertices() const { return vertices_; }
  /// Corner id of each model vertex, -1 when the vertex is not a corner.
  const std::vector<int>& vertex_corner() const { return vertex_corner_; }
  int num_contacts() const { return num_contacts_; }
  int num_parts() const { return num_parts_; }
  bool has_density() const { return has_density_; }
  /// Sum of triangle areas.
  double area() const { return area_; }
  /// Integral of rho over the model (equals area() without density).
  double mass() const { return mass_; }
  /// Integral of sqrt(rho) over the model: the area the seeds share as if rho were 1, since a 2D
  /// CVT puts seeds at a density proportional to sqrt(rho) (equals area() without density).
  double root_mass() const { return root_mass_; }
  BoundingBox bbox() const { return bbox_; }
  /// Number of triangle edges that lie on a contact (counted once per line edge).
  int num_line_edges() const { return num_line_edges_; }

 private:
  std::vector<TriangleRecord> records_;
  std::vector<int> record_of_;
  std::vector<Vec3> vertices_;
  std::vector<int> vertex_corner_;
  int num_contacts_ = 0;
  int num_parts_ = 0;
  int num_line_edges_ = 0;
  bool has_density_ = false;
  double area_ = 0.0;
  double mass_ = 0.0;
  double root_mass_ = 0.0;
  BoundingBox bbox_;
};

/// 63-bit Morton code of x inside `box` (21 bits per axis): sorting by it gives spatial locality.
std::uint64_t morton_code(const Vec3& x, const BoundingBox& box);

}  // namespace voroseal
