#include "framework/host/pipeline.h"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

#include <iostream>

#include "framework/core/error.h"
#include "framework/host/runner.h"
#include "framework/host/study_report.h"
#include "framework/host/study_results.h"
#include "framework/host/volume_cut.h"
#include "io/atomic_file.h"
#include "io/model_io.h"

namespace voroseal {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// ---- the study file ----------------------------------------------------------------------

// Reading options of a study ("read"), with the names of the CLI options.
std::vector<ParameterSpec> read_specs() {
  ParameterSpec angle{"feature-angle", ParameterType::Double, 0.0,
                      "split a surface where it folds more than this (degrees)"};
  angle.min = 0.0;
  angle.max = 180.0;
  ParameterSpec weld{"weld-tolerance", ParameterType::Double, 1e-7,
                     "welding distance relative to the bbox diagonal"};
  weld.min = 0.0;
  weld.max = 0.1;
  ParameterSpec corner{"corner-rule", ParameterType::Choice, "incidence", "corner placement rule"};
  corner.choices = {"incidence", "signature"};
  return {angle, weld, corner};
}

ReadOptions read_options(const Parameters& p) {
  ReadOptions options;
  options.build.feature_angle_deg = p.get_double("feature-angle");
  options.build.weld_tolerance = p.get_double("weld-tolerance");
  options.build.corner_rule =
      p.get_string("corner-rule") == "signature" ? CornerRule::Signature : CornerRule::Incidence;
  return options;
}

// Picture options of a study ("picture": true, false or an object of these).
std::vector<ParameterSpec> picture_specs() {
  const RenderOptions d;
  ParameterSpec width{"width", ParameterType::Int, d.width, "picture width in pixels"};
  width.min = 16, width.max = 8192;
  ParameterSpec height{"height", ParameterType::Int, d.height, "picture height in pixels"};
  height.min = 16, height.max = 8192;
  ParameterSpec azimuth{"azimuth", ParameterType::Double, d.azimuth_deg,
                        "viewer azimuth, degrees from north"};
  azimuth.min = -360, azimuth.max = 360;
  ParameterSpec elevation{"elevation", ParameterType::Double, d.elevation_deg,
                          "viewer elevation, degrees"};
  elevation.min = -90, elevation.max = 90;
  ParameterSpec exaggeration{"vertical-exaggeration", ParameterType::Double,
                             d.vertical_exaggeration, ""};
  exaggeration.min = 1e-3;
  exaggeration.max = 1e3;
  ParameterSpec perspective{"perspective", ParameterType::Bool, d.perspective, ""};
  ParameterSpec cut{"cut-away", ParameterType::Bool, d.cut_away, ""};
  ParameterSpec colour{"colour-by", ParameterType::Choice, "part", ""};
  colour.choices = {"part", "interface"};
  ParameterSpec edges{"edges", ParameterType::Choice, "auto", ""};
  edges.choices = {"auto", "always", "never"};
  ParameterSpec supersample{"supersample", ParameterType::Int, d.supersample, ""};
  supersample.min = 1, supersample.max = 4;
  // A study's pictures have axes and a scale bar unless asked not to (Study::picture).
  ParameterSpec axes{"axes", ParameterType::Bool, true, "axes and a scale bar"};
  return {width, height, azimuth, elevation,   exaggeration, perspective,
          cut,   colour, edges,   supersample, axes};
}

RenderOptions picture_options(const Parameters& p) {
  RenderOptions o;
  o.width = static_cast<int>(p.get_int("width"));
  o.height = static_cast<int>(p.get_int("height"));
  o.azimuth_deg = p.get_double("azimuth");
  o.elevation_deg = p.get_double("elevation");
  o.vertical_exaggeration = p.get_double("vertical-exaggeration");
  o.perspective = p.get_bool("perspective");
  o.cut_away = p.get_bool("cut-away");
  o.colour_by = p.get_string("colour-by") == "interface" ? ColourBy::Interface : ColourBy::Part;
  const std::string edges = p.get_string("edges");
  o.edges = edges == "always"  ? EdgeDrawing::Always
            : edges == "never" ? EdgeDrawing::Never
                               : EdgeDrawing::Auto;
  o.supersample = static_cast<int>(p.get_int("supersample"));
  o.axes_and_scale = p.get_bool("axes");
  return o;
}

// The picture options as the study file writes them (the inverse of picture_options).
json picture_document(const RenderOptions& o) {
  const char* edges = o.edges == EdgeDrawing::Always  ? "always"
                      : o.edges == EdgeDrawing::Never ? "never"
                                                      : "auto";
  return {{"width", o.width},
          {"height", o.height},
          {"azimuth", o.azimuth_deg},
          {"elevation", o.elevation_deg},
          {"vertical-exaggeration", o.vertical_exaggeration},
          {"perspective", o.perspective},
          {"cut-away", o.cut_away},
          {"colour-by", o.colour_by == ColourBy::Interface ? "interface" : "part"},
          {"edges", edges},
          {"supersample", o.supersample},
          {"axes", o.axes_and_scale}};
}

std::string resolve(const std::string& base_dir, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute() || base_dir.empty()) return path;
  return (fs::path(base_dir) / path).lexically_normal().string();
}

