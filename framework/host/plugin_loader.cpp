#include "framework/host/plugin_loader.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

#include "framework/core/error.h"

namespace voroseal {

namespace fs = std::filesystem;

std::vector<std::string> load_plugin(ModuleRegistry& registry, const std::string& library) {
  // RTLD_LOCAL: two plugins may carry their own copies of voroseal's static libraries without
  // clashing. Never dlclose'd: the registry keeps objects whose code lives in the library.
  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw InputError(library, 0, std::string("cannot load plugin: ") + (why ? why : "unknown reason"));
  }
  dlerror();
  void* symbol = dlsym(handle, kPluginEntryPoint);
  if (symbol == nullptr) {
    dlclose(handle);  // nothing of it was used
    throw InputError(library, 0,
                     std::string("not a voroseal plugin: it does not export extern \"C\" void ") + kPluginEntryPoint +
                         "(voroseal::ModuleRegistry&)");
  }
  using Entry = void (*)(ModuleRegistry&);
  std::set<std::string> before;
  for (const Module* m : registry.modules()) before.insert(m->name());
  auto names_added = [&] {
    std::vector<std::string> added;
    for (const Module* m : registry.modules())
      if (!before.count(m->name())) added.push_back(m->name());
    return added;
  };
  try {
    reinterpret_cast<Entry>(symbol)(registry);
  } catch (const ParameterError& e) {
    throw ParameterError("plugin " + library + ": " + e.what());
  }
  return names_added();
}

std::vector<std::string> find_plugin_libraries(const std::string& search_path) {
  std::vector<std::string> libraries;
  std::stringstream entries(search_path);
  std::string entry;
  while (std::getline(entries, entry, ':')) {
    if (entry.empty()) continue;
    std::error_code error;
    if (fs::is_regular_file(entry, error)) {
      libraries.push_back(entry);
      continue;
    }
    if (!fs::is_directory(entry, error)) continue;
    std::vector<std::string> found;
    for (const fs::directory_entry& file : fs::directory_iterator(entry, error))
      if (file.is_regular_file(error) && file.path().extension() == ".so") found.push_back(file.path().string());
    std::sort(found.begin(), found.end());
    libraries.insert(libraries.end(), found.begin(), found.end());
  }
  return libraries;
}

PluginLoadReport load_plugins(ModuleRegistry& registry, const std::string& search_path) {
  PluginLoadReport report;
  for (const std::string& library : find_plugin_libraries(search_path)) {
    try {
      const std::vector<std::string> added = load_plugin(registry, library);
      report.loaded.push_back(library);
      report.modules.insert(report.modules.end(), added.begin(), added.end());
    } catch (const std::exception& e) {
      report.errors.push_back(e.what());
    }
  }
  return report;
}

PluginLoadReport load_plugins_from_environment(ModuleRegistry& registry) {
  const char* path = std::getenv(kPluginPathVariable);
  if (path == nullptr || *path == '\0') return {};
  return load_plugins(registry, path);
}

}  // namespace voroseal
