// One module registered in its own registry, and a quiet context to run it on: the set-up every
// module test needs.
#pragma once

#include <string>

#include "framework/host/context.h"
#include "framework/host/registry.h"

namespace voroseal::test {

struct ModuleHarness {
  /// `register_module` is the module's registration function (voroseal_register_<name>).
  ModuleHarness(void (*register_module)(ModuleRegistry&), const std::string& name)
      : module((register_module(registry), registry.get(name))) {}
  ModuleHarness(const ModuleHarness&) = delete;
  ModuleHarness& operator=(const ModuleHarness&) = delete;

  ModuleRegistry registry;  // declared first: `module` refers into it
  Logger log{LogLevel::Quiet};
  Progress progress{false};
  Context context{log, progress};
  const Module& module;
};

}  // namespace voroseal::test
