#include "framework/cli/command_line.h"

#include <omp.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <thread>

#include "framework/core/error.h"
#include "framework/core/signal_cleanup.h"
#include "framework/host/memory_budget.h"
#include "framework/host/pipeline.h"
#include "framework/host/plugin_loader.h"
#include "framework/host/runner.h"
#include "framework/host/snakemake_workflow.h"
#include "framework/host/study_report.h"
#include "framework/host/study_results.h"
#include "framework/host/study_shard.h"
#include "io/atomic_file.h"

namespace voroseal {

namespace {

constexpr const char* kVersion = "0.1.0";
// --threads at most this many times the hardware threads: more only adds contention, and far
// more makes the OpenMP runtime fail to create them.
constexpr int kThreadsPerHardwareThread = 4;

int max_threads() {
  const unsigned hardware = std::thread::hardware_concurrency();
  return kThreadsPerHardwareThread * static_cast<int>(hardware > 0 ? hardware : 1);
}

// "0 to 100": a numeric parameter's bounds for --help and `voroseal modules`.
std::string range_text(const ParameterSpec& spec) {
  if (spec.type != ParameterType::Int && spec.type != ParameterType::Double) return "";
  auto number = [&](double v) {
    if (spec.type == ParameterType::Int && std::abs(v) < 9.0e15)
      return std::to_string(static_cast<long long>(v));
    return nlohmann::json(v).dump();
  };
  return number(spec.min) + " to " + number(spec.max);
}

std::string default_text(const ParameterSpec& spec) {
  if (spec.default_value.is_null()) return "";
  if (spec.default_value.is_string()) return spec.default_value.get<std::string>();
  return spec.default_value.dump();
}

std::string type_text(const ParameterSpec& spec) {
  if (spec.type != ParameterType::Choice) return to_string(spec.type);
  std::string s;
  for (const std::string& c : spec.choices) s += (s.empty() ? "" : "|") + c;
  return s;
}

// `voroseal modules`: every module with its parameters.
void print_modules(const ModuleRegistry& registry, bool json) {
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const Module* m : registry.modules()) {
      nlohmann::json params = nlohmann::json::array();
      for (const ParameterSpec& p : m->parameters())
        params.push_back({{"name", p.name},
                          {"type", to_string(p.type)},
                          {"default", p.default_value},
                          {"doc", p.doc},
                          {"choices", p.choices},
                          {"min", p.min},
                          {"max", p.max},
                          {"positional", p.positional},
                          {"required", p.required}});
      out.push_back({{"name", m->name()}, {"description", m->description()}, {"parameters", params}});
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
  for (const Module* m : registry.modules()) {
    std::cout << m->name() << "  " << m->description() << "\n";
    for (const ParameterSpec& p : m->parameters()) {
      if (p.positional)
        std::cout << "    " << p.name << " (or --" << p.name << ") <" << type_text(p) << ">";
      else
        std::cout << "    --" << p.name << " <" << type_text(p) << ">";
      const std::string d = default_text(p);
      if (!d.empty()) std::cout << " (default " << d << ")";
      const std::string range = range_text(p);
      if (!range.empty()) std::cout << " (" << range << ")";
      if (p.required) std::cout << " (required)";
      std::cout << "  " << p.doc << "\n";
    }
  }
}

struct ModuleCommand {
  const Module* module = nullptr;
  CLI::App* app = nullptr;
  std::string input;
  std::map<std::string, std::string> values;  // given on the command line
  std::map<std::string, bool> flags;
  std::map<std::string, CLI::Option*> bool_options;
};

// The options of `voroseal run`.
struct RunCommand {
  std::string study, output, shard;
  bool dry_run = false, no_pictures = false, resume = false;
  std::vector<int> only;                 // run numbers, from 1
  std::vector<std::string> emit, merge;  // {"snakemake", DIR}; run folders
};

// The path of this executable, for the jobs of a workflow.
std::string executable_path(const char* argv0) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) return self.string();
  return std::filesystem::absolute(argv0).lexically_normal().string();
}

