#include "framework/host/registry.h"

#include <algorithm>

#include "framework/core/error.h"

namespace voroseal {

void ModuleRegistry::add(std::unique_ptr<Module> module) {
  if (find(module->name()) != nullptr)
    throw ParameterError("a module named '" + module->name() + "' is already registered");
  modules_.push_back(std::move(module));
}

const Module* ModuleRegistry::find(const std::string& name) const {
  for (const auto& m : modules_)
    if (m->name() == name) return m.get();
  return nullptr;
}

const Module& ModuleRegistry::get(const std::string& name) const {
  if (const Module* m = find(name)) return *m;
  std::string known;
  for (const Module* m : modules()) known += (known.empty() ? "" : ", ") + m->name();
  throw ParameterError("unknown module '" + name + "' (known: " + known + ")");
}

std::vector<const Module*> ModuleRegistry::modules() const {
  std::vector<const Module*> list;
  for (const auto& m : modules_) list.push_back(m.get());
  std::sort(list.begin(), list.end(), [](const Module* a, const Module* b) { return a->name() < b->name(); });
  return list;
}

}  // namespace voroseal
