// The voroseal command line, built from the module registry: each module is a subcommand whose
// options are its declared parameters. Nothing here knows a module by name.
#pragma once

#include "framework/host/registry.h"

namespace voroseal {

/// Parses argv, runs the chosen module and returns the process exit code.
int run_command_line(const ModuleRegistry& registry, int argc, char** argv);

}  // namespace voroseal
