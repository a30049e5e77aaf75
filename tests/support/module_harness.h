// One module registered in its own registry, and a quiet context to run it on: the set-up every
// module test needs.
#pragma once

#include <cstdio>
#include <string>

#include "framework/host/context.h"
#include "framework/host/registry.h"

namespace voroseal::test {

struct ModuleHarness {
  /// `register_module` is the module's registration function (voroseal_register_<name>); the
  /// log goes to `log_file` at `log_level` (quiet by default).
  ModuleHarness(void (*register_module)(ModuleRegistry&), const std::string& name,
                LogLevel log_level = LogLevel::Quiet, std::FILE* log_file = stderr)
      : log(log_level, log_file), module((register_module(registry), registry.get(name))) {}
  ModuleHarness(const ModuleHarness&) = delete;
  ModuleHarness& operator=(const ModuleHarness&) = delete;

  ModuleRegistry registry;  // declared first: `module` refers into it
  Logger log;
  Progress progress{false};
  Context context{log, progress};
  const Module& module;
};

}  // namespace voroseal::test
