// Closest points on the input model: on a surface part, or on a contact line. The remesher uses
// it to put output vertices back on the surfaces and contacts they sample after moving them.
#pragma once

#include <memory>
#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

class SurfaceProjector {
 public:
  /// Builds one bounding-volume tree per surface part and the segments of every contact.
  /// The model must outlive the projector.
  explicit SurfaceProjector(const StructuralModel& model);
  ~SurfaceProjector();
  SurfaceProjector(const SurfaceProjector&) = delete;
  SurfaceProjector& operator=(const SurfaceProjector&) = delete;

  /// Closest point of surface part `part` to x (local frame).
  Vec3 on_part(int part, const Vec3& x) const;
  /// The same, searched from `near`, a point of the part close to x (where a vertex stood
  /// before it moved): only boxes closer than `near` are opened. Any `near` gives the right
  /// answer: when nothing closer than it is found, the search runs again without it.
  Vec3 on_part(int part, const Vec3& x, const Vec3& near) const;
  /// Closest point of contact `contact` to x.
  Vec3 on_contact(int contact, const Vec3& x) const;
  /// Distance from x to surface part `part`.
  double distance_to_part(int part, const Vec3& x) const { return (on_part(part, x) - x).norm(); }
  double distance_to_part(int part, const Vec3& x, const Vec3& near) const {
    return (on_part(part, x, near) - x).norm();
  }

 private:
  struct Trees;
  std::unique_ptr<Trees> trees_;
  const StructuralModel& model_;
};

}  // namespace voroseal
