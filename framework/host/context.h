// Context: what the steps of a run share: the current model, the volume mesh, the report.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/host/log.h"
#include "framework/model/structural_model.h"
#include "framework/model/volume_mesh.h"

namespace voroseal {

class ModuleRegistry;

struct Context {
  /// The logger then keeps its lines off the progress line (Logger::attach).
  Context(Logger& logger, Progress& progress) : log(logger), progress(progress) {
    logger.attach(&progress);
  }

  std::string input_path;                       // the model file read, if any
  std::shared_ptr<const StructuralModel> input;  // the model as read (reference for fidelity)
  /// The current model; steps replace it, never change it (it may be `input` itself).
  std::shared_ptr<const StructuralModel> model;
  std::shared_ptr<VolumeMesh> volume;            // set by tetmesh
  nlohmann::json report = nlohmann::json::object();  // report[module name] = its results
  int threads = 0;                              // 0: all cores
  double max_memory_bytes = 0;                  // 0: the machine's memory (memory_budget.h)
  int exit_code = 0;                            // a step may set a non-zero verdict (check)
  /// The modules of this run, so that a module can chain another one by name (remesh
  /// --tetmesh runs the tetmesh module) without linking it. Set by the runner; may be null.
  const ModuleRegistry* registry = nullptr;
  Logger& log;
  Progress& progress;
};

}  // namespace voroseal
