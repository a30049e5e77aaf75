// An example external module, built as a shared library (a CMake MODULE library) and loaded
// with dlopen from VOROSEAL_PLUGIN_PATH. It moves the model in file coordinates by shifting its
// frame origin (the local coordinates do not change), and reports what it did.
//
// Build your own the same way: derive voroseal::Module, export voroseal_register_plugin with C
// linkage, link voroseal_framework, and put the .so in a directory of VOROSEAL_PLUGIN_PATH.
#include <memory>

#include "framework/core/error.h"
#include "framework/host/module.h"
#include "framework/host/registry.h"

namespace {

class ExampleOffsetModule : public voroseal::Module {
 public:
  std::string name() const override { return "example-offset"; }
  std::string description() const override { return "example plugin: move the model by (dx, dy, dz)"; }
  std::vector<voroseal::ParameterSpec> parameters() const override {
    using voroseal::ParameterType;
    return {{"dx", ParameterType::Double, 0.0, "shift along x"},
            {"dy", ParameterType::Double, 0.0, "shift along y"},
            {"dz", ParameterType::Double, 0.0, "shift along z"}};
  }
  void run(voroseal::Context& context, const voroseal::Parameters& parameters) const override {
    if (!context.model) throw voroseal::ModelError("example-offset needs a model");
    const voroseal::Vec3 shift(parameters.get_double("dx"), parameters.get_double("dy"), parameters.get_double("dz"));
    // Models in the context are immutable: a step makes a changed copy and replaces it.
    auto moved = std::make_shared<voroseal::StructuralModel>(*context.model);
    moved->frame.origin += shift;
    context.model = moved;
    context.report["example-offset"] = {{"offset", {shift.x(), shift.y(), shift.z()}},
                                        {"triangles", context.model->num_triangles()}};
    context.log.info("example-offset: moved the model by " + std::to_string(shift.norm()));
  }
};

}  // namespace

extern "C" void voroseal_register_plugin(voroseal::ModuleRegistry& registry) {
  registry.add(std::make_unique<ExampleOffsetModule>());
}
