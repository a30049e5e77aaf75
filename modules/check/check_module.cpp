// `voroseal check MODEL`: is the model sealed and valid for gridding? Prints a report (or one
// JSON object with --json) on stdout; the run's exit code is 1 when the model is invalid.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "framework/core/error.h"
#include "framework/host/module.h"
#include "framework/host/registry.h"
#include "io/model_io.h"
#include "modules/check/model_validity.h"
#include "modules/check/volume_validity.h"

namespace voroseal {

namespace {

// The tets of `path` when it is a volume mesh file holding some, else none.
VolumeMesh tets_in(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".mesh" && ext != ".vtu" && ext != ".msh") return {};
  try {
    return read_volume_mesh(path);
  } catch (const InputError&) {
    return {};  // surfaces only: the model checks say it all
  }
}

class CheckModule : public Module {
 public:
  std::string name() const override { return "check"; }
  std::string description() const override {
    return "sealing and validity report (exit code 1 when the model is invalid)";
  }
  std::vector<ParameterSpec> parameters() const override {
    const CheckOptions defaults;
    ParameterSpec json{"json", ParameterType::Bool, false, "print one JSON object instead of the text report"};
    ParameterSpec short_edge{"short-edge", ParameterType::Double, defaults.short_edge_relative,
                             "edges shorter than this times the bbox diagonal are errors"};
    short_edge.min = 0;
    short_edge.max = 1;
    ParameterSpec area{"degenerate-area", ParameterType::Double, defaults.degenerate_area_relative,
                       "triangles with less area than this times diagonal^2 are near-degenerate (warnings)"};
    area.min = 0;
    area.max = 1;
    ParameterSpec angle{"min-angle", ParameterType::Double, defaults.min_angle_warning_deg,
                        "triangles with an angle below this (degrees) are warnings"};
    angle.min = 0;
    angle.max = 60;
    ParameterSpec wedge{"min-wedge", ParameterType::Double, defaults.thin_wedge_warning_deg,
                        "surfaces meeting at less than this (degrees) inside a region, and free "
                        "borders leaving a surface at less than this past the corner where they "
                        "meet, are warnings: where tet meshes keeping them get flat tets"};
    wedge.min = 0;
    wedge.max = 90;
    ParameterSpec intersections{"intersections", ParameterType::Bool, true,
                                "test triangle pairs for intersections, the most expensive check "
                                "(--no-intersections skips it)"};
    ParameterSpec examples{"examples", ParameterType::Int, defaults.max_examples, "examples listed per failed check"};
    examples.min = 0;
    examples.max = 100000;
    return {json, short_edge, area, angle, wedge, intersections, examples};
  }

  void run(Context& context, const Parameters& parameters) const override {
    CheckOptions options;
    options.short_edge_relative = parameters.get_double("short-edge");
    options.degenerate_area_relative = parameters.get_double("degenerate-area");
    options.min_angle_warning_deg = parameters.get_double("min-angle");
    options.thin_wedge_warning_deg = parameters.get_double("min-wedge");
    options.intersections = parameters.get_bool("intersections");
    options.max_examples = static_cast<int>(parameters.get_int("examples"));
    ValidityReport report = check_model(*context.model, options);
    if (report.model.empty()) report.model = context.input_path;
    // A volume mesh given as the input: its tets are checked too (the model is its surfaces).
    const VolumeMesh volume =
        context.input_path.empty() ? VolumeMesh{} : tets_in(context.input_path);
    if (!volume.tets.empty())
      for (CheckEntry& e : check_volume_mesh(volume, options.max_examples))
        report.checks.push_back(std::move(e));
    const nlohmann::json json = to_json(report);
    context.report["check"] = json;
    if (parameters.get_bool("json"))
      std::printf("%s\n", json.dump(2).c_str());
    else
      std::fputs(to_text(report).c_str(), stdout);
    std::fflush(stdout);
    if (!report.valid()) context.exit_code = std::max(context.exit_code, 1);
  }
};

}  // namespace

}  // namespace voroseal

void voroseal_register_check(voroseal::ModuleRegistry& registry) {
  registry.add(std::make_unique<voroseal::CheckModule>());
}
