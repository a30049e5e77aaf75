// The quality table of a structural model (seed paper, Table 2): sizes, feature counts,
// triangle shape (min angle, % of triangles with an angle < 30°, Q = 6S/(√3·h_max·p)), area,
// bounding-box diagonal, and the fidelity to a reference model (two-sided Hausdorff distance in
// % of the reference's bbox diagonal). Same definitions as the referee meshreport.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/geometry/surface_distance.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/model/structural_model.h"

namespace voroseal {

struct ModelStatistics {
  std::string model;
  long vertices = 0;  // model vertices used by a triangle
  long triangles = 0;
  int surfaces = 0, contacts = 0, corners = 0, regions = 0, interfaces = 0;
  QualitySummary quality;  // angles, Q, area, over all triangles (30° threshold)
  double bbox_diagonal = 0;
};

/// Measures the model (quality in parallel).
ModelStatistics measure_model(const StructuralModel& model);

/// Fidelity of a model to a reference (the input of a remesher).
struct FidelityStatistics {
  HausdorffDistance distance;     // model -> reference is a_to_b; reference -> model is b_to_a
  double reference_diagonal = 0;  // bbox diagonal of the reference
  double hausdorff_pct = 0;       // distance.hausdorff in % of reference_diagonal
  double area_ratio = 0;          // model area / reference area
  double seconds = 0;
};

/// Two-sided Hausdorff distance between the surfaces of `model` and `reference`, each sampled
/// with `samples` points (vertices, edge midpoints, then area-weighted random points from
/// `seed`), in the reference's frame.
/// \throws ModelError when either model has no triangle.
FidelityStatistics hausdorff(const StructuralModel& model, const StructuralModel& reference, size_t samples = 200000,
                             uint64_t seed = 1);

/// One JSON object with the keys scripts read: vertices, triangles, surfaces, contacts,
/// corners, regions, min_angle_deg, pct_triangles_angle_below_30, avg_quality, min_quality,
/// area, bbox_diagonal; with a fidelity, hausdorff_pct and the details (plus extra keys).
nlohmann::json to_json(const ModelStatistics& statistics, const FidelityStatistics* fidelity = nullptr,
                       const ModelStatistics* reference = nullptr);

/// A compact Table-2 style table: one row for the model, one for the reference when given.
std::string to_table(const ModelStatistics& statistics, const FidelityStatistics* fidelity = nullptr,
                     const ModelStatistics* reference = nullptr);

}  // namespace voroseal
