#include "framework/host/snakemake_workflow.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

namespace voroseal {

namespace fs = std::filesystem;

namespace {

// A Python string literal (a JSON string is one).
std::string python_string(const std::string& text) {
  return nlohmann::json(text).dump();
}

}  // namespace

std::string snakefile(const Study& study, const std::vector<StudyRun>& runs,
                      const SnakemakeOptions& options) {
  std::ostringstream s;
  s << "# Snakemake workflow of the voroseal study " << python_string(study.name)
    << ", written by\n"
       "# `voroseal run STUDY.json --emit snakemake DIR`: one job per run, then the summary and\n"
       "# the report (docs/studies.md). In this folder:\n"
       "#   snakemake -j 4                              # this machine, 4 cores\n"
       "#   snakemake -j 100 --slurm                    # a Slurm cluster (Snakemake 7)\n"
       "#   snakemake -j 100 --executor slurm           # a Slurm cluster (Snakemake 8)\n"
       "# Settings: snakemake --config output=DIR threads=2 mem_mb=8000 voroseal=... study=...\n"
       "import os\n"
       "import re\n\n";
  s << "VOROSEAL = config.get(\"voroseal\", " << python_string(options.voroseal) << ")\n"
    << "STUDY = config.get(\"study\", " << python_string(options.study) << ")\n"
    << "OUTPUT = config.get(\"output\", " << python_string(study.output) << ")\n"
    << "THREADS = int(config.get(\"threads\", " << options.threads << "))\n"
    << "MEM_MB = int(config.get(\"mem_mb\", " << options.mem_mb << "))\n"
    << "NO_PICTURES = " << (study.pictures ? "\"\"" : "\"--no-pictures\"") << "\n\n";
  s << "# The run folder under OUTPUT -> the run's number (as in the summary) and model file.\n"
       "RUNS = {\n";
  for (const StudyRun& run : runs) {
    const std::string folder = (fs::path(run.model_label) / run.key).generic_string();
    s << "    " << python_string(folder) << ": (" << run.index + 1 << ", "
      << python_string(run.model) << "),\n";
  }
  s << "}\n\n";
  s << "wildcard_constraints:\n"
       "    folder=\"|\".join(re.escape(f) for f in RUNS),\n\n"
       "localrules: all, summary\n\n"
       "rule all:\n"
       "    input:\n"
       "        [os.path.join(OUTPUT, f) for f in (\"summary.csv\", \"summary.json\", "
       "\"report.html\")],\n\n"
       "# One run of the study. Its model is an input when it exists: a missing one is recorded\n"
       "# as a failed run, as `voroseal run` does. Exit code 1 means the run is recorded as\n"
       "# failed or invalid in its run.json, which the summary shows: the workflow goes on.\n"
       "rule run:\n"
       "    input:\n"
       "        study=STUDY,\n"
       "        model=lambda w: [m for m in [RUNS[w.folder][1]] if os.path.exists(m)],\n"
       "    output:\n"
       "        os.path.join(OUTPUT, \"{folder}\", \"run.json\"),\n"
       "    params:\n"
       "        voroseal=VOROSEAL,\n"
       "        output=OUTPUT,\n"
       "        number=lambda w: RUNS[w.folder][0],\n"
       "        no_pictures=NO_PICTURES,\n"
       "    threads: THREADS\n"
       "    resources:\n"
       "        mem_mb=MEM_MB,\n"
       "    shell:\n"
       "        \"{params.voroseal:q} --quiet --threads {threads} --max-memory {resources.mem_mb}M "
       "\"\n"
       "        \"run {input.study:q} -o {params.output:q} --only {params.number} "
       "{params.no_pictures} \"\n"
       "        \"|| [ $? -eq 1 ]\"\n\n"
       "# The summary and the report of every run, as `voroseal run` writes them.\n"
       "rule summary:\n"
       "    input:\n"
       "        [os.path.join(OUTPUT, f, \"run.json\") for f in RUNS],\n"
       "    output:\n"
       "        [os.path.join(OUTPUT, f) for f in (\"summary.csv\", \"summary.json\", "
       "\"report.html\")],\n"
       "    params:\n"
       "        voroseal=VOROSEAL,\n"
       "        output=OUTPUT,\n"
       "    shell:\n"
       "        \"{params.voroseal:q} --quiet run --merge {params.output:q} -o {params.output:q} "
       "\"\n"
       "        \"|| [ $? -eq 1 ]\"\n";
  return s.str();
}

}  // namespace voroseal