// Replaces {study_dir}, {model} and {run_dir} in a path parameter.
std::string substitute(std::string text, const std::map<std::string, std::string>& values) {
  for (const auto& [name, value] : values) {
    const std::string token = "{" + name + "}";
    for (size_t at = text.find(token); at != std::string::npos;
         at = text.find(token, at + value.size()))
      text.replace(at, token.size(), value);
  }
  return text;
}

// The text of a swept value inside a folder name: letters, digits and . + - _ only.
std::string folder_text(const json& value) {
  std::string text = value.is_string() ? value.get<std::string>() : value.dump();
  for (char& c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '+' && c != '-' &&
        c != '_')
      c = '-';
  return text;
}

// One swept parameter: where it is (step -1: the reading options) and its values.
struct Axis {
  int step = -1;
  std::string parameter;
  std::vector<json> values;
  std::string label;  // "edge-length", or "remesh.edge-length" when the name is ambiguous
};

// Sends what the process writes on stdout (file descriptor 1) to a file while alive. Modules
// print their text reports on stdout (check does); in a study that text goes to the run's
// folder, so the study's own stdout stays clean (--json).
class StdoutToFile {
 public:
  explicit StdoutToFile(const std::string& path) {
    std::cout.flush();
    std::fflush(stdout);
    file_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (file_ < 0) return;
    saved_ = ::dup(STDOUT_FILENO);
    if (saved_ < 0 || ::dup2(file_, STDOUT_FILENO) < 0) restore();
  }
  ~StdoutToFile() { restore(); }
  StdoutToFile(const StdoutToFile&) = delete;
  StdoutToFile& operator=(const StdoutToFile&) = delete;

 private:
  void restore() {
    std::cout.flush();
    std::fflush(stdout);
    if (saved_ >= 0) {
      ::dup2(saved_, STDOUT_FILENO);
      ::close(saved_);
      saved_ = -1;
    }
    if (file_ >= 0) {
      ::close(file_);
      file_ = -1;
    }
  }
  int file_ = -1;
  int saved_ = -1;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The exit code and message of the exception being handled (as runner.cpp maps them).
std::pair<int, std::string> describe_current_exception() {
  try {
    throw;
  } catch (const InputError& e) {
    return {kExitUnreadable, e.what()};
  } catch (const ParameterError& e) {
    return {kExitUnreadable, e.what()};
  } catch (const ModelError& e) {
    return {kExitInvalid, std::string("invalid model: ") + e.what()};
  } catch (const MesherError& e) {
    return {kExitInvalid, std::string("meshing failed: ") + e.what()};
  } catch (const OutputError& e) {
    return {kExitInvalid, std::string("cannot write: ") + e.what()};
  } catch (const std::bad_alloc&) {
    return {kExitInternal, "out of memory"};
  } catch (const std::exception& e) {
    return {kExitInternal, std::string("internal error: ") + e.what()};
  } catch (...) {
    return {kExitInternal, "internal error: unknown exception"};
  }
}

bool holds_tets(const std::string& file) {
  std::string ext = fs::path(file).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string& e : writable_volume_extensions())
    if (e == ext) return true;
  return ext == ".node" || ext == ".ele";
}

// A colour as CSS writes it: #rrggbb.
std::string hex_colour(const std::array<uint8_t, 3>& c) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c[0], c[1], c[2]);
  return hex;
}