// `voroseal run --merge DIR...`: the runs of several output folders as one summary and report.
int merge_study_command(const RunCommand& command, bool json, Logger& log) {
  if (!command.study.empty())
    throw ParameterError("--merge: takes output folders, not a study file ('" + command.study +
                         "' given before --merge)");
  const MergedStudy merged = merge_study_results(command.merge, command.output);
  write_study_reports(merged.outcome);
  const StudyOutcome& outcome = merged.outcome;
  std::string missing;
  for (const int n : merged.missing) missing += (missing.empty() ? "" : ", ") + std::to_string(n);
  if (!missing.empty())
    log.warning("study " + outcome.study.name + ": no result for run " + missing + " (of " +
                std::to_string(outcome.runs.size() + merged.missing.size()) + ")");
  log.info("study " + outcome.study.name + ": " + std::to_string(outcome.runs.size()) +
           " runs merged; report " + outcome.study.output + "/report.html");
  if (json) std::cout << summary_json(outcome).dump(2) << "\n";
  return outcome.exit_code() != kExitOk || !merged.missing.empty() ? kExitInvalid : kExitOk;
}

// `--emit snakemake DIR`: writes DIR/Snakefile.
int emit_study_command(const RunCommand& command, const Study& study,
                       const std::vector<StudyRun>& runs, const SnakemakeOptions& options,
                       Logger& log) {
  if (command.emit[0] != "snakemake")
    throw ParameterError("--emit: unknown workflow format '" + command.emit[0] +
                         "' (known: snakemake)");
  const std::filesystem::path folder = command.emit[1];
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw OutputError(folder.string() + ": " + error.message());
  const std::string file = (folder / "Snakefile").string();
  std::vector<std::string> inputs = study.models;
  inputs.push_back(options.study);
  write_atomically(file, inputs,
                   [&](std::ostream& out) { out << snakefile(study, runs, options); });
  log.info("wrote " + file + " (" + std::to_string(runs.size()) + " runs): cd " + folder.string() +
           " && snakemake -j N");
  return kExitOk;
}

// `voroseal run STUDY.json`: the study's runs, its summary table and report.
int run_study_command(const ModuleRegistry& registry, const RunCommand& command, bool json,
                      int threads, double max_memory_bytes, const char* argv0, Logger& log,
                      Progress& progress) {
  try {
    if (!command.merge.empty()) return merge_study_command(command, json, log);
    if (command.study.empty())
      throw ParameterError("run: a study file is required (or --merge FOLDER...)");
    Study study = read_study(command.study);
    if (!command.output.empty())
      study.output = std::filesystem::absolute(command.output).lexically_normal().string();
    if (command.no_pictures) study.pictures = false;
    const std::vector<StudyRun> all = expand_study(study);
    validate_study(registry, study, all);

    StudyOptions options;
    options.threads = threads;
    options.max_memory_bytes = max_memory_bytes;
    options.resume = command.resume;
    if (!command.shard.empty()) options.runs = shard_runs(all, parse_shard(command.shard));
    if (!command.only.empty()) {
      std::set<int> chosen;
      for (const int n : command.only) {
        if (n < 1 || n > static_cast<int>(all.size()))
          throw ParameterError("--only: there is no run " + std::to_string(n) + " (the study has " +
                               std::to_string(all.size()) + ", numbered from 1)");
        chosen.insert(n - 1);
      }
      options.runs = std::vector<int>(chosen.begin(), chosen.end());
      // Jobs of one study run side by side: each writes its run folder, --merge the summary.
      options.reports = false;
    }
    std::vector<StudyRun> runs;
    for (const int index : options.runs.value_or(std::vector<int>())) runs.push_back(all[index]);
    if (!options.runs) runs = all;

    if (!command.emit.empty()) {
      SnakemakeOptions workflow;
      workflow.voroseal = executable_path(argv0);
      workflow.study = std::filesystem::absolute(command.study).lexically_normal().string();
      workflow.threads = threads > 0 ? threads : 1;
      constexpr double kMiB = 1024.0 * 1024.0;
      if (max_memory_bytes > 0)
        workflow.mem_mb = static_cast<long>(std::ceil(max_memory_bytes / kMiB));
      return emit_study_command(command, study, runs, workflow, log);
    }
    if (command.dry_run) {
      nlohmann::json list = nlohmann::json::array();
      for (const StudyRun& r : runs)
        list.push_back({{"run", r.index + 1},
                        {"model", r.model},
                        {"directory", r.directory},
                        {"swept", r.swept}});
      if (json) {
        std::cout << nlohmann::json{{"study", study.name}, {"output", study.output}, {"runs", list}}
                         .dump(2)
                  << "\n";
      } else {
        std::cout << "study " << study.name << ": " << runs.size() << " runs into " << study.output
                  << "\n";
        for (const StudyRun& r : runs)
          std::cout << "  " << r.index + 1 << "  " << r.model_label << "/" << r.key << "\n";
      }
      return kExitOk;
    }
    const StudyOutcome outcome = run_study(registry, study, options, log, progress);
    if (json) std::cout << summary_json(outcome).dump(2) << "\n";
    return outcome.exit_code();
  } catch (...) {
    return exit_code_for_current_exception(log);
  }
}

}  // namespace

