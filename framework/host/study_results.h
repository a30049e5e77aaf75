// A study's runs read back from their run.json files: to skip the runs already complete
// (`voroseal run --resume`) and to put the runs of several output folders (shards, Snakemake
// jobs) together into one summary and report (`voroseal run --merge`). A run.json is removed
// when its run starts and written atomically when it ends, so its presence means the run ended.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/host/pipeline.h"

namespace voroseal {

/// The outcome recorded in a run.json. `run` is the study's run it records, its `directory`
/// the folder the file is in; the files it names (outputs, picture, step texts), relative to
/// the output folder the run was written to, are made relative to `output`.
/// \throws InputError (the document is not a run.json), naming `file`
RunOutcome run_outcome_from_json(const nlohmann::json& document, const StudyRun& run,
                                 const std::string& output, const std::string& file);

/// The outcome of `run` from its run.json when the run is complete: the file records this
/// study (study_document) and this run, its status is ok or invalid (a failed run is done
/// again: its cause may be gone), and the files it lists exist. nullopt otherwise.
std::optional<RunOutcome> read_complete_run(const Study& study, const StudyRun& run);

struct MergedStudy {
  StudyOutcome outcome;      // the runs found, in study order; seconds: the sum of theirs
  std::vector<int> missing;  // numbers (from 1) of the study's runs found in no folder
};

/// Reads every <model>/<key>/run.json under `folders` as the runs of one study, whose output
/// folder becomes `output` (empty: the study's default, out/<name>).
/// \throws InputError (a folder or a run.json that cannot be read), ParameterError (no run
/// found, runs of different studies, a run found twice, a run.json that is no run of its study)
MergedStudy merge_study_results(const std::vector<std::string>& folders, const std::string& output);

}  // namespace voroseal
