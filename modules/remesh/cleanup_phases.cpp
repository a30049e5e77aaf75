#include "modules/remesh/cleanup_phases.h"

#include <cmath>

#include "modules/remesh/cleanup_steps.h"

namespace voroseal::cleanup {

PhaseCounts topology(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  CleanupCounts& n = r.counts;
  n.needles_collapsed = collapse_needles(e, c.thresholds.needle_angle_deg);
  n.valence3_removed = remove_valence3(e);
  n.valence3_raised = raise_valence3_on_contacts(e);
  r.progress = n.needles_collapsed + n.valence3_removed + n.valence3_raised;
  return r;
}

PhaseCounts valence3(Editor& e, const CleanupContext&) {
  PhaseCounts r;
  r.counts.valence3_removed = remove_valence3(e);
  r.counts.valence3_raised = raise_valence3_on_contacts(e);
  r.progress = r.counts.valence3_removed + r.counts.valence3_raised;
  return r;
}

PhaseCounts merges(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  CleanupCounts& n = r.counts;
  merge_close_features(e, c.projector, c.options.min_feature, n);
  n.needles_collapsed = collapse_needles(e, c.thresholds.needle_angle_deg);
  n.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  r.progress = static_cast<int>(n.merges.size()) + n.needles_collapsed;
  return r;
}

PhaseCounts smoothing(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  r.progress = r.counts.smoothing_moves =
      smooth(e, c.projector, nullptr, c.options.target_size.get());
  r.counts.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  r.counts.smoothing_passes = 1;
  return r;
}

PhaseCounts relaxation(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  r.progress = r.counts.smoothing_moves =
      smooth(e, c.projector, nullptr, c.options.target_size.get());
  return r;
}

PhaseCounts angles(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  r.progress = r.counts.angle_moves = optimize_angles(e, c.projector, c.thresholds.sharp_deg);
  if (r.progress > 0) r.counts.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  return r;
}

PhaseCounts sharp_collapses(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  r.progress = r.counts.sharp_collapses = collapse_sharp(e, c.projector, c.thresholds.sharp_deg);
  if (r.progress > 0) r.counts.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  return r;
}

PhaseCounts contact_spacing(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  const double shorter_than = c.thresholds.contact_short_edge * e.mean_edge();
  r.progress = r.counts.contact_collapses = space_contacts(e, c.projector, shorter_than);
  if (r.progress > 0) r.counts.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  return r;
}

PhaseCounts sharp_moves(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  r.progress = r.counts.sharp_moves =
      reduce_sharp_triangles(e, c.projector, 1, c.thresholds.flip_flatness_deg, r.counts.flips);
  return r;
}

PhaseCounts quality(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  r.progress = r.counts.quality_moves =
      optimize_quality(e, c.projector, c.thresholds.quality_below);
  r.counts.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  return r;
}

PhaseCounts fidelity(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  const double tolerance = c.options.fidelity_tolerance;
  int alive = 0;
  for (size_t t = 0; t < e.mesh().triangles.size(); ++t) alive += e.alive(static_cast<int>(t));
  const int budget = static_cast<int>(std::ceil(c.thresholds.fidelity_split_share * alive));
  const int splits = refine_for_fidelity(e, c.projector, tolerance, budget);
  r.progress = r.counts.fidelity_splits =
      splits + refine_toward_input(e, tolerance, budget - splits);
  if (r.progress == 0) return r;
  r.counts.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  smooth(e, c.projector, nullptr, c.options.target_size.get());
  r.counts.flips += flip_edges(e, c.thresholds.flip_flatness_deg);
  return r;
}

PhaseCounts grading(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  r.progress = r.counts.grading_splits =
      grade_neighbours(e, c.projector, c.thresholds.max_neighbour_ratio);
  if (r.progress > 0) r.counts.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  return r;
}

PhaseCounts pinch_out_zip(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  const PinchZips zips = zip_pinch_outs(e, c.options.min_feature, c.options.zip_wedge_deg);
  r.counts.pinch_zips = zips.steps;
  r.counts.pinch_rungs = zips.rungs;
  r.counts.pinch_pockets = zips.pockets;
  r.progress = zips.edits();
  if (r.progress > 0) r.counts.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  return r;
}

PhaseCounts wedges(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  const double lift = c.thresholds.wedge_lift * c.options.min_feature;
  r.progress = r.counts.wedge_moves =
      open_wedge_tets(e, c.projector, c.options.wedge_dihedral_deg, lift);
  return r;
}

PhaseCounts final_repair(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  repair(e, c.projector, c.thresholds, r.counts);
  return r;
}

PhaseCounts tips(Editor& e, const CleanupContext& c) {
  PhaseCounts r;
  CleanupCounts& n = r.counts;
  n.tips_joined = join_close_tips(e, c.options.min_feature, c.options.wedge_dihedral_deg, n);
  if (n.tips_joined > 0) n.flips = flip_edges(e, c.thresholds.flip_flatness_deg);
  // Flips that make nothing worse.
  n.valence3_raised = raise_valence3_on_contacts(e);
  r.progress = n.tips_joined + n.valence3_raised;
  return r;
}

}  // namespace voroseal::cleanup
