#include "framework/cli/command_line.h"
#include "framework/host/registry.h"

int main(int argc, char** argv) {
  voroseal::ModuleRegistry registry;
  voroseal::register_builtin_modules(registry);
  return voroseal::run_command_line(registry, argc, argv);
}