void write_json_file(const json& document, const std::string& path,
                     const std::vector<std::string>& inputs) {
  write_atomically(path, inputs, [&](std::ostream& out) { out << document.dump(2) << "\n"; });
}

}  // namespace

// ---- parsing -----------------------------------------------------------------------------

Study parse_study(const json& document, const std::string& base_dir, const std::string& file) {
  const std::string where = file.empty() ? std::string("study") : file;
  auto fail = [&](const std::string& key, const std::string& why) {
    return ParameterError(where + ": " + key + ": " + why);
  };
  if (!document.is_object()) throw ParameterError(where + ": a study is a JSON object");
  static const std::set<std::string> known = {"name", "description", "output", "models",
                                              "read", "steps",       "write",  "picture"};
  for (const auto& [key, value] : document.items())
    if (!known.count(key))
      throw fail(
          key,
          "unknown key (known: name, description, output, models, read, steps, write, picture)");

  Study study;
  study.file = file;
  study.base_dir = base_dir;
  if (document.contains("name")) {
    if (!document["name"].is_string() || document["name"].get<std::string>().empty())
      throw fail("name", "expected a non-empty string");
    study.name = document["name"].get<std::string>();
  } else {
    study.name = file.empty() ? "study" : fs::path(file).stem().string();
  }
  for (char c : study.name)
    if (c == '/' || c == '\\') throw fail("name", "must not contain a path separator");

  std::string output = "out/" + study.name;
  if (document.contains("output")) {
    if (!document["output"].is_string() || document["output"].get<std::string>().empty())
      throw fail("output", "expected a folder name");
    output = document["output"].get<std::string>();
  }
  // Outputs go where voroseal runs (like any command's output), inputs are found beside the study.
  study.output = fs::absolute(output).lexically_normal().string();

  const json models = document.value("models", json());
  if (models.is_string()) {
    study.models.push_back(resolve(base_dir, models.get<std::string>()));
  } else if (models.is_array() && !models.empty()) {
    for (const json& m : models) {
      if (!m.is_string()) throw fail("models", "expected file names, got " + m.dump());
      study.models.push_back(resolve(base_dir, m.get<std::string>()));
    }
  } else {
    throw fail("models", "expected a model file or a non-empty list of model files");
  }

  if (document.contains("read")) {
    if (!document["read"].is_object()) throw fail("read", "expected an object of reading options");
    study.read = document["read"];
  }

  const json steps = document.value("steps", json());
  if (!steps.is_array())
    throw fail("steps", "expected a list of {\"module\": ..., \"parameters\": {...}}");
  for (size_t i = 0; i < steps.size(); ++i) {
    const json& s = steps[i];
    const std::string key = "steps[" + std::to_string(i) + "]";
    if (s.is_string()) {
      study.steps.push_back({s.get<std::string>(), json::object()});
      continue;
    }
    if (!s.is_object() || !s.contains("module") || !s["module"].is_string())
      throw fail(key, "expected {\"module\": name, \"parameters\": {...}}");
    for (const auto& [k, v] : s.items())
      if (k != "module" && k != "parameters")
        throw fail(key + "." + k, "unknown key (known: module, parameters)");
    StudyStep step;
    step.module = s["module"].get<std::string>();
    if (s.contains("parameters")) {
      if (!s["parameters"].is_object()) throw fail(key + ".parameters", "expected an object");
      step.parameters = s["parameters"];
    }
    study.steps.push_back(std::move(step));
  }

  if (document.contains("write")) {
    const json& w = document["write"];
    auto add = [&](const json& f, StudyOutput::What what, const std::string& key) {
      if (!f.is_string() || f.get<std::string>().empty())
        throw fail(key, "expected a file name, got " + f.dump());
      study.write.push_back({f.get<std::string>(), what});
    };
    if (w.is_array()) {
      for (size_t i = 0; i < w.size(); ++i) {
        const std::string key = "write[" + std::to_string(i) + "]";
        if (w[i].is_object()) {
          for (const auto& [k, v] : w[i].items()) {
            if (k != "model" && k != "volume")
              throw fail(key + "." + k, "expected model or volume");
            add(v, k == "model" ? StudyOutput::What::Model : StudyOutput::What::Volume,
                key + "." + k);
          }
        } else {
          add(w[i], StudyOutput::What::Auto, key);
        }
      }
    } else if (w.is_object()) {
      for (const auto& [k, v] : w.items()) {
        if (k != "model" && k != "volume") throw fail("write." + k, "expected model or volume");
        const auto what = k == "model" ? StudyOutput::What::Model : StudyOutput::What::Volume;
        if (v.is_array())
          for (const json& f : v) add(f, what, "write." + k);
        else
          add(v, what, "write." + k);
      }
    } else {
      throw fail("write", "expected a list of file names or {\"model\": ..., \"volume\": ...}");
    }
  }

  if (document.contains("picture")) {
    const json& p = document["picture"];
    if (p.is_boolean()) {
      study.pictures = p.get<bool>();
    } else if (p.is_object()) {
      try {
        study.picture = picture_options(Parameters(picture_specs(), p));
      } catch (const ParameterError& e) {
        throw fail("picture", e.what());
      }
    } else {
      throw fail("picture", "expected true, false or an object of picture options");
    }
  }
  return study;
}

