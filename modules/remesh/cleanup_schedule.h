// The clean-up's schedule: which phases (cleanup_phases.h) run, in which order, for how many
// rounds and when. Internal to the remesh module; why this order: modules/remesh/README.md.
#pragma once

#include <vector>

#include "modules/remesh/cleanup_phase.h"

namespace voroseal::cleanup {

std::vector<PhaseSpec> cleanup_schedule(const CleanupThresholds& t);

}  // namespace voroseal::cleanup
