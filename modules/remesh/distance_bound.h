// A remesh within a distance of its input (`remesh --distance-bound D`): cells as coarse as the
// bound allows, then the remesh checked against the input and refined where it strays farther.
//
// Before: a remesh triangle is a chord of the surface patch it spans, whose circumradius is its
// edge length s over √3. If that patch lies within δ of a plane, the chord strays from it by at
// most 2δ, so the size at a point is the largest s (in steps of √2 down from h) whose patch is
// within kDistanceSizingShare · D / 2 of its best plane; along a contact, the contact's vertices
// within s / 2 and their best line. The flattest places keep h; curvature and bends get what
// their sag allows, whatever the triangles of the input (noise finer than D costs nothing).
//
// After: the two-sided distance is measured as the referee measures it (surface_distance.h);
// the places farther than D get smaller cells (refine_at_places) and the remesh is built again.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "framework/geometry/size_field.h"
#include "framework/geometry/surface_distance.h"
#include "framework/model/structural_model.h"

namespace voroseal {

/// The a priori sizes aim at this share of the bound: the seeds are not at the ideal spots and
/// the clean-up moves vertices, so the rest is margin.
constexpr double kDistanceSizingShare = 0.7;
/// Sizes go down from h by factors √2 at most this many times (h / 16 at the 8th).
constexpr int kDistanceSizingSteps = 8;
/// Samples of the sizing per edge length h along each direction at first; twice as many, level
/// after level, around the samples whose size came out under twice their spacing.
constexpr double kDistanceSamplesPerCell = 4.0;
/// Points of a patch used in its plane fit, at most (a stride over the patch beyond).
constexpr int kDistancePatchPoints = 512;
/// Rounds of refinement after the check, at most.
constexpr int kDistanceRounds = 4;
/// Cells around a place that strays d > 0.9 D: the size there times 0.9 D / d (a cut crease or
/// a lost feature strays as far as the cells are large; a sag shrinks faster), within these
/// factors. (The square converged no faster on geogen's layercake: each rebuild strays anew.)
constexpr double kDistanceShrinkMin = 0.25, kDistanceShrinkMax = 0.7;
/// Places are refined where the remesh strays farther than this share of the bound: the check's
/// samples are not the referee's, and a place just under the bound may be just over it there.
constexpr double kDistanceRefineShare = 0.9;
/// Sample points per model for the check (the referee's default).
constexpr size_t kDistanceSamples = 200000;

/// `text` is a length in the model's units or a percentage of its bounding-box diagonal
/// ("0.1%"). \throws ParameterError when it is not a positive number.
double parse_distance_bound(const std::string& text, const StructuralModel& model);

struct DistanceSizing {
  std::shared_ptr<const SizeField> field;  // null when no sample needs less than h
  int samples = 0;                         // where the size was measured
  int finer = 0;                           // samples given a size below h
  double smallest = 0.0;                   // smallest size given (h when none)
};

/// The sizes at which a remesh of edge length at most `h` stays within `bound` of `model`.
/// \pre bound > 0, h > 0
DistanceSizing distance_sizing(const StructuralModel& model, double bound, double h, int threads);

struct DistanceCheck {
  HausdorffDistance distance;  // a: the input, b: the remesh
  /// Points of the input (local frame) where either surface is farther than `refine_above`
  /// from the other, at most one per cell of a grid of `spacing`, and the largest such distance
  /// in each cell.
  std::vector<Vec3> places;
  std::vector<double> place_distance;
  long samples_over = 0;  // samples of both sides farther than the bound itself
};

/// Distances of remeshes to one input: the input's samples and triangle tree are made once for
/// all the checks of a remesh and its refinement rounds.
class InputDistance {
 public:
  /// `samples` points on each side (sample_surface, seed 1). `input` must outlive this.
  explicit InputDistance(const StructuralModel& input, size_t samples = kDistanceSamples);

  /// How far `remesh` (its own frame) strays from the input against `bound`.
  DistanceCheck check(const StructuralModel& remesh, double bound, double refine_above,
                      double spacing) const;

 private:
  const StructuralModel& input_;
  size_t samples_;
  ModelTriangles triangles_;
  std::vector<Vec3> input_samples_;
  TriangleSetDistance to_input_;
};

}  // namespace voroseal
