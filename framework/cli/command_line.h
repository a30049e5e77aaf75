// The voroseal command line, built from the module registry: each module is a subcommand whose
// options are its declared parameters. Nothing here knows a module by name.
#pragma once

#include "framework/host/registry.h"

namespace voroseal {

/// Loads the plugins of $VOROSEAL_PLUGIN_PATH into the registry, parses argv, runs the chosen
/// module (or `run STUDY.json`, `modules`) and returns the process exit code.
int run_command_line(ModuleRegistry& registry, int argc, char** argv);

}  // namespace voroseal
