// `voroseal stats MODEL [--ref INPUT]`: the quality table of the current model (Table 2 of the
// seed paper), with the Hausdorff distance to a reference. Text table on stdout, or one JSON
// object with --json; the same object goes to context.report["stats"].
#include <cstdio>
#include <filesystem>

#include "framework/core/error.h"
#include "framework/geometry/volume_quality.h"
#include "framework/host/memory_budget.h"
#include "framework/host/module.h"
#include "framework/host/parameter_limits.h"
#include "framework/host/registry.h"
#include "io/model_io.h"
#include "modules/stats/model_statistics.h"

namespace voroseal {

namespace {

// Memory of one sample point of the Hausdorff distance (its position, the triangle it lies on
// and its distance): both surfaces are sampled.
constexpr double kBytesPerSample = 64.0;

// The tetrahedral mesh in `path`, or null when the file holds none (or is not a volume format).
std::shared_ptr<const VolumeMesh> volume_in(const std::string& path) {
  if (path.empty()) return nullptr;
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".mesh" && ext != ".vtu" && ext != ".msh" && ext != ".node" && ext != ".ele") return nullptr;
  try {
    auto mesh = std::make_shared<VolumeMesh>(read_volume_mesh(path));
    return mesh->tets.empty() ? nullptr : mesh;
  } catch (const InputError&) {
    return nullptr;  // a surface-only file: the model statistics say it all
  }
}

nlohmann::json volume_json(const VolumeMesh& mesh, const VolumeQuality& q) {
  nlohmann::json regions = nlohmann::json::array();
  for (size_t r = 0; r < q.region_volume.size(); ++r) {
    if (q.region_tets[r] == 0) continue;
    regions.push_back({{"id", r},
                       {"name", r < mesh.region_names.size() ? mesh.region_names[r] : std::to_string(r)},
                       {"tets", q.region_tets[r]},
                       {"volume", q.region_volume[r]}});
  }
  nlohmann::json census = nlohmann::json::object();  // {"5": n, "10": n, ...}
  for (size_t i = 0; i < kDihedralCensusDeg.size(); ++i)
    census[std::to_string(static_cast<int>(kDihedralCensusDeg[i]))] = q.tets_below_deg[i];
  return {{"vertices", q.vertices},
          {"tets", q.tets},
          {"regions", q.regions},
          {"min_dihedral_deg", q.min_dihedral_deg},
          {"max_dihedral_deg", q.max_dihedral_deg},
          {"tets_below_deg", census},
          {"max_radius_edge", q.max_radius_edge},
          {"mean_radius_edge", q.mean_radius_edge},
          {"nonpositive_tets", q.nonpositive_tets},
          {"repeated_vertex_tets", q.repeated_vertex_tets},
          {"total_volume", q.total_volume},
          {"triangles_not_in_tets", q.nonconforming_triangles},
          {"region_volumes", regions}};
}

std::string volume_table(const VolumeMesh& mesh, const VolumeQuality& q) {
  std::string out;
  char line[384];
  // The share of tets under 15°, the bound of "well-shaped" tets.
  const long under = q.tets_below_deg[kCensusBin15Deg];
  const double under_15 = q.tets > 0 ? 100.0 * under / q.tets : 0.0;
  std::snprintf(line, sizeof line,
                "volume: %ld tets, %ld vertices, %d regions; dihedral min %.2f max %.2f deg, "
                "%ld tets (%.3f %%) under 15 deg; radius-edge max %.3g mean %.3g; %ld flat or "
                "inverted tets; %ld tets with a repeated vertex; %ld surface triangles not on a "
                "tet\n",
                q.tets, q.vertices, q.regions, q.min_dihedral_deg, q.max_dihedral_deg, under,
                under_15, q.max_radius_edge, q.mean_radius_edge, q.nonpositive_tets,
                q.repeated_vertex_tets, q.nonconforming_triangles);
  out += line;
  for (size_t r = 0; r < q.region_volume.size(); ++r) {
    if (q.region_tets[r] == 0) continue;
    const std::string name = r < mesh.region_names.size() ? mesh.region_names[r] : std::to_string(r);
    std::snprintf(line, sizeof line, "  region %-24s %9ld tets  volume %.6g\n", name.c_str(), q.region_tets[r],
                  q.region_volume[r]);
    out += line;
  }
  return out;
}

class StatsModule : public Module {
 public:
  std::string name() const override { return "stats"; }
  std::string description() const override {
    return "quality table (Table 2 of the seed paper), Hausdorff distance with --ref, tet quality of volume meshes";
  }
  std::vector<ParameterSpec> parameters() const override {
    ParameterSpec ref{"ref", ParameterType::Path, nullptr, "reference model: adds the two-sided Hausdorff distance"};
    ParameterSpec json{"json", ParameterType::Bool, false, "print one JSON object instead of the table"};
    ParameterSpec samples{"samples", ParameterType::Int, 200000, "sample points per surface for the distance"};
    samples.min = 1;
    samples.max = kMaxCount;
    ParameterSpec seed{"seed", ParameterType::Int, 1, "seed of the random sample points"};
    seed.min = 0;
    seed.max = kMaxRandomSeed;
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
      const long samples = parameters.get_int("samples");
      require_memory(context, 2.0 * kBytesPerSample * static_cast<double>(samples),
                     "stats --samples " + std::to_string(samples));
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
    // A volume mesh: the one a previous step (tetmesh) made, or the input file when it holds
    // tetrahedra (a .mesh, .vtu, .msh or TetGen file written by tetmesh).
    std::shared_ptr<const VolumeMesh> volume = context.volume;
    if (!volume) volume = volume_in(context.input_path);
    if (volume) json["volume"] = volume_json(*volume, measure_volume(*volume));
    context.report["stats"] = json;
    if (parameters.get_bool("json")) {
      std::printf("%s\n", json.dump(2).c_str());
    } else {
      std::fputs(
          to_table(statistics, with_ref ? &fidelity : nullptr, with_ref ? &reference_statistics : nullptr).c_str(),
          stdout);
      if (volume) std::fputs(volume_table(*volume, measure_volume(*volume)).c_str(), stdout);
    }
    std::fflush(stdout);
  }
};

}  // namespace

}  // namespace voroseal

void voroseal_register_stats(voroseal::ModuleRegistry& registry) {
  registry.add(std::make_unique<voroseal::StatsModule>());
}
