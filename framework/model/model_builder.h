// Building a StructuralModel from triangulated surfaces (paper §1.1 "Input"; design.md).
#pragma once

#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"

namespace voroseal {

/// Where a corner is placed on contact lines.
enum class CornerRule {
  /// RINGMesh / GOCAD: a vertex is a corner when its line degree is not 2, when the set of
  /// surface parts incident to it differs from that of its line edges (a part touching the
  /// line only at that vertex), and one corner is put on every closed contact.
  Incidence,
  /// meshreport: line degree not 2, or two line edges with different sets of incident parts;
  /// closed contacts have no corner.
  Signature,
};

struct BuildOptions {
  /// Vertices closer than this, relative to the bbox diagonal, are welded.
  double weld_tolerance = 1e-7;
  /// Edges where two triangles of one group fold more than this (degrees) separate surface
  /// parts. 0 disables it. Needed for soups where box sides share a group.
  double feature_angle_deg = 0.0;
  CornerRule corner_rule = CornerRule::Incidence;
  /// Infer regions by radial sorting even when the soup lists them (used to cross-check).
  bool ignore_explicit_regions = false;
};

/// Builds the model: welds vertices, finds line edges, surface parts, contacts, corners and
/// regions (explicit when the soup has them, else radial sorting of triangles around line
/// edges). Moves coordinates to a local frame.
/// \throws ModelError when the surfaces cannot form a model (e.g. a non-orientable part).
StructuralModel build_model(const SurfaceSoup& soup, const BuildOptions& options = {});

/// The inverse view: one group per surface part, file coordinates, for writers.
SurfaceSoup to_soup(const StructuralModel& model);

/// The soup group of surface part `part`: its name and its interface's name, kind and feature.
SurfaceGroup group_of_part(const StructuralModel& model, int part);

}  // namespace voroseal
