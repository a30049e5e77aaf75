// ModuleRegistry: the modules a program knows. Built-in modules are registered by a generated
// function (see framework/host/CMakeLists.txt); external ones are loaded from shared libraries.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "framework/host/module.h"

namespace voroseal {

class ModuleRegistry {
 public:
  /// \throws ParameterError when a module of that name is already registered.
  void add(std::unique_ptr<Module> module);
  /// nullptr when unknown.
  const Module* find(const std::string& name) const;
  /// \throws ParameterError naming the known modules when unknown.
  const Module& get(const std::string& name) const;
  std::vector<const Module*> modules() const;  // sorted by name

 private:
  std::vector<std::unique_ptr<Module>> modules_;
};

/// Registers the modules compiled into voroseal (check, stats, remesh, tetmesh, ...).
void register_builtin_modules(ModuleRegistry& registry);

}  // namespace voroseal
