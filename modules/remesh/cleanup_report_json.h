// The clean-up's phases (CleanupReport::phases) as JSON, for the remesh module's report.
#pragma once

#include <nlohmann/json.hpp>

#include "modules/remesh/cleanup_report.h"

namespace voroseal {

// One object per phase: name, rounds, edits, kept, defects and invalid before and after, seconds.
inline nlohmann::json phases_json(const std::vector<PhaseRecord>& phases) {
  nlohmann::json out = nlohmann::json::array();
  for (const PhaseRecord& p : phases)
    out.push_back({{"name", p.name},
                   {"rounds", p.rounds},
                   {"edits", p.edits},
                   {"kept", p.kept},
                   {"rounds_kept", p.rounds_kept},
                   {"defects_before", p.defects_before},
                   {"defects_after", p.defects_after},
                   {"invalid_before", p.invalid_before},
                   {"invalid_after", p.invalid_after},
                   {"seconds", p.seconds}});
  return out;
}

}  // namespace voroseal
