#include "framework/cli/command_line.h"

#include <omp.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <map>

#include "framework/core/error.h"
#include "framework/host/runner.h"

namespace voroseal {

namespace {

constexpr const char* kVersion = "0.1.0";

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
                          {"required", p.required}});
      out.push_back({{"name", m->name()}, {"description", m->description()}, {"parameters", params}});
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
  for (const Module* m : registry.modules()) {
    std::cout << m->name() << "  " << m->description() << "\n";
    for (const ParameterSpec& p : m->parameters()) {
      std::cout << "    --" << p.name << " <" << type_text(p) << ">";
      const std::string d = default_text(p);
      if (!d.empty()) std::cout << " (default " << d << ")";
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
};

}  // namespace

int run_command_line(const ModuleRegistry& registry, int argc, char** argv) {
  CLI::App app{"voroseal: remesh 3D structural models (Pellerin et al. 2014) and tet-mesh them with TetGen.\n"
               "Every subcommand below is a module; `voroseal modules` lists their parameters."};
  app.require_subcommand(1);
  app.set_version_flag("--version", kVersion);
  int threads = 0;
  bool quiet = false, verbose = false;
  app.add_option("--threads", threads, "worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
  app.add_flag("-q,--quiet", quiet, "no progress and no log on stderr, only results and errors");
  app.add_flag("-v,--verbose", verbose, "debug log on stderr");

  bool modules_json = false;
  CLI::App* list = app.add_subcommand("modules", "list the modules and their parameters");
  list->add_flag("--json", modules_json, "as JSON");

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
      c.app->add_option("--weld-tolerance", weld_tolerance, "welding distance relative to the bbox diagonal")
          ->check(CLI::NonNegativeNumber);
      c.app->add_option("--corner-rule", corner_rule,
                        "incidence (RINGMesh: a corner where the set of touching surfaces changes, one per "
                        "closed contact) or signature (meshreport)")
          ->check(CLI::IsMember({"incidence", "signature"}));
    }
    for (const ParameterSpec& spec : module->parameters()) {
      std::string doc = spec.doc;
      const std::string d = default_text(spec);
      if (!d.empty()) doc += " (default " + d + ")";
      if (spec.type == ParameterType::Bool) {
        c.app->add_flag("--" + spec.name, c.flags[spec.name], doc);
        continue;
      }
      std::string names = spec.positional ? spec.name : "--" + spec.name;
      if (!spec.short_name.empty() && !spec.positional) names = "-" + spec.short_name + "," + names;
      CLI::Option* o = c.app->add_option(names, c.values[spec.name], doc);
      o->type_name(type_text(spec));
      if (spec.required) o->required();
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUnreadable;
  }

  if (list->parsed()) {
    print_modules(registry, modules_json);
    return kExitOk;
  }
  if (threads > 0) omp_set_num_threads(threads);

  Logger log(quiet ? LogLevel::Warning : verbose ? LogLevel::Debug : LogLevel::Info);
  Progress progress(!quiet && stderr_is_terminal());
  Context context(log, progress);
  context.threads = threads;
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
        if (c.flags[spec.name]) run.parameters[spec.name] = true;
      } else if (c.app->count(spec.positional ? spec.name : "--" + spec.name) > 0) {
        run.parameters[spec.name] = c.values[spec.name];
      }
    }
    return run_module_reporting(registry, run, context);
  }
  return kExitUnreadable;
}

}  // namespace voroseal
