#include "modules/remesh/cleanup_report.h"

namespace voroseal {

int CleanupCounts::edits() const {
  return valence3_removed + valence3_raised + needles_collapsed + sharp_collapses +
         contact_collapses + angle_moves + quality_moves + sharp_moves + wedge_moves + tips_joined +
         pinch_zips + pinch_rungs + pinch_pockets + flips + smoothing_moves + coincident_removed +
         fidelity_splits + grading_splits + static_cast<int>(merges.size());
}

void CleanupCounts::add(const CleanupCounts& o) {
  valence3_removed += o.valence3_removed;
  valence3_raised += o.valence3_raised;
  needles_collapsed += o.needles_collapsed;
  sharp_collapses += o.sharp_collapses;
  contact_collapses += o.contact_collapses;
  angle_moves += o.angle_moves;
  quality_moves += o.quality_moves;
  sharp_moves += o.sharp_moves;
  wedge_moves += o.wedge_moves;
  tips_joined += o.tips_joined;
  pinch_zips += o.pinch_zips;
  pinch_rungs += o.pinch_rungs;
  pinch_pockets += o.pinch_pockets;
  flips += o.flips;
  smoothing_passes += o.smoothing_passes;
  smoothing_moves += o.smoothing_moves;
  coincident_removed += o.coincident_removed;
  intersections_found += o.intersections_found;
  fidelity_splits += o.fidelity_splits;
  grading_splits += o.grading_splits;
  merges.insert(merges.end(), o.merges.begin(), o.merges.end());
}

}  // namespace voroseal
