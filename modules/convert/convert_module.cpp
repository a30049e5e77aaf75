// `voroseal convert IN OUT`: rewrites a model in another format, keeping the structure the target
// format can hold (.ml keeps regions and layers; other formats keep surface parts as groups).
#include "framework/host/module.h"
#include "framework/host/registry.h"
#include "io/model_io.h"

namespace voroseal {

namespace {

class ConvertModule : public Module {
 public:
  std::string name() const override { return "convert"; }
  std::string description() const override { return "convert a model between file formats"; }
  std::vector<ParameterSpec> parameters() const override {
    ParameterSpec output{"output", ParameterType::Path, nullptr, "output file; format from its extension"};
    output.required = true;
    output.positional = true;
    output.short_name = "o";
    output.output = true;
    output.extensions = writable_model_extensions();
    return {output};
  }
  void run(Context& context, const Parameters& parameters) const override {
    const std::string out = parameters.get_string("output");
    write_model(*context.model, out, WriteOptions{{context.input_path}});
    context.report["convert"] = {{"input", context.input_path}, {"output", out}};
    context.log.info("wrote " + out);
  }
};

}  // namespace

}  // namespace voroseal

void voroseal_register_convert(voroseal::ModuleRegistry& registry) {
  registry.add(std::make_unique<voroseal::ConvertModule>());
}
