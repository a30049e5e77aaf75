// A study as a Snakemake workflow (`voroseal run STUDY.json --emit snakemake DIR`): one job
// per run, each running voroseal on that run alone (`run STUDY --only N`), then one job
// putting their run.json files together into the summary and the report (`run --merge`), so
// that `snakemake -j N` on a workstation or a Slurm executor on a cluster gives the results
// `voroseal run` gives, from the same code.
#pragma once

#include <string>
#include <vector>

#include "framework/host/pipeline.h"

namespace voroseal {

/// Memory of one job (Snakemake's mem_mb, MiB) when not given: a run needing more is
/// refused by its module's memory check and recorded as failed, naming the figure.
constexpr long kSnakemakeDefaultMemMb = 4096;

struct SnakemakeOptions {
  std::string voroseal;  // the executable, absolute
  std::string study;     // the study file, absolute
  int threads = 1;       // threads of each job (Snakemake lowers it to the cores it has)
  long mem_mb = kSnakemakeDefaultMemMb;  // memory of each job, also its --max-memory
};

/// The Snakefile. Its settings (voroseal, study, output, threads, mem_mb) can be changed with
/// `snakemake --config NAME=VALUE`.
std::string snakefile(const Study& study, const std::vector<StudyRun>& runs,
                      const SnakemakeOptions& options);

}  // namespace voroseal
