// Splitting a study's runs over machines: shard I of N (1 <= I <= N) takes the runs whose
// number, counted from 1 as in the summary, is I, I + N, I + 2N, ... Dealing the runs out in
// turn spreads the models and the resolutions of a sweep over the shards, and the same study
// always splits the same way.
#pragma once

#include <string>
#include <vector>

#include "framework/host/pipeline.h"

namespace voroseal {

struct StudyShard {
  int index = 1;  // I, from 1
  int count = 1;  // N
};

/// "I/N" as given to --shard. \throws ParameterError naming --shard unless 1 <= I <= N.
StudyShard parse_shard(const std::string& text);

/// The indices (StudyRun::index) of the runs of `shard`, in study order.
std::vector<int> shard_runs(const std::vector<StudyRun>& runs, const StudyShard& shard);

}  // namespace voroseal