Study read_study(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open the study file");
  json document;
  try {
    document = json::parse(in, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw InputError(path, 0, std::string("not a valid JSON study: ") + e.what());
  }
  const fs::path parent = fs::absolute(path).parent_path();
  return parse_study(document, parent.string(), path);
}

json study_document(const Study& study) {
  json steps = json::array();
  for (const StudyStep& s : study.steps)
    steps.push_back({{"module", s.module}, {"parameters", s.parameters}});
  json write = json::array();
  for (const StudyOutput& w : study.write) {
    if (w.what == StudyOutput::What::Auto)
      write.push_back(w.file);
    else
      write.push_back({{w.what == StudyOutput::What::Model ? "model" : "volume", w.file}});
  }
  return {{"name", study.name},
          {"models", study.models},
          {"read", study.read},
          {"steps", steps},
          {"write", write},
          {"picture", study.pictures ? picture_document(study.picture) : json(false)}};
}

// ---- sweep expansion ---------------------------------------------------------------------

std::vector<StudyRun> expand_study(const Study& study) {
  const std::string where = study.file.empty() ? std::string("study") : study.file;
  std::vector<Axis> axes;
  auto collect = [&](int step, const json& parameters, const std::string& key) {
    for (const auto& [name, value] : parameters.items()) {
      if (!value.is_array()) continue;
      if (value.empty())
        throw ParameterError(where + ": " + key + "." + name + ": an empty list sweeps nothing");
      axes.push_back({step, name, std::vector<json>(value.begin(), value.end()), name});
    }
  };
  collect(-1, study.read, "read");
  for (size_t s = 0; s < study.steps.size(); ++s)
    collect(static_cast<int>(s), study.steps[s].parameters,
            "steps[" + std::to_string(s) + "].parameters");
  std::map<std::string, int> uses;
  for (const Axis& a : axes) ++uses[a.parameter];
  for (Axis& a : axes)
    if (uses[a.parameter] > 1)
      a.label = (a.step < 0 ? std::string("read") : study.steps[a.step].module) + "." + a.parameter;
  // The same module twice with the same swept name: number the steps instead.
  std::map<std::string, int> qualified;
  for (const Axis& a : axes) ++qualified[a.label];
  for (Axis& a : axes)
    if (qualified[a.label] > 1) a.label = "step" + std::to_string(a.step + 1) + "." + a.parameter;

  // Unique labels for the models (two files with the same stem get -2, -3 ...).
  std::vector<std::string> labels;
  std::map<std::string, int> seen;
  for (const std::string& m : study.models) {
    std::string stem = folder_text(json(fs::path(m).stem().string()));
    if (stem.empty()) stem = "model";
    const int n = ++seen[stem];
    labels.push_back(n == 1 ? stem : stem + "-" + std::to_string(n));
  }

  size_t combinations = 1;
  for (const Axis& a : axes) combinations *= a.values.size();
  std::vector<StudyRun> runs;
  for (size_t m = 0; m < study.models.size(); ++m) {
    std::set<std::string> keys;
    for (size_t c = 0; c < combinations; ++c) {
      StudyRun run;
      run.index = static_cast<int>(runs.size());
      run.model = study.models[m];
      run.model_label = labels[m];
      run.read = study.read;
      for (const StudyStep& step : study.steps) run.step_parameters.push_back(step.parameters);
      // Mixed radix: the last axis varies fastest.
      size_t rest = c;
      std::vector<size_t> choice(axes.size());
      for (size_t a = axes.size(); a-- > 0;) {
        choice[a] = rest % axes[a].values.size();
        rest /= axes[a].values.size();
      }
      std::string key;
      for (size_t a = 0; a < axes.size(); ++a) {
        const json& value = axes[a].values[choice[a]];
        json& target = axes[a].step < 0 ? run.read : run.step_parameters[axes[a].step];
        target[axes[a].parameter] = value;
        run.swept[axes[a].label] = value;
        key +=
            (key.empty() ? "" : "_") + folder_text(json(axes[a].label)) + "=" + folder_text(value);
      }
      if (key.empty()) key = "default";
      if (key.size() > 120) key = key.substr(0, 120);
      std::string unique = key;
      for (int n = 2; keys.count(unique); ++n) unique = key + "-" + std::to_string(n);
      keys.insert(unique);
      run.key = unique;
      run.directory = (fs::path(study.output) / run.model_label / run.key).string();
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

void validate_study(const ModuleRegistry& registry, const Study& study,
                    const std::vector<StudyRun>& runs) {
  const std::string where = study.file.empty() ? std::string("study") : study.file;
  for (size_t s = 0; s < study.steps.size(); ++s)
    if (registry.find(study.steps[s].module) == nullptr) {
      try {
        registry.get(study.steps[s].module);
      } catch (const ParameterError& e) {
        throw ParameterError(where + ": steps[" + std::to_string(s) + "]: " + e.what());
      }
    }
  for (const StudyRun& run : runs) {
    try {
      Parameters(read_specs(), run.read);
    } catch (const ParameterError& e) {
      throw ParameterError(where + ": read: " + e.what());
    }
    for (size_t s = 0; s < study.steps.size(); ++s) {
      const Module& module = registry.get(study.steps[s].module);
      try {
        Parameters(module.parameters(), run.step_parameters[s]);
      } catch (const ParameterError& e) {
        throw ParameterError(where + ": steps[" + std::to_string(s) + "] (" + module.name() +
                             "): " + e.what());
      }
    }
  }
}

// ---- running -----------------------------------------------------------------------------

namespace {

// Runs one combination on its own Context. Never throws for a failure of the run itself.
RunOutcome execute_run(const ModuleRegistry& registry, const Study& study, const StudyRun& run,
                       const StudyOptions& options, Logger& log, Progress& progress) {
  const auto run_start = std::chrono::steady_clock::now();
  RunOutcome outcome;
  outcome.run = run;
  auto relative = [&](const std::string& path) {
    return fs::relative(path, study.output).generic_string();
  };
  auto fail = [&](const std::string& stage) {
    const auto [code, message] = describe_current_exception();
    outcome.status = "failed";
    outcome.exit_code = code;
    if (outcome.error.empty()) outcome.error = stage + ": " + message;
    return message;
  };

  Context context(log, progress);
  context.threads = options.threads;
  context.max_memory_bytes = options.max_memory_bytes;
  context.registry = &registry;  // modules that run other modules (remesh --tetmesh) find them here
  const std::map<std::string, std::string> placeholders = {
      {"study_dir", study.base_dir}, {"model", run.model}, {"run_dir", run.directory}};

  // Parameters, validated (the study was validated before: this cannot throw here).
  const Parameters read_parameters(read_specs(), run.read);
  outcome.parameters["read"] = read_parameters.json();
  std::vector<Parameters> step_parameters;
  outcome.parameters["steps"] = json::array();
  for (size_t s = 0; s < study.steps.size(); ++s) {
    const Module& module = registry.get(study.steps[s].module);
    json values = run.step_parameters[s];
    // Path parameters: placeholders, then relative to the run's folder (outputs land there).
    for (const ParameterSpec& spec : module.parameters())
      if (spec.type == ParameterType::Path && values.contains(spec.name) &&
          values[spec.name].is_string()) {
        const std::string path = substitute(values[spec.name].get<std::string>(), placeholders);
        values[spec.name] = resolve(run.directory, path);
      }
    step_parameters.emplace_back(module.parameters(), values);
    outcome.parameters["steps"].push_back(
        {{"module", module.name()}, {"parameters", step_parameters.back().json()}});
    outcome.steps.push_back({module.name()});
  }

  // run.json is written last: a run killed before it has none and is not complete (resume).
  const std::string run_file = (fs::path(run.directory) / "run.json").string();
  std::error_code error;
  fs::remove(run_file, error);
  fs::create_directories(run.directory, error);
  if (error) {
    outcome.status = "failed";
    outcome.exit_code = kExitInvalid;
    outcome.error = "output: cannot create " + run.directory + ": " + error.message();
    return outcome;
  }

  // Read.
  auto start = std::chrono::steady_clock::now();
  bool read_ok = true;
  try {
    progress.start("read " + run.model_label, 0);
    load_model(context, run.model, read_options(read_parameters));
    progress.finish();
  } catch (...) {
    progress.finish();
    log.error(fail("read"));
    read_ok = false;
  }
  outcome.read_seconds = seconds_since(start);

  // Steps, in order; after a failure the rest are skipped.
  for (size_t s = 0; s < study.steps.size() && read_ok && outcome.status != "failed"; ++s) {
    const Module& module = registry.get(study.steps[s].module);
    StepOutcome& step = outcome.steps[s];
    const int verdict_before = context.exit_code;
    context.exit_code = 0;
    const std::string text_file =
        (fs::path(run.directory) / ("step" + std::to_string(s + 1) + "-" + module.name() + ".txt"))
            .string();
    start = std::chrono::steady_clock::now();
    try {
      const StdoutToFile capture(text_file);
      module.run(context, step_parameters[s]);
      step.exit_code = context.exit_code;
      step.status = context.exit_code == 0 ? "ok" : "invalid";
    } catch (...) {
      const std::string message = fail(module.name());
      step.status = "failed";
      step.exit_code = outcome.exit_code;
      step.error = message;
      log.error(module.name() + ": " + message);
    }
    step.seconds = seconds_since(start);
    std::error_code size_error;
    if (fs::exists(text_file, size_error) && fs::file_size(text_file, size_error) == 0)
      fs::remove(text_file, size_error);
    else if (fs::exists(text_file, size_error))
      step.text = relative(text_file);
    context.exit_code = std::max(verdict_before, context.exit_code);
    log.info("  " + module.name() + " " + step.status + " (" +
             std::to_string(step.seconds).substr(0, 6) + " s)");
  }
  if (outcome.status != "failed" && context.exit_code != 0) {
    outcome.status = "invalid";
    outcome.exit_code = context.exit_code;
  }
  outcome.report = context.report;

  if (read_ok) {
    // Measures and histograms of the final model (and volume); never fatal to the run.
    try {
      const RunMeasures measures = measure_run(context);
      outcome.measures = measures.row;
      outcome.histograms = measures.histograms;
    } catch (const std::exception& e) {
      log.warning(std::string("measures: ") + e.what());
    }
  }

  // Outputs: only when the steps succeeded (a half-finished model is not a result).
  start = std::chrono::steady_clock::now();
  if (read_ok && outcome.status != "failed") {
    WriteOptions write;
    write.protected_paths = {run.model};
    for (const StudyOutput& out : study.write) {
      const std::string path = resolve(run.directory, substitute(out.file, placeholders));
      try {
        const bool volume =
            out.what == StudyOutput::What::Volume ||
            (out.what == StudyOutput::What::Auto && context.volume && holds_tets(path));
        if (volume) {
          if (!context.volume)
            throw OutputError(path + ": the run made no volume mesh (add a tetmesh step)");
          write_volume_mesh(*context.volume, path, write);
        } else {
          write_model(*context.model, path, write);
        }
        outcome.outputs.push_back(relative(path));
      } catch (...) {
        const std::string message = fail("write");
        log.error(message);
      }
    }
  }
  outcome.write_seconds = seconds_since(start);

  // Picture of the final surfaces, failed runs included: the model a step choked on is what
  // one wants to look at.
  start = std::chrono::steady_clock::now();
  if (study.pictures && read_ok && context.model) {
    try {
      const std::string path = (fs::path(run.directory) / "picture.png").string();
      progress.start("picture", 0);
      write_png(render_model(*context.model, study.picture), path);
      progress.finish();
      outcome.picture = relative(path);
      const StructuralModel& model = *context.model;
      const bool by_part = study.picture.colour_by == ColourBy::Part;
      const size_t n = by_part ? model.parts.size() : model.interfaces.size();
      for (size_t i = 0; i < n; ++i) {
        outcome.legend.push_back(
            {{"name", by_part ? model.parts[i].name : model.interfaces[i].name},
             {"colour", hex_colour(surface_colour(static_cast<int>(i)))}});
      }
    } catch (const std::exception& e) {
      progress.finish();
      log.warning(std::string("picture: ") + e.what());
    }
  }
  // The tet mesh cut in two, from the same viewpoint, coloured by region.
  if (study.pictures && read_ok && context.volume && !context.volume->tets.empty()) {
    try {
      const std::string path = (fs::path(run.directory) / "cut.png").string();
      progress.start("picture of the tets", 0);
      write_png(render_volume_cut(*context.volume, study.picture), path);
      progress.finish();
      outcome.cut_picture = relative(path);
      const std::vector<std::string>& names = context.volume->region_names;
      std::set<int> regions(context.volume->tet_region.begin(), context.volume->tet_region.end());
      for (const int region : regions)
        outcome.region_legend.push_back(
            {{"name", region >= 0 && region < static_cast<int>(names.size())
                          ? names[region]
                          : "region " + std::to_string(region)},
             {"colour", hex_colour(surface_colour(region))}});
    } catch (const std::exception& e) {
      progress.finish();
      log.warning(std::string("picture of the tets: ") + e.what());
    }
  }
  outcome.picture_seconds = seconds_since(start);
  outcome.total_seconds = seconds_since(run_start);

  try {
    write_json_file(run_json(outcome, study), run_file, study.models);
  } catch (const std::exception& e) {
    log.error(e.what());
  }
  return outcome;
}

}  // namespace

StudyOutcome run_study(const ModuleRegistry& registry, const Study& study,
                       const StudyOptions& options, Logger& log, Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<StudyRun> all = expand_study(study);
  validate_study(registry, study, all);
  std::vector<StudyRun> runs = options.runs ? std::vector<StudyRun>() : all;
  for (const int index : options.runs.value_or(std::vector<int>())) {
    if (index < 0 || index >= static_cast<int>(all.size()))
      throw ParameterError("run " + std::to_string(index + 1) + " does not exist (the study has " +
                           std::to_string(all.size()) + " runs)");
    runs.push_back(all[index]);
  }
  std::error_code error;
  fs::create_directories(study.output, error);
  if (error)
    throw OutputError(study.output + ": cannot create the study folder: " + error.message());

  StudyOutcome outcome;
  outcome.study = study;
  log.info("study " + study.name + ": " + std::to_string(runs.size()) + " of " +
           std::to_string(all.size()) + " runs into " + study.output);
  for (const StudyRun& run : runs) {
    std::string title = "[" + std::to_string(run.index + 1) + "/" + std::to_string(all.size()) +
                        "] " + run.model_label + " " + run.key;
    std::optional<RunOutcome> done_before;
    if (options.resume) done_before = read_complete_run(study, run);
    if (done_before) {
      log.info(title + ": complete, skipped (--resume)");
      outcome.runs.push_back(std::move(*done_before));
    } else {
      log.info(title);
      outcome.runs.push_back(execute_run(registry, study, run, options, log, progress));
    }
    const RunOutcome& done = outcome.runs.back();
    if (done.status == "failed") ++outcome.failed;
    if (done.status == "invalid") ++outcome.invalid;
    if (done.status == "invalid") log.warning(title + ": invalid (a step gave a negative verdict)");
    outcome.seconds = seconds_since(start);
    if (options.reports) write_study_reports(outcome);
  }
  outcome.seconds = seconds_since(start);
  if (options.reports) write_study_reports(outcome);
  log.info("study " + study.name + ": " +
           std::to_string(runs.size() - outcome.failed - outcome.invalid) + " ok, " +
           std::to_string(outcome.invalid) + " invalid, " + std::to_string(outcome.failed) +
           " failed in " + std::to_string(outcome.seconds).substr(0, 7) + " s" +
           (options.reports ? "; report " + (fs::path(study.output) / "report.html").string()
                            : std::string()));
  return outcome;
}

}  // namespace voroseal
