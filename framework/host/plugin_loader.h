// External modules: shared libraries that register modules into a ModuleRegistry. A plugin
// exports
//     extern "C" void voroseal_register_plugin(voroseal::ModuleRegistry& registry);
// which calls registry.add(...) like a built-in module does. The CLI and the Python module load
// every *.so found in the directories of VOROSEAL_PLUGIN_PATH (':'-separated) at start.
//
// A loaded library stays loaded for the life of the process: the registry holds objects whose
// code lives in it, so it is never unloaded.
#pragma once

#include <string>
#include <vector>

#include "framework/host/registry.h"

namespace voroseal {

/// The symbol a plugin library exports.
inline constexpr const char* kPluginEntryPoint = "voroseal_register_plugin";
/// The environment variable listing plugin directories.
inline constexpr const char* kPluginPathVariable = "VOROSEAL_PLUGIN_PATH";

/// Loads one plugin library and lets it register its modules. Returns the names of the modules
/// it added.
/// \throws InputError when the library cannot be loaded or does not export
///         voroseal_register_plugin; ParameterError when it registers a module name that is
///         already taken (modules it added before that stay registered).
std::vector<std::string> load_plugin(ModuleRegistry& registry, const std::string& library);

/// The plugin libraries (*.so, sorted by name within a directory) in the directories of a
/// ':'-separated search path. Entries that do not exist are skipped; a file entry is taken as
/// a library itself.
std::vector<std::string> find_plugin_libraries(const std::string& search_path);

/// What loading the libraries of a search path did.
struct PluginLoadReport {
  std::vector<std::string> loaded;  // library paths
  std::vector<std::string> modules;  // module names added
  std::vector<std::string> errors;   // one message per library that failed
};

/// Loads every library of the search path; a library that fails is reported in `errors` and the
/// others are still loaded.
PluginLoadReport load_plugins(ModuleRegistry& registry, const std::string& search_path);

/// load_plugins() on $VOROSEAL_PLUGIN_PATH (nothing when unset or empty).
PluginLoadReport load_plugins_from_environment(ModuleRegistry& registry);

}  // namespace voroseal
