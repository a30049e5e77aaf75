// clean_up(): the steps of the clean-up (cleanup_steps.h) in order, and why in that order.
#include "modules/remesh/mesh_cleanup.h"

#include "modules/remesh/cleanup_steps.h"

namespace voroseal {

using namespace cleanup;

CleanupReport clean_up(RemeshedSurface& surface, const StructuralModel& input, const SurfaceProjector& projector,
                       const CleanupOptions& options) {
  CleanupReport report;
  Editor e(surface, input);
  e.set_projector(&projector);
  const ContactArcs arcs(input);
  e.set_fidelity(options.fidelity_tolerance, &arcs);
  // Folds along contacts and needles first: they are most of what the mesh building leaves
  // invalid, and d_min merges need valid surroundings to be accepted.
  report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
  report.valence3_removed += remove_valence3(e);
  report.valence3_raised += raise_valence3_on_contacts(e);
  merge_close_features(e, projector, options.min_feature, report);
  report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
  report.flips += flip_edges(e, options.flip_flatness_deg);
  for (int i = 0; i < options.smoothing_iterations; ++i) {
    smooth(e, projector);
    report.flips += flip_edges(e, options.flip_flatness_deg);
    ++report.smoothing_passes;
  }
  report.valence3_removed += remove_valence3(e);
  report.valence3_raised += raise_valence3_on_contacts(e);
  // Smoothing brings some features closer than d_min, and the first merges open the way to others.
  merge_close_features(e, projector, options.min_feature, report);
  report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
  report.flips += flip_edges(e, options.flip_flatness_deg);
  smooth(e, projector);
  if (options.fidelity_tolerance > 0.0) {
    for (int round = 0; round < 3; ++round) {
      const int splits = refine_for_fidelity(e, projector, options.fidelity_tolerance) +
                         refine_toward_input(e, options.fidelity_tolerance);
      report.fidelity_splits += splits;
      if (splits == 0) break;
      report.flips += flip_edges(e, options.flip_flatness_deg);
      smooth(e, projector);
      report.flips += flip_edges(e, options.flip_flatness_deg);
    }
    merge_close_features(e, projector, options.min_feature, report);
    report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
    report.flips += flip_edges(e, options.flip_flatness_deg);
  }
  auto angle_passes = [&]() {
    for (int i = 0; i < options.angle_passes; ++i) {
      const int moved = optimize_angles(e, projector, 30.0);
      if (moved == 0) break;
      report.flips += flip_edges(e, options.flip_flatness_deg);
    }
  };
  angle_passes();
  // What the angle passes could not fix, an edge collapse sometimes does; then they go again.
  int collapsed = 0;
  for (int round = 0; round < options.sharp_collapse_rounds; ++round) {
    const int n = collapse_sharp(e, projector, 30.0);
    if (n == 0) break;
    collapsed += n;
    report.flips += flip_edges(e, options.flip_flatness_deg);
  }
  report.sharp_collapses += collapsed;
  if (collapsed > 0) angle_passes();
  // Moves counted in sharp triangles, where the angle passes left some; again after the quality
  // passes, whose moves change the rings.
  report.sharp_moves +=
      reduce_sharp_triangles(e, projector, options.sharp_passes, options.flip_flatness_deg, report.flips);
  // Last, as the angle passes trade shape for the smallest angle: each vertex goes where its
  // triangles are best shaped, no triangle getting sharper than 30 degrees.
  auto quality_passes = [&]() {
    for (int i = 0; i < options.quality_passes; ++i) {
      const int moved = optimize_quality(e, projector, options.quality_below);
      report.quality_moves += moved;
      report.flips += flip_edges(e, options.flip_flatness_deg);
      if (moved == 0) break;
    }
    report.sharp_moves +=
        reduce_sharp_triangles(e, projector, options.sharp_passes, options.flip_flatness_deg, report.flips);
  };
  quality_passes();
  if (options.zip_wedge_deg > 0.0) {
    const PinchZips zips = zip_pinch_outs(e, options.min_feature, options.zip_wedge_deg);
    report.pinch_zips = zips.steps;
    report.pinch_rungs = zips.rungs;
    report.pinch_pockets = zips.pockets;
    if (zips.edits() > 0) report.flips += flip_edges(e, options.flip_flatness_deg);
    // The steps leave stretched triangles next to the fronts (the zipped vertices are pinned,
    // their neighbours are not): the angle and quality passes again (modelA6 at 3000-8000 seeds,
    // 9 runs: 5 -> 7 reach a 5 deg tet mesh; at 12,000 seeds 4.9 -> 6.6 deg).
    if (zips.edits() > 0) {
      angle_passes();
      quality_passes();
    }
  }
  for (int i = 0; options.wedge_dihedral_deg > 0.0 && i < 8; ++i) {
    // Up to half of d_min off the surfaces: where two surfaces closer than d_min may merge,
    // opening their wedge that much stays within the same tolerance.
    const int moved = open_wedge_tets(e, projector, options.wedge_dihedral_deg, 0.5 * options.min_feature);
    report.wedge_moves += moved;
    if (moved == 0) break;
  }
  if (options.resolve_intersections) repair(e, projector, options, report);
  // Last, as the repair may need to move a tip.
  report.tips_joined = join_close_tips(e, options.min_feature, options.wedge_dihedral_deg, report);
  if (report.tips_joined > 0) report.flips += flip_edges(e, options.flip_flatness_deg);
  // The edits since (the repairs included) may have closed new fans of three; flips that make
  // nothing worse.
  report.valence3_raised += raise_valence3_on_contacts(e);
  e.finish();
  return report;
}

void RemeshedSurface::remove_triangles(const std::vector<char>& dead) {
  size_t kept = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (t < dead.size() && dead[t]) continue;
    triangles[kept] = triangles[t];
    triangle_part[kept] = triangle_part[t];
    ++kept;
  }
  triangles.resize(kept);
  triangle_part.resize(kept);
  remove_unused_vertices();
}

void RemeshedSurface::remove_unused_vertices() {
  std::vector<int> index(vertices.size(), -1);
  int n = 0;
  for (const Triangle& t : triangles)
    for (int v : t)
      if (index[v] < 0) index[v] = n++;
  std::vector<Vec3> new_vertices(n);
  std::vector<VertexFeature> new_features(n);
  for (size_t v = 0; v < vertices.size(); ++v)
    if (index[v] >= 0) {
      new_vertices[index[v]] = vertices[v];
      new_features[index[v]] = features[v];
    }
  for (Triangle& t : triangles)
    for (int& v : t) v = index[v];
  vertices = std::move(new_vertices);
  features = std::move(new_features);
}

}  // namespace voroseal
