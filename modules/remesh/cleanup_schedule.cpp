#include "modules/remesh/cleanup_schedule.h"

#include "modules/remesh/cleanup_phases.h"

namespace voroseal::cleanup {

namespace {

// When a phase runs.
bool always(const CleanupContext&) { return true; }
bool with_tolerance(const CleanupContext& c) { return c.options.fidelity_tolerance > 0.0; }
bool after_collapses(const CleanupContext& c) { return c.so_far.sharp_collapses > 0; }
bool with_zip(const CleanupContext& c) { return c.options.zip_wedge_deg > 0.0; }
bool after_zip(const CleanupContext& c) { return c.so_far.pinch_zips + c.so_far.pinch_rungs > 0; }
bool with_wedges(const CleanupContext& c) { return c.options.wedge_dihedral_deg > 0.0; }
bool with_repair(const CleanupContext& c) { return c.options.resolve_intersections; }
// Sizes asked for by the user (CleanupOptions::grade).
bool graded(const CleanupContext& c) { return c.options.grade; }

}  // namespace

std::vector<PhaseSpec> cleanup_schedule(const CleanupThresholds& t) {
  constexpr PhaseCheck kButFolds = PhaseCheck::InvalidDefects;
  // clang-format off
  return {
      // name                     round            rounds                   enabled when
      {"topology",                topology,        t.topology_rounds,       always},
      {"merges",                  merges,          t.merge_rounds,          always},
      {"shape: smoothing",        smoothing,       t.smoothing_iterations,  always},
      {"topology: valence 3",     valence3,        t.topology_rounds,       always},
      {"merges",                  merges,          t.merge_rounds,          always},
      {"shape: relaxation",       relaxation,      1,                       always},
      {"fidelity",                fidelity,        t.fidelity_rounds,       with_tolerance},
      {"merges",                  merges,          t.merge_rounds,          with_tolerance},
      {"shape: contact spacing",  contact_spacing, t.contact_spacing_rounds, always},
      {"shape: angles",           angles,          t.angle_passes,          always},
      {"shape: sharp collapses",  sharp_collapses, t.sharp_collapse_rounds, always},
      {"shape: angles",           angles,          t.angle_passes,          after_collapses},
      {"shape: sharp moves",      sharp_moves,     t.sharp_passes,          always},
      {"shape: grading",          grading,         t.grading_rounds,        graded},
      {"shape: quality",          quality,         t.quality_passes,        always},
      {"shape: sharp moves",      sharp_moves,     t.sharp_passes,          always},
      {"volume: pinch-out zip",   pinch_out_zip,   1,                       with_zip, kButFolds},
      {"shape: angles",           angles,          t.angle_passes,          after_zip},
      {"shape: quality",          quality,         t.quality_passes,        after_zip},
      {"shape: sharp moves",      sharp_moves,     t.sharp_passes,          after_zip},
      {"volume: wedges",          wedges,          t.wedge_rounds,          with_wedges},
      {"shape: grading",          grading,         t.grading_rounds,        graded},
      {"final: repair",           final_repair,    1,                       with_repair},
      {"final: tips",             tips,            1,                       always},
  };
  // clang-format on
}

}  // namespace voroseal::cleanup