int run_command_line(ModuleRegistry& registry, int argc, char** argv) {
  // External modules first: they become subcommands like the built-in ones.
  const PluginLoadReport plugins = load_plugins_from_environment(registry);

  CLI::App app{"voroseal: remesh 3D structural models (Pellerin et al. 2014) and tet-mesh them with TetGen.\n"
               "Every subcommand below is a module; `voroseal modules` lists their parameters."};
  app.require_subcommand(1);
  app.set_version_flag("--version", kVersion);
  install_signal_cleanup();
  int threads = 0;
  bool quiet = false, verbose = false;
  const int threads_limit = max_threads();
  app.add_option("--threads", threads,
                 "worker threads (0: all cores; 0 to " + std::to_string(threads_limit) + ")")
      ->check(CLI::Range(0, threads_limit));
  std::string max_memory;
  app.add_option("--max-memory", max_memory,
                 "memory a command may plan to use, e.g. 8G (default: the machine's memory, " +
                     memory_text(machine_memory_bytes()) + ")");
  app.add_flag("-q,--quiet", quiet, "no progress and no info lines on stderr: only results, warnings and errors");
  app.add_flag("-v,--verbose", verbose, "debug log on stderr");
  bool json_output = false;
  app.add_flag("--json", json_output, "print the result (module report, study summary) as JSON on stdout");
  // Global options may also follow the subcommand: `voroseal stats m.ts --threads 2`.
  app.fallthrough();

  bool modules_json = false;
  CLI::App* list = app.add_subcommand("modules", "list the modules and their parameters");
  list->add_flag("--json", modules_json, "as JSON");

  RunCommand run_command;
  CLI::App* study = app.add_subcommand("run", "run a study: a pipeline of modules over models with parameter "
                                              "sweeps, a summary table and an HTML report (docs/studies.md)");
  study->add_option("study", run_command.study, "study file (.json)");
  study->add_option("-o,--output", run_command.output,
                    "output folder (default: the study's \"output\")");
  study->add_flag("--no-pictures", run_command.no_pictures,
                  "do not render the pictures of each run (surfaces, tet cut)");
  CLI::Option* dry_run = study->add_flag("--dry-run", run_command.dry_run,
                                         "check the study and list its runs without running them");
  CLI::Option* shard =
      study->add_option("--shard", run_command.shard,
                        "run shard I of N only: the runs numbered I, I+N, I+2N, ... (1 <= I <= N)");
  shard->type_name("I/N");
  CLI::Option* only =
      study->add_option("--only", run_command.only,
                        "run these runs only (numbers as in the summary, e.g. 3,7); no summary: "
                        "put the run folders together with --merge");
  only->delimiter(',')->type_name("N[,N...]")->excludes(shard);
  CLI::Option* resume = study->add_flag(
      "--resume", run_command.resume,
      "keep the runs already complete in the output folder (ok or invalid, outputs present)");
  CLI::Option* emit = study->add_option(
      "--emit", run_command.emit,
      "write a workflow running the study instead: `--emit snakemake DIR` writes DIR/Snakefile");
  emit->expected(2)
      ->type_name("FORMAT DIR")
      ->excludes(shard)
      ->excludes(only)
      ->excludes(resume)
      ->excludes(dry_run);
  study
      ->add_option("--merge", run_command.merge,
                   "one summary and report from the runs in these output folders (shards, jobs)")
      ->expected(1, -1)
      ->type_name("DIR...")
      ->excludes(shard)
      ->excludes(only)
      ->excludes(resume)
      ->excludes(emit)
      ->excludes(dry_run);

  // Reading options shared by every module that reads a model.
  double feature_angle = 0.0, weld_tolerance = 1e-7;
  std::string corner_rule = "incidence";

  std::vector<ModuleCommand> commands;
  commands.reserve(registry.modules().size());
  for (const Module* module : registry.modules()) {
    commands.emplace_back();
    ModuleCommand& c = commands.back();
    c.module = module;
    c.app = app.add_subcommand(module->name(), module->description());
    if (module->needs_model()) {
      c.app->add_option("model", c.input, "model file (.ml .ts .obj .mesh)")->required();
      c.app->add_option("--feature-angle", feature_angle,
                        "split a surface where it folds more than this (degrees); for soups without groups")
          ->check(CLI::Range(0.0, 180.0));
      c.app
          ->add_option("--weld-tolerance", weld_tolerance,
                       "welding distance relative to the bbox diagonal (0 to 0.1)")
          ->check(CLI::Range(0.0, 0.1));
      c.app->add_option("--corner-rule", corner_rule,
                        "incidence (RINGMesh: a corner where the set of touching surfaces changes, one per "
                        "closed contact) or signature (meshreport)")
          ->check(CLI::IsMember({"incidence", "signature"}));
    }
    for (const ParameterSpec& spec : module->parameters()) {
      std::string doc = spec.doc;
      const std::string d = default_text(spec);
      if (!d.empty()) doc += " (default " + d + ")";
      const std::string range = range_text(spec);
      if (!range.empty()) doc += " (" + range + ")";
      if (spec.type == ParameterType::Bool) {
        // --name switches it on, --no-name off (for parameters that default to true).
        c.bool_options[spec.name] = c.app->add_flag("--" + spec.name + ",!--no-" + spec.name, c.flags[spec.name], doc);
        continue;
      }
      // A positional parameter may also be named, as `voroseal modules` lists it.
      std::string names = spec.positional ? spec.name + ",--" + spec.name : "--" + spec.name;
      if (!spec.short_name.empty()) names = "-" + spec.short_name + "," + names;
      CLI::Option* o = c.app->add_option(names, c.values[spec.name], doc);
      o->type_name(type_text(spec));
      if (spec.required) o->required();
      if (spec.repeatable) o->multi_option_policy(CLI::MultiOptionPolicy::Join);
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUnreadable;
  }

  Logger log(quiet ? LogLevel::Warning : verbose ? LogLevel::Debug : LogLevel::Info);
  for (const std::string& error : plugins.errors) log.error(error + " (skipped)");
  for (const std::string& library : plugins.loaded) log.debug("plugin " + library);
  if (list->parsed()) {
    print_modules(registry, modules_json || json_output);
    return kExitOk;
  }
  if (threads > 0) omp_set_num_threads(threads);
  double max_memory_bytes = 0.0;
  if (!max_memory.empty()) {
    try {
      max_memory_bytes = parse_memory_size(max_memory);
    } catch (const ParameterError& e) {
      log.error(e.what());
      return kExitUnreadable;
    }
  }

  Progress progress(progress_display(quiet));
  if (study->parsed())
    return run_study_command(registry, run_command, json_output, threads, max_memory_bytes, argv[0],
                             log, progress);
  Context context(log, progress);
  context.threads = threads;
  context.max_memory_bytes = max_memory_bytes;
  for (ModuleCommand& c : commands) {
    if (!c.app->parsed()) continue;
    ModuleRun run;
    run.module = c.module->name();
    run.input = c.input;
    run.read.build.feature_angle_deg = feature_angle;
    run.read.build.weld_tolerance = weld_tolerance;
    run.read.build.corner_rule = corner_rule == "signature" ? CornerRule::Signature : CornerRule::Incidence;
    for (const ParameterSpec& spec : c.module->parameters()) {
      if (spec.type == ParameterType::Bool) {
        if (c.bool_options[spec.name]->count() > 0) run.parameters[spec.name] = c.flags[spec.name];
      } else if (c.app->count("--" + spec.name) > 0) {
        run.parameters[spec.name] = c.values[spec.name];
      }
    }
    // A module that prints its own JSON (a bool parameter "json") is asked to; for the others
    // the CLI prints the context report.
    bool module_prints_json = false;
    for (const ParameterSpec& spec : c.module->parameters())
      module_prints_json = module_prints_json || (spec.name == "json" && spec.type == ParameterType::Bool);
    if (json_output && module_prints_json) run.parameters["json"] = true;
    const int code = run_module_reporting(registry, run, context);
    if (json_output && !module_prints_json) std::cout << context.report.dump(2) << "\n";
    return code;
  }
  return kExitUnreadable;
}

}  // namespace voroseal
