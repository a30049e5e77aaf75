// Validity of a structural model before gridding (RINGMesh's geomodel validity checks, plus
// region orientation): is it sealed, conformal, free of intersections and of degenerate
// elements, and are its regions consistently signed?
//
// Checks, in the order they are reported (E: error, makes the model invalid; W: warning, does
// not):
//  E structure                  indices in range; part mesh points equal their model vertices
//  E boundary_incidence         part <-> contact, contact <-> corner, interface <-> part lists
//                               agree; every side of every part belongs to exactly one region
//                               (the universe included)
//  E finite_extension           at least one bounded region; the model boundary (parts with one
//                               side on the universe) is closed and one connected component
//  E free_borders               free border edges (one triangle) are fault tips inside one
//                               bounded region, not holes between regions or towards the universe
//  E contact_conformity         contacts are chains of triangle edges with the incidence and
//                               surface parts they claim, ending at their corners; no edge is on
//                               two contacts
//  E border_edges_off_contacts  free border edges on no contact
//  E non_manifold_edges_off_contacts  edges with 3+ triangles, or between two parts, on no contact
//  E region_orientation         each region's signed sides form a closed, consistently oriented
//                               surface; its signed volume is -V (bounded) or +V (universe);
//                               volumes add up
//  E surface_orientation        the triangles of a surface part could not be oriented alike
//  E cracks                     colocated duplicated vertices inside one surface that welding hid
//                               (BuildReport: crack vertices and sewn edges; not searched in a
//                               group that holds several surfaces)
//  E colocated_vertices         distinct model vertices closer than the welding tolerance
//  E degenerate_triangles       collinear triangles (exact predicate): no normal, no orientation
//  W near_degenerate_triangles  area < degenerate_area_relative * diag^2 but not collinear: legal
//                               (orientation and intersection tests are exact) but useless for
//                               meshing; a remesher removes them. modelA2.ml has one (6.6e-5 m²,
//                               box_model_3/36): a warning, so that the model stays an input.
//  E short_edges                edges shorter than short_edge_relative * diag
//  E self_intersections         triangle pairs intersecting beyond shared edges/vertices (exact
//                               predicates; touching counts)
//  W small_angles               triangles with an angle < min_angle_warning_deg (needles): legal
//                               but bad for meshing; a remesher removes them
//  W thin_wedges                contact edges where two surfaces meet at less than
//                               thin_wedge_warning_deg inside a region (pinch-outs): any tet
//                               mesh keeping the surfaces has a dihedral angle that small there
//  W thin_border_gaps           free borders leaving a surface at less than
//                               thin_wedge_warning_deg past the corner where they meet (a fault
//                               tip running on just off another surface): tets across the gap
//                               are flat unless the surfaces are meshed finer there
//                               (border_gaps.h)
//  W split_vertices             vertices where a surface touches itself, split in its mesh
//  W disconnected_surfaces      surface parts in several pieces
//  W input_repairs              triangles the builder dropped (degenerate, duplicated) or flipped
//                               (flips only count where region sides come from the file)
//  W unused_vertices            model vertices on no triangle
//
// Locations in the report are file coordinates (local + model.frame.origin).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

enum class Severity { Error, Warning };
const char* to_string(Severity severity);

struct CheckOptions {
  /// Edges shorter than this times the bbox diagonal are errors (the welding tolerance).
  double short_edge_relative = 1e-7;
  /// Triangles with less area than this times diag^2 are near-degenerate (meshreport's threshold).
  double degenerate_area_relative = 1e-12;
  /// Triangles with an angle below this (degrees) are reported as warnings.
  double min_angle_warning_deg = 1.0;
  /// Contact wedges thinner than this (degrees) inside a region are reported as warnings.
  double thin_wedge_warning_deg = 5.0;
  /// Distinct vertices closer than this times the diagonal are colocated (welding tolerance).
  double colocated_relative = 1e-7;
  /// Relative tolerance on "region volumes add up".
  double volume_tolerance = 1e-6;
  /// Run the (most expensive) self-intersection test.
  bool intersections = true;
  /// Examples kept per check.
  int max_examples = 10;
};

/// One place where a check failed.
struct CheckExample {
  std::string what;                   // e.g. "edge 12-57", "triangle 301 of KOBE/0"
  Vec3 location = Vec3::Zero();       // file coordinates
  std::vector<std::string> surfaces;  // names of the surface parts involved
};

/// The outcome of one check: passed when count == 0.
struct CheckEntry {
  std::string name;
  Severity severity = Severity::Error;
  long count = 0;
  std::string message;  // what was found (or what was verified, when passed)
  std::vector<CheckExample> examples;
  nlohmann::json details = nlohmann::json::object();  // check-specific numbers
  double seconds = 0;                                 // time of this check
  bool passed() const { return count == 0; }
};

struct ValidityReport {
  std::string model;
  int vertices = 0, triangles = 0, surfaces = 0, contacts = 0, corners = 0, regions = 0;
  std::vector<CheckEntry> checks;  // every check run, in the order of the list above
  double seconds = 0;              // time of check_model()
  double prepare_seconds = 0;      // flattening and edge tables shared by the checks
  double intersection_seconds = 0;

  bool valid() const;  // no failed error check
  int errors() const;  // failed checks of severity Error
  int warnings() const;
  const CheckEntry* find(const std::string& name) const;  // nullptr when not run
};

/// Runs every check on the model. Never throws on a broken model: inconsistencies are findings.
/// \throws ParameterError on negative thresholds.
ValidityReport check_model(const StructuralModel& model, const CheckOptions& options = {});

/// {"model", "valid", "errors", "warnings", "counts": {...}, "checks": [{"name", "severity",
///  "count", "passed", "message", "details", "examples": [{"what", "location": [x,y,z],
///  "surfaces"}]}],
///  "timing_s": {...}}
nlohmann::json to_json(const ValidityReport& report);

/// A human report: one line per check, examples of the failed ones, the verdict.
std::string to_text(const ValidityReport& report);

}  // namespace voroseal
