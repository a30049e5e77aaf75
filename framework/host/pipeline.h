// Scripted studies (`voroseal run STUDY.json`): a pipeline of registered modules run on each
// model, where any parameter given as a list is swept. Every combination (models x swept values,
// a cross product) is one run with its own Context and its own output folder; a run that fails
// is recorded and the study goes on. docs/studies.md describes the file format and the outputs.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/host/log.h"
#include "framework/host/registry.h"
#include "framework/host/render.h"

namespace voroseal {

/// One step of the pipeline: a registered module and its parameters; a list value is swept.
struct StudyStep {
  std::string module;
  nlohmann::json parameters = nlohmann::json::object();
};

/// A file written at the end of each run, into the run's folder.
struct StudyOutput {
  enum class What { Model, Volume, Auto };
  std::string file;        // file name (relative to the run folder) or absolute path
  What what = What::Auto;  // Auto: the volume mesh when the run made one and the format holds
                           // tets (.mesh .vtu .msh .node .ele), else the surface model
};

struct Study {
  std::string name;
  std::string file;      // the study file ("" when built in code)
  std::string base_dir;  // relative model paths resolve here (the study file's folder)
  // Output folder, absolute (a relative one is taken from the working directory).
  std::string output;
  std::vector<std::string> models;                 // model files, resolved against base_dir
  nlohmann::json read = nlohmann::json::object();  // reading options; a list value is swept
  std::vector<StudyStep> steps;
  std::vector<StudyOutput> write;
  bool pictures = true;
  /// Picture options; a study's pictures have axes and a scale bar by default.
  RenderOptions picture = [] {
    RenderOptions o;
    o.axes_and_scale = true;
    return o;
  }();
};

/// Parses a study given as JSON. `base_dir` resolves relative model paths; a relative output
/// folder is taken from the working directory.
/// \throws ParameterError naming the offending key (with `file` as a prefix when given).
Study parse_study(const nlohmann::json& document, const std::string& base_dir,
                  const std::string& file = "");

/// Reads and parses a study file. \throws InputError (unreadable, not JSON), ParameterError
Study read_study(const std::string& path);

/// The study as a normalized document (absolute models, the object form of "write", every
/// picture option), without its output folder: what every run.json records, so that runs of the
/// same study can be recognized wherever they ran, and parse_study() reads it back.
nlohmann::json study_document(const Study& study);

/// One combination of the sweep.
struct StudyRun {
  int index = 0;            // 0-based position in the study
  std::string model;        // model file
  std::string model_label;  // the model's file stem, made unique within the study
  std::string key;          // folder name from the swept values ("default" when none)
  std::string directory;    // <output>/<model_label>/<key>
  nlohmann::json read = nlohmann::json::object();   // concrete reading options
  std::vector<nlohmann::json> step_parameters;      // concrete parameters of each step
  nlohmann::json swept = nlohmann::json::object();  // "step.parameter" -> value, swept ones only
};

/// The runs of a study: models (outermost) x swept values, in file order, the last list varying
/// fastest. \throws ParameterError on an empty list.
std::vector<StudyRun> expand_study(const Study& study);

/// Checks that every module exists and every run's parameters are valid, before anything runs.
/// \throws ParameterError
void validate_study(const ModuleRegistry& registry, const Study& study,
                    const std::vector<StudyRun>& runs);

struct StepOutcome {
  std::string module;
  // ok, invalid (the step gave a non-zero verdict), failed, skipped
  std::string status = "skipped";
  int exit_code = 0;
  double seconds = 0;
  std::string error;
  // What the step printed on stdout: a file relative to the study output ("" if nothing).
  std::string text;
};

struct RunOutcome {
  StudyRun run;
  std::string status = "ok";  // ok, invalid, failed
  int exit_code = 0;          // as the CLI's exit codes (runner.h)
  std::string error;          // the first error, prefixed with the step that raised it
  double read_seconds = 0, write_seconds = 0, picture_seconds = 0, total_seconds = 0;
  std::vector<StepOutcome> steps;
  nlohmann::json parameters = nlohmann::json::object();  // validated, defaults filled
  nlohmann::json report = nlohmann::json::object();      // the run's Context::report
  nlohmann::json measures = nlohmann::json::object();    // summary-row metrics (study_report.h)
  nlohmann::json histograms = nlohmann::json::object();
  nlohmann::json legend = nlohmann::json::array();  // surface name and picture colour
  std::vector<std::string> outputs;                 // files written, relative to the study output
  std::string picture;                              // relative to the study output, "" when none
  std::string cut_picture;  // the tet mesh cut in two (volume_cut.h), as picture; "" when none
  nlohmann::json region_legend = nlohmann::json::array();  // region name and colour in it
};

struct StudyOutcome {
  Study study;
  std::vector<RunOutcome> runs;
  double seconds = 0;
  int failed = 0, invalid = 0;
  /// 0 when every run is ok, 1 when one failed or was invalid.
  int exit_code() const { return failed + invalid > 0 ? 1 : 0; }
};

struct StudyOptions {
  int threads = 0;              // Context::threads of every run
  double max_memory_bytes = 0;  // Context::max_memory_bytes of every run (0: the machine's)
  /// The runs to do (StudyRun::index), in this order; nullopt: all of them.
  std::optional<std::vector<int>> runs;
  /// Takes a run from its run.json instead of running it when that run is complete
  /// (study_results.h: read_complete_run).
  bool resume = false;
  /// Writes summary.csv, summary.json and report.html after every run (so a long study can be
  /// watched), and at the end.
  bool reports = true;
};

/// Runs the study: validates it (throws before running anything), then each run in order on a
/// fresh Context: read the model, run the steps, write the outputs and run.json, render the
/// picture. A failing step fails its run (later steps are skipped) and the study continues.
/// \throws ParameterError (invalid study), OutputError (the output folder cannot be made)
StudyOutcome run_study(const ModuleRegistry& registry, const Study& study,
                       const StudyOptions& options, Logger& log, Progress& progress);

}  // namespace voroseal
