// The plugin interface: a module is a named step (check, remesh, tetmesh, stats, ...) with
// typed parameters, run on a Context. The CLI subcommands, `voroseal modules`, pipelines and
// the Python binding all come from the registered modules.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "framework/host/context.h"
#include "framework/host/parameters.h"

namespace voroseal {

class Module {
 public:
  virtual ~Module() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;  // one line
  virtual std::vector<ParameterSpec> parameters() const = 0;
  /// True when the module needs a model in the context (read from the positional input).
  virtual bool needs_model() const { return true; }
  /// True when an input holding tets (a volume mesh, TetGen files) is read as a volume mesh into
  /// context.volume instead of as a model (whose reading would keep its triangles only).
  virtual bool reads_volume_mesh() const { return false; }
  /// Runs the step. Reads and updates `context` (model, volume, report).
  /// \throws ParameterError, ModelError, MesherError, InputError, OutputError
  virtual void run(Context& context, const Parameters& parameters) const = 0;
};

}  // namespace voroseal
