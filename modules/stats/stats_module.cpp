// `voroseal stats MODEL [--ref INPUT]`: the quality table of the current model (Table 2 of the
// seed paper), with the Hausdorff distance to a reference. Text table on stdout, or one JSON
// object with --json; the same object goes to context.report["stats"].
#include <cstdio>

#include "framework/host/module.h"
#include "framework/host/registry.h"
#include "io/model_io.h"
#include "modules/stats/model_statistics.h"

namespace voroseal {

namespace {

class StatsModule : public Module {
 public:
  std::string name() const override { return "stats"; }
  std::string description() const override {
    return "quality table (Table 2 of the seed paper), Hausdorff distance with --ref";
  }
  std::vector<ParameterSpec> parameters() const override {
    ParameterSpec ref{"ref", ParameterType::Path, nullptr, "reference model: adds the two-sided Hausdorff distance"};
    ParameterSpec json{"json", ParameterType::Bool, false, "print one JSON object instead of the table"};
    ParameterSpec samples{"samples", ParameterType::Int, 200000, "sample points per surface for the distance"};
    samples.min = 1;
    ParameterSpec seed{"seed", ParameterType::Int, 1, "seed of the random sample points"};
    seed.min = 0;
    return {ref, json, samples, seed};
  }

  void run(Context& context, const Parameters& parameters) const override {
    const StructuralModel& model = *context.model;
    ModelStatistics statistics = measure_model(model);
    if (statistics.model.empty()) statistics.model = context.input_path;
    FidelityStatistics fidelity;
    ModelStatistics reference_statistics;
    const bool with_ref = parameters.has("ref");
    if (with_ref) {
      const std::string path = parameters.get_string("ref");
      const StructuralModel reference = read_model(path);
      reference_statistics = measure_model(reference);
      if (reference_statistics.model.empty()) reference_statistics.model = path;
      context.log.info("stats: Hausdorff distance to " + path);
      fidelity = hausdorff(model, reference, static_cast<size_t>(parameters.get_int("samples")),
                           static_cast<uint64_t>(parameters.get_int("seed")));
    }
    nlohmann::json json =
        to_json(statistics, with_ref ? &fidelity : nullptr, with_ref ? &reference_statistics : nullptr);
    // Hook for volume statistics: when a previous step (tetmesh) left a volume mesh in
    // context.volume, its figures belong here under json["volume"] (measure_volume() of
    // modules/tetmesh/volume_quality.h); wired by the pipeline owner to keep stats independent of
    // the tetmesh module.
    context.report["stats"] = json;
    if (parameters.get_bool("json"))
      std::printf("%s\n", json.dump(2).c_str());
    else
      std::fputs(
          to_table(statistics, with_ref ? &fidelity : nullptr, with_ref ? &reference_statistics : nullptr).c_str(),
          stdout);
    std::fflush(stdout);
  }
};

}  // namespace

}  // namespace voroseal

void voroseal_register_stats(voroseal::ModuleRegistry& registry) {
  registry.add(std::make_unique<voroseal::StatsModule>());
}
