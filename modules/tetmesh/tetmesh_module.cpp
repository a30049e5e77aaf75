// `voroseal tetmesh MODEL -o OUT [--quality 1.5] [--min-dihedral 10] [--max-volume V]`:
// tet-meshes the current model with TetGen, keeping its surfaces (conformal tets), sets
// context.volume and report["tetmesh"], and writes the mesh when an output is given.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "framework/core/error.h"
#include "framework/geometry/volume_quality.h"
#include "framework/host/memory_budget.h"
#include "framework/host/module.h"
#include "framework/host/parameter_limits.h"
#include "framework/host/registry.h"
#include "framework/model/border_gaps.h"
#include "framework/model/contact_wedges.h"
#include "framework/model/size_rules.h"
#include "io/model_io.h"
#include "io/size_field_format.h"
#include "modules/tetmesh/tetrahedralize.h"

namespace voroseal {

namespace {

// Wedges between surfaces, and free borders leaving a surface (border_gaps.h), up to this angle
// are looked for (thinnest_wedge_deg, thinnest_border_gap_deg).
constexpr double kWedgeReportDeg = 30.0;
// Tets with a dihedral angle under this are nearly flat: finite-element and finite-volume
// solvers fail on them or lose their accuracy there, so they are warned about.
constexpr double kFlatTetDeg = 1.0;
// Memory estimate of a --max-volume run: TetGen's quality bound makes tets several times
// smaller than the volume bound, and a tet costs TetGen and the mesh about this many bytes
// (docs/benchmarks.md, "Reliability").
constexpr double kTetsPerBoundVolume = 4.0;
constexpr double kBytesPerTet = 256.0;

// The volume the tets will fill: the regions' (the closed surfaces' when there are none).
double meshed_volume(const StructuralModel& model) {
  double volume = 0.0;
  for (const Region& region : model.regions) volume += std::abs(model.signed_volume(region.sides));
  if (model.regions.empty()) volume = std::abs(model.signed_volume(model.universe.sides));
  return volume;
}

// Σ volume / bound over the regions with a bound: the tets the bounds alone ask for.
double bounded_tets(const StructuralModel& model, const TetmeshOptions& options) {
  if (model.regions.empty()) return meshed_volume(model) / options.volume_bound(0);
  double tets = 0.0;
  for (size_t r = 0; r < model.regions.size(); ++r)
    if (const double bound = options.volume_bound(static_cast<int>(r)); bound > 0.0)
      tets += std::abs(model.signed_volume(model.regions[r].sides)) / bound;
  return tets;
}

// The volume bound per region of `--region-size` rules: a regular tet of edge H, the smallest
// where rules meet. \throws ParameterError for a rule that names no region.
std::vector<double> region_volume_bounds(const StructuralModel& model,
                                         const std::vector<SizeRule>& rules) {
  std::vector<double> bounds(model.regions.size(), 0.0);
  for (const SizeRule& rule : rules) {
    const std::vector<int> regions = regions_named(model, rule.pattern);
    if (regions.empty())
      throw ParameterError("parameter --region-size: '" + rule.pattern +
                           "' names no region or layer of the model (it has " +
                           region_and_layer_names(model) + ")");
    const double volume = std::pow(rule.size, 3) / (6.0 * std::sqrt(2.0));
    for (int r : regions)
      if (bounds[r] == 0.0 || volume < bounds[r]) bounds[r] = volume;
  }
  return bounds;
}

// The tets of `mesh` with a dihedral angle under kFlatTetDeg, and the flattest of them.
struct FlatTets {
  long count = 0;
  long worst = -1;
  double worst_deg = 180.0;
};
FlatTets find_nearly_flat_tets(const VolumeMesh& mesh) {
  FlatTets flat;
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    const Tetrahedron& k = mesh.tets[t];
    const double smallest =
        min_dihedral_angle_deg(mesh.vertices[k[0]], mesh.vertices[k[1]], mesh.vertices[k[2]], mesh.vertices[k[3]]);
    if (smallest >= kFlatTetDeg) continue;
    ++flat.count;
    if (smallest < flat.worst_deg) flat.worst_deg = smallest, flat.worst = static_cast<long>(t);
  }
  return flat;
}

class TetmeshModule : public Module {
 public:
  std::string name() const override { return "tetmesh"; }
  std::string description() const override {
    return "tetrahedral mesh of the model's regions with TetGen, conformal to its surfaces";
  }
  std::vector<ParameterSpec> parameters() const override {
    ParameterSpec output{"output", ParameterType::Path, nullptr,
                         "volume mesh file (.mesh, .vtu, .msh, .node/.ele); not written when absent"};
    output.short_name = "o";
    output.output = true;
    output.extensions = writable_volume_extensions();
    ParameterSpec quality{"quality", ParameterType::Double, 1.5,
                          "maximum radius-edge ratio TetGen refines to (switch q); 0 turns refinement off"};
    quality.min = 0.0;
    quality.max = kMaxRadiusEdge;
    ParameterSpec dihedral{"min-dihedral", ParameterType::Double, 10.0,
                           "minimum dihedral angle in degrees TetGen refines to (q<ratio>/<angle>); 0: "
                           "TetGen's default (none)"};
    dihedral.min = 0.0;
    dihedral.max = 60.0;
    ParameterSpec volume{"max-volume", ParameterType::Double, nullptr,
                         "maximum tet volume in model units^3 (switch a); no bound when absent"};
    volume.min = 0.0;
    volume.max = kMaxModelVolume;
    ParameterSpec region_size{
        "region-size", ParameterType::String, nullptr,
        "target tet edge length in some regions, NAME=H (repeatable, or comma-separated): a "
        "region or layer name (globs); a volume bound H^3/(6 sqrt 2) there (a regular tet of "
        "edge H), the smaller where --max-volume also holds"};
    region_size.repeatable = true;
    ParameterSpec surface_sizes{
        "surface-sizes", ParameterType::Bool, false,
        "tets inside the regions about as large as the surface triangles around them (TetGen's "
        "point sizes, switch m: the mean surface edge at each surface vertex)"};
    ParameterSpec size_field{
        "size-field", ParameterType::Path, nullptr,
        "tet edge lengths at points, a file of 'x y z h' lines or a .vtu point field (as "
        "remesh --size-field), graded away from the points by --gradation; the smaller where "
        "--surface-sizes also holds"};
    ParameterSpec gradation{"gradation", ParameterType::Double, 1.3,
                            "with --size-field: sizes grow by at most this factor per size of "
                            "distance from the field's points"};
    gradation.min = 1.01;
    gradation.max = 10.0;
    ParameterSpec keep{"keep-surface", ParameterType::Bool, true,
                       "TetGen adds no point on the surfaces (switch Y): tets conformal to the surface triangles "
                       "(bisected only by --refine-surface-below)"};
    ParameterSpec slivers{"sliver-passes", ParameterType::Int, 4,
                          "extra TetGen runs with interior points added next to the slivers TetGen leaves by the kept "
                          "surface"};
    slivers.min = 0;
    slivers.max = 10;
    ParameterSpec optimise{"sliver-max-dihedral", ParameterType::Double, 150.0,
                           "TetGen's optimisation flips, smooths and splits tets whose largest dihedral angle "
                           "exceeds this (0, or 90 to 180 degrees; with --quality > 0 and no --max-volume); "
                           "0: TetGen's own thresholds (165/179)"};
    optimise.min = 0.0;
    optimise.max = 179.9;
    ParameterSpec refine{
        "refine-surface-below", ParameterType::Double, TetmeshOptions{}.refine_surface_below_deg,
        "bisect the surface edges under tets flatter than this (degrees) that no interior point "
        "opens (a layer thinner than its triangles) and mesh again, under the flattest first: "
        "same surfaces, finer triangles there; kept when the tets are better; 0 keeps the "
        "surface triangles exactly"};
    refine.min = 0.0;
    refine.max = 60.0;
    ParameterSpec rounds{"refine-surface-rounds", ParameterType::Int,
                         TetmeshOptions{}.refine_surface_rounds,
                         "at most this many surface bisection rounds in each of its sets (under a "
                         "quarter, half and all of --refine-surface-below; each round halves the "
                         "edges it splits)"};
    rounds.min = 0;
    rounds.max = 10;
    ParameterSpec polish{
        "polish-dihedral", ParameterType::Double, TetmeshOptions{}.polish_dihedral_deg,
        "a last TetGen run refining to this dihedral bound (degrees) on the surfaces and points "
        "kept, kept when its smallest dihedral angle is higher, or the same with no more tets "
        "under 15 deg (0: none)"};
    polish.min = 0.0;
    polish.max = 60.0;
    ParameterSpec smooth{
        "smooth", ParameterType::Bool, TetmeshOptions{}.smooth_points,
        "last, move the points of the tets under " +
            std::to_string(static_cast<int>(kSmoothBelowDeg)) +
            " deg to where their tets' smallest dihedral angle is largest (each move kept only "
            "where that angle rises), those on surfaces by --surface-slide"};
    ParameterSpec slide{
        "surface-slide", ParameterType::Double, TetmeshOptions{}.surface_slide,
        "with --smooth, the surface points of those tets slide along their surfaces, the new "
        "surface triangles within this many local edge lengths of the old ones (the output's "
        "surfaces are the slid ones); 0 keeps the surface points where they are"};
    slide.min = 0.0;
    slide.max = kMaxSurfaceSlide;
    ParameterSpec flat_slide{
        "flat-slide", ParameterType::Double, TetmeshOptions{}.flat_surface_slide,
        "then the surface points of the tets left flat slide further, up to this: doubled from "
        "--surface-slide while tets under " +
            std::to_string(static_cast<int>(kSurfaceSideDeg)) +
            " deg remain, then to raise the tets under " +
            std::to_string(static_cast<int>(kSmoothBelowDeg)) +
            " deg (the surfaces move more only there; no point gains a tet under " +
            std::to_string(static_cast<int>(kSmoothBelowDeg)) +
            " deg); not above --surface-slide: no further slide"};
    flat_slide.min = 0.0;
    flat_slide.max = kMaxSurfaceSlide;
    ParameterSpec size{
        "size-rounds", ParameterType::Int, 8,
        "with --max-volume and the surfaces kept: at most this many rounds of bisecting the "
        "surface edges under tets over the bound (TetGen adds no point next to a kept coarse "
        "triangle); the command fails when the bound still does not hold"};
    size.min = 0;
    size.max = kMaxSizeRounds;
    ParameterSpec extra{
        "extra-time", ParameterType::Double, TetmeshOptions{}.extra_time,
        "the sliver passes and surface bisection rounds stop before they would take longer "
        "than this many times the first TetGen run, or " +
            std::to_string(static_cast<int>(kMinExtraSeconds)) +
            " s (0: no limit; the --max-volume rounds are never cut)"};
    extra.min = 0.0;
    extra.max = 1000.0;
    return {output,    quality, dihedral,   volume,   region_size, surface_sizes, size_field,
            gradation, keep,    slivers,    optimise, refine,      rounds,        polish,
            smooth,    slide,   flat_slide, size,     extra};
  }

