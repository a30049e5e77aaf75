// What the verdict on a remesh adds to `voroseal check`'s: defects that only a comparison with
// the input shows. Each is an error check with its places, which the repair rounds refine.
#pragma once

#include <vector>

#include "framework/model/structural_model.h"
#include "modules/check/model_validity.h"
#include "modules/remesh/remesh.h"

namespace voroseal {

/// Free borders of `output` on parts whose input part has none: holes the remesh made, even
/// where `check` would take them for fault tips (an input sealed there says they are not).
CheckEntry holes_made(const StructuralModel& input, const StructuralModel& output,
                      const std::vector<int>& input_part_of_output, int max_places);

/// Output regions that are no input region: pockets closed between surfaces that lie closer
/// than a cell. A defect the refinement removes, never an outcome (unlike a merge).
CheckEntry no_region_gained(const StructuralModel& input, const TopologyReport& topology,
                            int max_places);

/// With --keep-topology the user asked for every input feature: an input surface part, contact,
/// corner, region or pair of touching regions without its counterpart is a defect.
CheckEntry topology_kept(const StructuralModel& input, const TopologyReport& topology,
                         int max_places);

/// "surface", "contact" or "corner": the report's and the log's name of a feature's kind.
const char* feature_kind(VertexFeature::Kind kind);

}  // namespace voroseal
