// Running modules the way the CLI, pipelines and the Python binding do: read the model when the
// module needs one, run the module, map errors to exit codes.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "framework/host/context.h"
#include "framework/host/registry.h"
#include "io/model_io.h"

namespace voroseal {

/// Exit codes of voroseal (documented in docs/user-guide.md).
enum ExitCode : int {
  kExitOk = 0,
  kExitInvalid = 1,     // the model is not valid (check), meshing failed, output not written
  kExitUnreadable = 2,  // unreadable input or bad command line
  kExitInternal = 3,    // a bug
};

struct ModuleRun {
  std::string module;
  std::string input;                                   // model file ("" when not needed)
  nlohmann::json parameters = nlohmann::json::object();  // name -> value (strings accepted)
  ReadOptions read;
};

/// Reads the input into the context (input and a working copy as model).
/// \throws InputError, ModelError
void load_model(Context& context, const std::string& path, const ReadOptions& options);
/// Reads `path` into context.volume when it holds tets (read_tets_if_any); false otherwise.
bool load_volume_mesh(Context& context, const std::string& path);

/// Validates the parameters and runs the module on the context (loading the input first when
/// the module needs a model and the context has none). Exceptions propagate.
void run_module(const ModuleRegistry& registry, const ModuleRun& run, Context& context);

/// run_module() with every error caught, reported on the logger, and turned into an exit code.
int run_module_reporting(const ModuleRegistry& registry, const ModuleRun& run, Context& context);

/// The exit code and message for the exception being handled (call inside a catch block).
int exit_code_for_current_exception(const Logger& log);

}  // namespace voroseal