  void run(Context& context, const Parameters& parameters) const override {
    if (!context.model) throw ModelError("tetmesh needs a model");
    const StructuralModel& model = *context.model;
    TetmeshOptions options;
    options.radius_edge_ratio = parameters.get_double("quality");
    options.min_dihedral_deg = parameters.get_double("min-dihedral");
    if (parameters.has("max-volume")) options.max_volume = parameters.get_double("max-volume");
    if (parameters.has("region-size"))
      options.region_max_volume = region_volume_bounds(
          model, parse_size_rules(parameters.get_string("region-size"), "--region-size"));
    options.surface_sizes = parameters.get_bool("surface-sizes");
    options.gradation = parameters.get_double("gradation");
    if (parameters.has("size-field"))
      options.size_field = load_size_field(parameters.get_string("size-field"), model.frame.origin);
    if (options.bounded()) {
      // Refused before TetGen starts: a tiny bound would run for hours towards billions of tets.
      const double tets = kTetsPerBoundVolume * bounded_tets(model, options);
      char asked[96];
      std::snprintf(asked, sizeof asked, "tetmesh with its volume bounds (%.3g tets)", tets);
      require_memory(context, tets * kBytesPerTet, asked);
    }
    options.keep_surface = parameters.get_bool("keep-surface");
    options.sliver_passes = static_cast<int>(parameters.get_int("sliver-passes"));
    options.sliver_max_dihedral_deg = parameters.get_double("sliver-max-dihedral");
    options.refine_surface_below_deg = parameters.get_double("refine-surface-below");
    options.polish_dihedral_deg = parameters.get_double("polish-dihedral");
    options.refine_surface_rounds = static_cast<int>(parameters.get_int("refine-surface-rounds"));
    options.size_rounds = static_cast<int>(parameters.get_int("size-rounds"));
    options.smooth_points = parameters.get_bool("smooth");
    options.surface_slide = parameters.get_double("surface-slide");
    options.flat_surface_slide = parameters.get_double("flat-slide");
    options.extra_time = parameters.get_double("extra-time");

    const auto start = std::chrono::steady_clock::now();
    ProgressStep tetgen(context.progress, "tetmesh: TetGen");
    TetmeshRun run;
    auto mesh = std::make_shared<VolumeMesh>(tetrahedralize(model, options, context.log, &run));
    tetgen.finish(std::to_string(mesh->tets.size()) + " tets");
    const VolumeQuality quality = measure_volume(*mesh);
    // The scan measures every tet again: only when some tet is that flat.
    const FlatTets flat = quality.min_dihedral_deg < kFlatTetDeg ? find_nearly_flat_tets(*mesh) : FlatTets{};
    // Against the triangles TetGen got: the model's, or their bisected halves.
    const StructuralModel& meshed = run.refined_model ? *run.refined_model : model;
    const long nonconforming = static_cast<long>(model_triangles_not_in_tets(meshed, *mesh).size());

    nlohmann::json regions = nlohmann::json::array();
    double max_error = 0.0;
    for (size_t r = 0; r < model.regions.size(); ++r) {
      const double bound = options.volume_bound(static_cast<int>(r));
      const double enclosed = -model.signed_volume(model.regions[r].sides);
      const double meshed = r < quality.region_volume.size() ? quality.region_volume[r] : 0.0;
      const long tets = r < quality.region_tets.size() ? quality.region_tets[r] : 0;
      const double error = enclosed != 0.0 ? std::abs(meshed - enclosed) / std::abs(enclosed) : std::abs(meshed);
      max_error = std::max(max_error, error);
      regions.push_back(
          {{"name", model.regions[r].name},
           {"tets", tets},
           {"volume", meshed},
           {"enclosed_volume", enclosed},
           {"relative_error", error},
           {"largest_tet",
            r < quality.region_max_volume.size() ? quality.region_max_volume[r] : 0.0},
           {"volume_bound", bound > 0.0 ? nlohmann::json(bound) : nlohmann::json()}});
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The tets below the dihedral bound, by what holds them there (SliverCensus).
    auto group = [](const SliverCensus::Group& g) {
      return nlohmann::json{{"tets", g.tets}, {"min_dihedral_deg", g.min_dihedral_deg}};
    };
    const nlohmann::json slivers = {{"bound_deg", run.slivers.bound_deg},
                                    {"tets", run.slivers.total()},
                                    {"wedge", group(run.slivers.wedge)},
                                    {"layer", group(run.slivers.layer)},
                                    {"needle", group(run.slivers.needle)},
                                    {"surface", group(run.slivers.surface)},
                                    {"interior", group(run.slivers.interior)}};
    // Tets under each census angle: {"5": n, "10": n, ...}.
    auto census = [](const std::array<long, kDihedralCensusDeg.size()>& below) {
      nlohmann::json counts = nlohmann::json::object();
      for (size_t i = 0; i < below.size(); ++i)
        counts[std::to_string(static_cast<int>(kDihedralCensusDeg[i]))] = below[i];
      return counts;
    };
    // The thinnest wedge between surfaces inside a region: no mesh keeping them does better.
    const std::vector<ContactWedge> wedges = thin_contact_wedges(model, kWedgeReportDeg);
    // The thinnest gap where a free border leaves a surface: tets across it are flat unless the
    // surfaces are meshed finer there.
    const std::vector<BorderGap> gaps = thin_border_gaps(model, kWedgeReportDeg);
    nlohmann::json report = {
        {"switches", run.switches},
        {"input",
         {{"points", run.input_points},
          {"triangles", run.input_facets},
          {"regions", model.regions.size()}}},
        {"vertices", quality.vertices},
        {"steiner_points", run.steiner_points},
        {"tets", quality.tets},
        {"triangles", quality.triangles},
        {"regions_meshed", quality.regions},
        {"split_triangles", run.split_facets},
        {"attempts", run.attempts},
        {"sliver_passes", run.sliver_passes},
        {"extra_time_spent", run.extra_time_spent},
        {"sliver_points", run.sliver_points},
        {"polished", run.polished},
        {"smoothed_points", run.smoothed_points},
        {"slid_points", run.slid_points},
        {"further_slide", run.further_slide},
        {"tets_below_deg",
         {{"tetgen", census(run.tetgen_tets_below)},
          {"before_smoothing", census(run.smoothing_tets_below)},
          {"final", census(quality.tets_below_deg)}}},
        {"surface_min_angle_deg", run.surface_min_angle_deg},
        {"surface_needles", run.surface_needles},
        {"slivers", slivers},
        {"surface_bisection",
         {{"rounds", run.surface_rounds},
          {"edges", run.bisected_edges},
          {"triangles", meshed.num_triangles()}}},
        {"max_volume",
         {{"bound",
           options.max_volume > 0.0 ? nlohmann::json(options.max_volume) : nlohmann::json()},
          {"largest", quality.max_volume},
          {"size_rounds", run.size_rounds},
          {"edges", run.size_bisected_edges}}},
        {"thinnest_wedge_deg",
         wedges.empty() ? nlohmann::json() : nlohmann::json(wedges.front().angle_deg)},
        {"thinnest_border_gap_deg",
         gaps.empty() ? nlohmann::json() : nlohmann::json(gaps.front().angle_deg)},
        {"nonconforming_triangles", nonconforming},
        {"nonpositive_tets", quality.nonpositive_tets},
        {"min_dihedral_deg", quality.min_dihedral_deg},
        {"nearly_flat_tets", flat.count},
        {"max_dihedral_deg", quality.max_dihedral_deg},
        {"max_radius_edge", quality.max_radius_edge},
        {"mean_radius_edge", quality.mean_radius_edge},
        {"max_relative_volume_error", max_error},
        {"regions", regions},
        {"seconds",
         {{"plc", run.plc_seconds},
          {"tetgen", run.tetgen_seconds},
          {"smoothing", run.smoothing_seconds},
          {"total", seconds}}},
    };
    context.log.info("tetmesh: " + std::to_string(quality.tets) + " tets in " + std::to_string(quality.regions) +
                     " regions, min dihedral " + std::to_string(quality.min_dihedral_deg) + " deg, max radius-edge " +
                     std::to_string(quality.max_radius_edge));
    // The dihedral histogram of TetGen's first mesh, before the smoothing and in the end.
    std::string marks, first, smoothing, last;
    for (size_t i = 0; i < kDihedralCensusDeg.size(); ++i) {
      const char* sep = i == 0 ? "" : "/";
      marks += sep + std::to_string(static_cast<int>(kDihedralCensusDeg[i]));
      first += sep + std::to_string(run.tetgen_tets_below[i]);
      smoothing += sep + std::to_string(run.smoothing_tets_below[i]);
      last += sep + std::to_string(quality.tets_below_deg[i]);
    }
    context.log.info("tetmesh: tets under " + marks + " deg: " + first + " from TetGen, " +
                     smoothing + " before the smoothing, " + last + " in the end");
    // A point of the model's local frame, in file coordinates, for the log.
    auto file_point = [](const Vec3& local, const Vec3& origin) {
      const Vec3 at = local + origin;
      char text[96];
      std::snprintf(text, sizeof text, "(%.10g, %.10g, %.10g)", at[0], at[1], at[2]);
      return std::string(text);
    };
    auto tet_centre = [&](long t) {
      const Tetrahedron& k = mesh->tets[t];
      return 0.25 * (mesh->vertices[k[0]] + mesh->vertices[k[1]] + mesh->vertices[k[2]] + mesh->vertices[k[3]]);
    };
    if (flat.count > 0) {
      const std::string at = file_point(tet_centre(flat.worst), mesh->frame.origin);
      const int region = mesh->tet_region[flat.worst];
      const std::string in = region >= 0 && region < static_cast<int>(mesh->region_names.size())
                                 ? " in " + mesh->region_names[region]
                                 : std::string();
      char what[320];
      std::snprintf(what, sizeof what,
                    "tetmesh: %ld nearly flat tets (a dihedral angle under %g deg; the flattest %.3g deg at "
                    "%s%s): a solver may fail on them. ",
                    flat.count, kFlatTetDeg, flat.worst_deg, at.c_str(), in.c_str());
      context.log.warning(std::string(what) +
                          "They come from the surfaces (thin wedges, needle triangles, surfaces nearly touching "
                          "without a contact)");
    }
    if (!wedges.empty() && wedges.front().angle_deg < options.min_dihedral_deg) {
      const ContactWedge& w = wedges.front();
      const std::string where = file_point(0.5 * (model.vertices[w.a] + model.vertices[w.b]), model.frame.origin);
      const std::string pair = model.parts[w.lower_part].name + " and " + model.parts[w.upper_part].name;
      context.log.warning(
          "tetmesh: surfaces " + pair + " meet at " + std::to_string(w.angle_deg) + " deg" +
          (w.region >= 0 ? " inside " + model.regions[w.region].name : std::string()) + " at " +
          where + ": no tet mesh keeping the surfaces has a larger minimum dihedral angle " +
          "(`voroseal check` lists the thin wedges)");
    }
    // The flattest tets across a layer: where the surface mesh is too coarse for the layer.
    if (run.slivers.flattest_layer_tet >= 0 && run.slivers.layer.min_dihedral_deg < options.min_dihedral_deg &&
        run.slivers.layer.min_dihedral_deg <= quality.min_dihedral_deg + 1e-9) {
      auto name = [&](int s) {
        return s >= 0 && s < static_cast<int>(mesh->part_names.size()) ? mesh->part_names[s]
                                                                       : std::to_string(s);
      };
      const Vec3 centre = tet_centre(run.slivers.flattest_layer_tet);
      const std::string where = file_point(centre, mesh->frame.origin);
      // A free border running on just off a surface past their corner: the gap between them,
      // not a layer, is what the surface triangles are too wide for. The tet is in a gap (under
      // the dihedral bound) when it is as near the gap's border as the border's edges are long.
      const auto near = std::find_if(gaps.begin(), gaps.end(), [&](const BorderGap& g) {
        if (!(g.angle_deg < options.min_dihedral_deg)) return false;
        double nearest = (centre - model.vertices[g.apex]).norm(), edge = 0.0;
        for (size_t i = 0; i < g.border.size(); ++i) {
          const Vec3& v = model.vertices[g.border[i]];
          nearest = std::min(nearest, (centre - v).norm());
          edge = std::max(edge, (v - model.vertices[i > 0 ? g.border[i - 1] : g.apex]).norm());
        }
        return nearest <= edge;
      });
      if (near != gaps.end())
        context.log.warning(
            "tetmesh: the flattest tets (" + std::to_string(run.slivers.layer.min_dihedral_deg) +
            " deg) lie at " + where + ", in the gap between the free border of " +
            model.parts[near->border_part].name + " and " + model.parts[near->surface_part].name +
            ", which it leaves at " + std::to_string(near->angle_deg) + " deg from " +
            file_point(model.vertices[near->apex], model.frame.origin) +
            " (`voroseal check` lists thin border gaps): surfaces meshed finer there (a smaller "
            "--edge-length, or --size on the two), or the border extended onto the surface or "
            "cut back, open it");
      else
        context.log.warning(
            "tetmesh: the flattest tets (" + std::to_string(run.slivers.layer.min_dihedral_deg) +
            " deg) lie across the layer between surfaces " + name(run.slivers.layer_surfaces[0]) +
            " and " + name(run.slivers.layer_surfaces[1]) + " at " + where +
            ", thinner there than its triangles are wide" +
            (run.surface_rounds > 0 ? " even after the surface bisection" : std::string()) +
            ": remesh with `--thin-layers --zip-pinch-outs` (finer cells on thin layers, "
            "pinch-outs thinner than d_min closed) or a smaller --edge-length");
    }
    if (parameters.has("output")) {
      const std::string path = parameters.get_string("output");
      WriteOptions write;
      write.protected_paths = {context.input_path};
      ProgressStep writing(context.progress, "tetmesh: writing");
      write_volume_mesh(*mesh, path, write);
      writing.finish();
      report["output"] = path;
      context.log.info("wrote " + path);
    }
    context.report["tetmesh"] = report;
    context.volume = mesh;
  }
};

}  // namespace

}  // namespace voroseal

void voroseal_register_tetmesh(voroseal::ModuleRegistry& registry) {
  registry.add(std::make_unique<voroseal::TetmeshModule>());
}
