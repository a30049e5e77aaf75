#include "framework/host/runner.h"

#include <exception>
#include <optional>
#include <utility>

#include "framework/core/error.h"
#include "framework/host/output_paths.h"

namespace voroseal {

void load_model(Context& context, const std::string& path, const ReadOptions& options) {
  auto model = std::make_shared<StructuralModel>(read_model(path, options));
  context.input_path = path;
  context.input = model;
  context.model = model;  // shared: steps replace the current model, never change it
}

bool load_volume_mesh(Context& context, const std::string& path) {
  std::optional<VolumeMesh> mesh = read_tets_if_any(path);
  if (!mesh) return false;
  context.volume = std::make_shared<VolumeMesh>(std::move(*mesh));
  context.input_path = path;
  return true;
}

void run_module(const ModuleRegistry& registry, const ModuleRun& run, Context& context) {
  const Module& module = registry.get(run.module);
  context.registry = &registry;
  const Parameters parameters(module.parameters(), run.parameters);
  check_output_paths(module.parameters(), parameters,
                     {context.input_path.empty() ? run.input : context.input_path});
  if (module.needs_model() && !context.model && !(module.reads_volume_mesh() && context.volume)) {
    if (run.input.empty()) throw ParameterError(run.module + ": a model file is required");
    if (!(module.reads_volume_mesh() && load_volume_mesh(context, run.input)))
      load_model(context, run.input, run.read);
  }
  module.run(context, parameters);
}

int exit_code_for_current_exception(const Logger& log) {
  try {
    throw;
  } catch (const InputError& e) {
    log.error(e.what());
    return kExitUnreadable;
  } catch (const ParameterError& e) {
    log.error(e.what());
    return kExitUnreadable;
  } catch (const ModelError& e) {
    log.error(std::string("invalid model: ") + e.what());
    return kExitInvalid;
  } catch (const MesherError& e) {
    log.error(std::string("meshing failed: ") + e.what());
    return kExitInvalid;
  } catch (const OutputError& e) {
    log.error(std::string("cannot write: ") + e.what());
    return kExitInvalid;
  } catch (const std::bad_alloc&) {
    log.error("out of memory");
    return kExitInternal;
  } catch (const std::exception& e) {
    log.error(std::string("internal error: ") + e.what());
    return kExitInternal;
  }
}

int run_module_reporting(const ModuleRegistry& registry, const ModuleRun& run, Context& context) {
  try {
    run_module(registry, run, context);
    return context.exit_code;
  } catch (...) {
    return exit_code_for_current_exception(context.log);
  }
}

}  // namespace voroseal
