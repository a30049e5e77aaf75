#include <unistd.h>

#include <cstdlib>

#include "framework/cli/command_line.h"
#include "framework/host/registry.h"

namespace {

// OpenMP threads wait passively between parallel regions, so that on a machine shared with other
// jobs they do not spin on cores those jobs need (a loaded run is then faster, not slower).
// libgomp reads OMP_WAIT_POLICY once, when it is loaded: the policy is set in the environment and
// the program executed again. A policy the user set is kept; if the exec fails, the run goes on.
void wait_passively_between_parallel_regions(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
}

}  // namespace

int main(int argc, char** argv) {
  wait_passively_between_parallel_regions(argv);
  voroseal::ModuleRegistry registry;
  voroseal::register_builtin_modules(registry);
  return voroseal::run_command_line(registry, argc, argv);
}
