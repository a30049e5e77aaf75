// The `remesh` module: the remesher (remesh.h) behind the plugin interface: its parameters,
// the JSON report (seeds, optimisation history, mesh building, clean-up, topology and feature
// audit, timings), the log lines, --dump-seeds and --tetmesh.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <system_error>
#include <unordered_set>

#include "framework/core/edge_key.h"
#include "framework/core/error.h"
#include "framework/host/memory_budget.h"
#include "framework/host/module.h"
#include "framework/host/parameter_limits.h"
#include "framework/host/registry.h"
#include "io/atomic_file.h"
#include "io/model_io.h"
#include "io/size_field_format.h"
#include "modules/check/model_validity.h"
#include "modules/remesh/cleanup_report_json.h"
#include "modules/remesh/distance_bound.h"
#include "modules/remesh/inherited_defects.h"
#include "modules/remesh/remesh.h"
#include "modules/remesh/remesh_verdict.h"

namespace voroseal {

namespace {

// What a remesh holds per seed (its cell in the RVD, the optimiser's vectors, the dual mesh and
// its clean-up) and per input triangle (the model, its search trees, the RVD's clipping):
// upper figures, for refusing runs that cannot fit before they start.
constexpr double kBytesPerSeed = 4096.0;
constexpr double kBytesPerInputTriangle = 2048.0;
// Input triangles bisected for sizes finer than them: at most this many per seed (a cell then
// spans a few of them, enough for its density; more only costs time and memory).
constexpr double kInputTrianglesPerSizedSeed = 8.0;
// Defects named in the error when the remeshed model is invalid.
constexpr int kDefectsNamed = 5;
// Rounds of refinement of an invalid remesh, by default. A round's defects do not fall
// monotonically (a refinement moves the cells next to the places too), and the rounds cost
// nothing on a remesh that comes out valid (docs/benchmarks.md).
constexpr int kRepairRounds = 5;
// With --keep-topology the repair rounds also refine where a feature is lost, the one
// refinement it needs: the ball refinement everywhere a cell fails adds seeds fourfold per round
// along thin layers without keeping more (docs/benchmarks.md).
constexpr int kKeepTopologyRepairRounds = 12;
// Places of each failed check the refinement of an invalid remesh goes to.
constexpr int kPlacesRefined = 200;
// A crossing of the remesh is the input's own when the input's surfaces cross within this many
// edge lengths of it.
constexpr double kInheritedReach = 2.0;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Writes "x y z" per seed in file coordinates (local + frame origin), atomically.
void dump_seeds(const std::vector<Vec3>& seeds, const Frame& frame, const std::string& path,
                const std::string& input_path) {
  write_atomically(path, {input_path}, [&](std::ostream& out) {
    char line[128];
    for (const Vec3& p : seeds) {
      const Vec3 x = p + frame.origin;
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", x[0], x[1], x[2]);
      out << line;
    }
  });
}

/// check_model() on `text` read back as the file `path` would be.
ValidityReport written_verdict(const std::string& text, const std::string& path,
                               const CheckOptions& options,
                               std::shared_ptr<const StructuralModel>& read_back) {
  try {
    auto model = std::make_shared<const StructuralModel>(read_model_text(text, path));
    ValidityReport report = check_model(*model, options);
    report.model = path;
    read_back = std::move(model);
    return report;
  } catch (const std::exception& e) {
    // A written model that does not read back is as invalid as can be.
    ValidityReport report;
    report.model = path;
    CheckEntry entry;
    entry.name = "structure";
    entry.count = 1;
    entry.message = std::string("the written model does not read back: ") + e.what();
    report.checks.push_back(entry);
    return report;
  }
}

/// The verdict on a remesh: `voroseal check`'s on the model as written (cracks show only when
/// the file is read back), plus the holes and pockets it made and, with --keep-topology, the
/// input features it lost; `text` is the file to write at `out`.
struct Judgement {
  std::string text;
  ValidityReport verdict;
  std::shared_ptr<const StructuralModel> written;  // the output as read back from `text`
  /// What the refinement of an invalid remesh removes: the failed checks' counts.
  long defects() const {
    long n = 0;
    for (const CheckEntry& c : verdict.checks)
      if (c.severity == Severity::Error) n += c.count;
    return n;
  }
};

/// `inherited`, when given, excuses what the input fails too (inherited_defects.h).
Judgement judge(const StructuralModel& input, const RemeshResult& result, const std::string& out,
                const WriteOptions& write, bool keep_topology,
                const InputDefects* inherited = nullptr) {
  CheckOptions options;
  options.max_examples = kPlacesRefined;
  Judgement j;
  if (!out.empty()) {
    j.text = model_text(result.model, out, write);
    j.verdict = written_verdict(j.text, out, options, j.written);
  } else {
    j.verdict = check_model(result.model, options);
  }
  j.verdict.checks.push_back(
      holes_made(input, result.model, result.topology.input_part_of_output, kPlacesRefined));
  j.verdict.checks.push_back(no_region_gained(input, result.topology, kPlacesRefined));
  if (keep_topology)
    j.verdict.checks.push_back(topology_kept(input, result.topology, kPlacesRefined));
  if (inherited != nullptr)
    inherited->excuse(result.model, result.topology.input_part_of_output,
                      kInheritedReach * result.seeds.edge_length, j.verdict);
  return j;
}

/// An input that bounds no region is a set of surfaces (faults from a community fault model),
/// not a model to seal: when `check` finds it invalid, its remesh is judged against it, and
/// what the input fails too is excused (inherited_defects.h). Null for an input that bounds
/// regions (its remesh must be valid) or is valid.
std::unique_ptr<const InputDefects> defects_to_inherit(const StructuralModel& input, Logger& log) {
  if (!input.regions.empty()) return nullptr;
  CheckOptions options;
  options.max_examples = 0;
  options.intersections = false;  // InputDefects finds the crossings, with their places
  auto inherited = std::make_unique<const InputDefects>(input, check_model(input, options));
  if (!inherited->any()) return nullptr;
  std::string failed;
  for (const std::string& name : inherited->failed()) failed += (failed.empty() ? "" : ", ") + name;
  log.warning("remesh: the input, a set of surfaces bounding no region, is not valid (" + failed +
              (inherited->crossings() > 0
                   ? ": " + std::to_string(inherited->crossings()) + " crossing triangle pairs"
                   : std::string()) +
              "): the remesh is judged against it, and what it inherits is a warning");
  return inherited;
}

/// Where an invalid remesh is refined: the failed checks' places, and the rims of the pockets
/// (where they were cut off from their region), in the model's local frame.
std::vector<Vec3> places_to_refine(const Judgement& j, const TopologyReport& topology,
                                   const Frame& frame) {
  std::vector<Vec3> places;
  for (const CheckEntry& c : j.verdict.checks)
    if (c.severity == Severity::Error && !c.passed())
      for (const CheckExample& e : c.examples) places.push_back(e.location - frame.origin);
  for (const GainedRegion& g : topology.regions_gained)
    places.insert(places.end(), g.rim.begin(), g.rim.end());
  return places;
}

/// The failed error checks with their counts and a few places.
nlohmann::json verdict_json(const ValidityReport& verdict) {
  nlohmann::json failed = nlohmann::json::array();
  for (const CheckEntry& c : verdict.checks) {
    if (c.severity != Severity::Error || c.passed()) continue;
    nlohmann::json places = nlohmann::json::array();
    for (size_t i = 0; i < c.examples.size() && i < static_cast<size_t>(kDefectsNamed); ++i)
      places.push_back(
          {{"what", c.examples[i].what},
           {"location",
            {c.examples[i].location.x(), c.examples[i].location.y(), c.examples[i].location.z()}}});
    failed.push_back(
        {{"check", c.name}, {"count", c.count}, {"message", c.message}, {"examples", places}});
  }
  return {{"errors", verdict.errors()}, {"failed", failed}};
}

/// "self_intersections: 4 (triangle 12 ... at x y z; ...)", kDefectsNamed places in all.
std::string defects_text(const ValidityReport& verdict) {
  std::string text;
  int named = 0;
  for (const CheckEntry& c : verdict.checks) {
    if (c.severity != Severity::Error || c.passed()) continue;
    text += (text.empty() ? "" : "; ") + c.name + " " + std::to_string(c.count);
    std::string places;
    for (const CheckExample& e : c.examples) {
      if (named >= kDefectsNamed) break;
      char at[128];
      std::snprintf(at, sizeof at, " at %.10g %.10g %.10g", e.location.x(), e.location.y(),
                    e.location.z());
      places += (places.empty() ? "" : ", ") + e.what + at;
      ++named;
    }
    if (!places.empty()) text += " (" + places + ")";
  }
  return text;
}

/// A distance bound asked for (`--distance-bound`) and the sizes it gave before the remesh.
struct DistanceBound {
  double bound = 0.0;
  double h = 0.0;  // the uniform edge length
  const DistanceSizing* sizing = nullptr;
};

/// Where the two-sided distance is reached, in file coordinates.
Vec3 farthest(const HausdorffDistance& d, const Frame& frame) {
  return (d.a_to_b.max >= d.b_to_a.max ? d.a_to_b.max_at : d.b_to_a.max_at) + frame.origin;
}

nlohmann::json distance_json(const DistanceCheck& check, double bound) {
  const HausdorffDistance& d = check.distance;
  return {{"bound", bound},
          {"hausdorff", d.hausdorff},
          {"input_to_remesh", d.a_to_b.max},
          {"remesh_to_input", d.b_to_a.max},
          {"samples_over", check.samples_over},
          {"held", d.hausdorff <= bound}};
}

/// Where the remesh strays farther than the bound from the input: smaller cells there
/// (refine_at_places), the mesh built again, for up to kDistanceRounds rounds. A round's remesh
/// stays when it has no more defects and is closer. Logs and reports the distance; a bound that
/// does not hold sets exit code 1.
nlohmann::json hold_distance_bound(const StructuralModel& input, const DistanceBound& asked,
                                   const SeedOptions& options, const RemeshOptions& remesh_options,
                                   const std::string& out, const WriteOptions& write,
                                   const InputDefects* inherited, RemeshResult& result,
                                   Judgement& judgement, Context& context) {
  const double bound = asked.bound;
  // One place per half cell: each gets smaller cells over the cell it lies in, graded.
  const double spacing = 0.5 * asked.h;
  const double refine_above = kDistanceRefineShare * bound;
  const InputDistance to_input(input);
  DistanceCheck check = to_input.check(result.model, bound, refine_above, spacing);
  char line[320];
  std::snprintf(line, sizeof line, "remesh: distance to the input %.4g, bound %.4g",
                check.distance.hausdorff, bound);
  context.log.info(line);
  BallRefinementOptions refine = remesh_options.refinement;
  refine.min_size = result.min_feature;
  SeedOptimizationResult last = result.seeds;
  nlohmann::json rounds = nlohmann::json::array();
  for (int round = 0; round < kDistanceRounds && !check.places.empty(); ++round) {
    if (!judgement.verdict.valid()) break;  // the repairs come first; they failed
    const auto t0 = std::chrono::steady_clock::now();
    ProgressStep step(context.progress, "remesh: distance round " + std::to_string(round + 1));
    const std::vector<Vec3> places = check.places;
    std::vector<double> shrinks(places.size());
    for (size_t i = 0; i < places.size(); ++i)
      shrinks[i] = std::clamp(refine_above / check.place_distance[i], kDistanceShrinkMin,
                              kDistanceShrinkMax);
    const int added = refine_at_places(input, last, options, places, refine, kRepairRounds + round,
                                       context.log, context.progress, &shrinks);
    RemeshResult next =
        remesh_from_seeds(input, last, remesh_options, context.log, context.progress);
    Judgement j = judge(input, next, out, write, remesh_options.keep_topology, inherited);
    DistanceCheck c = to_input.check(next.model, bound, refine_above, spacing);
    std::snprintf(line, sizeof line, "distance %.4g", c.distance.hausdorff);
    step.finish(line);
    rounds.push_back({{"places", places.size()},
                      {"seeds_added", added},
                      {"hausdorff", c.distance.hausdorff},
                      {"defects", j.defects()},
                      {"seconds", seconds_since(t0)}});
    std::snprintf(line, sizeof line,
                  "remesh: distance round %d: %zu places farther than %.4g from the input "
                  "refined (%d seeds added): distance %.4g, %ld defects",
                  round + 1, places.size(), bound, added, c.distance.hausdorff, j.defects());
    context.log.info(line);
    const Vec3 at = farthest(c.distance, input.frame);
    std::snprintf(line, sizeof line, "remesh: distance round %d: farthest at %.10g %.10g %.10g",
                  round + 1, at.x(), at.y(), at.z());
    context.log.debug(line);
    const bool closer = c.distance.hausdorff < check.distance.hausdorff;
    if (j.defects() <= judgement.defects() && closer) {
      result = std::move(next);
      judgement = std::move(j);
      check = std::move(c);
    } else {  // refine the last seeds further
      check.places = std::move(c.places);
      check.place_distance = std::move(c.place_distance);
    }
  }
  nlohmann::json report = distance_json(check, bound);
  report["rounds"] = std::move(rounds);
  report["sizing"] = {{"samples", asked.sizing->samples},
                      {"finer", asked.sizing->finer},
                      {"smallest", asked.sizing->smallest}};
  const HausdorffDistance& d = check.distance;
  const bool held = d.hausdorff <= bound;
  const Vec3 at = farthest(d, input.frame);
  std::snprintf(line, sizeof line,
                "remesh: two-sided distance to the input %.4g (input to remesh %.4g, remesh to "
                "input %.4g): %s the bound %.4g%s",
                d.hausdorff, d.a_to_b.max, d.b_to_a.max, held ? "within" : "PAST", bound,
                held ? "" : ", farthest at");
  std::string message = line;
  if (!held) {
    std::snprintf(line, sizeof line, " %.10g %.10g %.10g (%ld samples past it)", at.x(), at.y(),
                  at.z(), check.samples_over);
    context.log.error(message + line +
                      "; features merged below --min-feature, or cells the refinement could "
                      "not shrink further: see the report's distance_bound");
    context.exit_code = std::max(context.exit_code, 1);
  } else {
    context.log.info(message);
  }
  return report;
}

class RemeshModule final : public Module {
 public:
  std::string name() const override { return "remesh"; }
  std::string description() const override {
    return "Remesh the surfaces at a target resolution (CVT seed optimisation, Pellerin et al. 2014)";
  }
  std::vector<ParameterSpec> parameters() const override {
    // Field by field: robust to new ParameterSpec members.
    auto spec = [](const char* name, ParameterType type, nlohmann::json def, const char* doc,
                   double min = 0.0, double max = kMaxModelLength) {
      ParameterSpec p;
      p.name = name;
      p.type = type;
      p.default_value = std::move(def);
      p.doc = doc;
      p.min = min;
      p.max = max;
      return p;
    };
    std::vector<ParameterSpec> p;
    p.push_back(spec("edge-length", ParameterType::Double, nullptr,
                     "target edge length in model units (gives the number of seeds)", 0.0));
    p.push_back(spec("seeds", ParameterType::Int, nullptr,
                     "number of seeds (overrides --edge-length)", 1, kMaxCount));
    p.push_back(spec("iterations", ParameterType::Int, 100, "maximum optimisation iterations", 0, 1e6));
    ParameterSpec optimizer = spec("optimizer", ParameterType::Choice, "lbfgs",
                                   "seed optimiser: lbfgs, lloyd, or ceres (when built with Ceres)");
    optimizer.choices = {"lbfgs", "lloyd", "ceres"};
    p.push_back(optimizer);
    p.push_back(spec("seed", ParameterType::Int, 1, "random seed of the initial sampling", 0,
                     kMaxRandomSeed));
    p.push_back(spec("gradient-threshold", ParameterType::Double, 1e-6,
                     "stop when |grad F| falls below this fraction of its initial value", 0.0,
                     1.0));
    p.push_back(spec("energy-tolerance", ParameterType::Double, 0.0,
                     "stop when F fell by less than this fraction of its decrease so far over "
                     "the last 10 iterations (0: off)",
                     0.0, 1.0));
    p.push_back(spec("boundary-weight", ParameterType::Double, nullptr,
                     "weight alpha in [0, 1] of the contact energy (default: from the gradient-norm ratio)", 0.0, 1.0));
    p.push_back(spec("dump-seeds", ParameterType::Path, nullptr, "write the optimised seeds, x y z per line"));
    p.back().output = true;
    ParameterSpec output =
        spec("output", ParameterType::Path, nullptr,
             "write the remeshed model (format from the extension); nothing is written "
             "when it is not valid");
    output.short_name = "o";
    output.output = true;
    output.extensions = writable_model_extensions();
    p.push_back(output);
    ParameterSpec keep_invalid =
        spec("keep-invalid", ParameterType::Path, nullptr,
             "write the remeshed model here when it is not valid, for inspection");
    keep_invalid.output = true;
    keep_invalid.extensions = writable_model_extensions();
    p.push_back(keep_invalid);
    p.push_back(spec("min-feature", ParameterType::Double, nullptr,
                     "merge features closer than this distance, d_min of paper Fig. 11c-d "
                     "(default: 0.15 x the mean edge length; 0: never merge)",
                     0.0));
    p.push_back(spec("fidelity", ParameterType::Double, nullptr,
                     "split where the remesh strays farther than this from the input "
                     "(default: 0.1 x the mean edge length; 0: off)",
                     0.0));
    p.push_back(spec("thin-layers", ParameterType::Bool, false,
                     "smaller cells on the sides of layers thinner than the cells, so that a tet mesh can fill them "
                     "without flat tets, and along contacts shorter than a cell, so that their corners stay apart "
                     "(more seeds there; the size elsewhere is kept)"));
    p.push_back(spec("layer-ratio", ParameterType::Double, LayerSizingOptions{}.ratio,
                     "with --thin-layers: cells at most this many times the layer thickness", 0.5, 1e6));
    p.push_back(spec("layer-refinement", ParameterType::Double, LayerSizingOptions{}.max_refinement,
                     "with --thin-layers: cells at most this many times smaller than elsewhere", 1.0, 100.0));
    p.push_back(spec("corner-ratio", ParameterType::Double, LayerSizingOptions{}.corner_ratio,
                     "with --thin-layers: cells at most this many times the length of a contact shorter than a cell "
                     "(0: off)",
                     0.0, 100.0));
    ParameterSpec size = spec("size", ParameterType::String, nullptr,
                              "target edge length on some surfaces, NAME=H (repeatable, or "
                              "comma-separated): a surface, region or layer name (globs), or "
                              "kind:fault, kind:horizon, kind:boundary; the smallest size wins");
    size.repeatable = true;
    p.push_back(size);
    p.push_back(spec("size-field", ParameterType::Path, nullptr,
                     "target edge lengths at points, a file of 'x y z h' lines (file "
                     "coordinates) or a .vtu with a scalar point data array of sizes (the "
                     "only one, or size or h): h at the points, graded away from them; the "
                     "smallest size wins"));
    p.push_back(spec("distance-bound", ParameterType::String, nullptr,
                     "keep the remesh within this distance of the input, a length or a "
                     "percentage of the model's diagonal (0.1%): cells as coarse as the "
                     "surfaces' curvature and the contacts' bends allow (never coarser than "
                     "--seeds or --edge-length ask), then refined where the two-sided distance "
                     "exceeds it; exit 1 when it cannot hold"));
    p.push_back(spec("gradation", ParameterType::Double, SeedOptions{}.gradation,
                     "with --size, --size-field or --distance-bound: sizes change by at most "
                     "this factor between neighbouring cells",
                     1.01, 10.0));
    p.push_back(spec("zip-pinch-outs", ParameterType::Bool, false,
                     "close layers that end in a pinch-out and stay thinner than d_min past it: their two sides "
                     "zip into one surface from the pinch-out on, so that a tet mesh has no flat tets there "
                     "(experimental: check the tet mesh; where a zip stops short, tets can get worse)"));
    p.push_back(spec("zip-wedge", ParameterType::Double, 12.0,
                     "with --zip-pinch-outs: zip while the two sides meet at a wedge thinner than this (degrees)",
                     0.1, 90.0));
    p.push_back(spec("refine-rounds", ParameterType::Int, BallRefinementOptions{}.max_rounds,
                     "rounds of refinement where a restricted Voronoi cell fails the topological "
                     "ball property by more than d_min (0: none, the failures are only counted)",
                     0, 20));
    p.push_back(spec("refine-iterations", ParameterType::Int, BallRefinementOptions{}.iterations,
                     "optimiser iterations after each refinement round", 0, 1e6));
    static const std::string repair_rounds_help =
        "rounds of refinement where the remeshed model comes out invalid, closes a pocket or "
        "(--keep-topology) loses a feature: smaller cells around each place, seeds optimised "
        "again, mesh built again (0: none; default " + std::to_string(kRepairRounds) + ", " +
        std::to_string(kKeepTopologyRepairRounds) + " with --keep-topology)";
    p.push_back(spec("repair-rounds", ParameterType::Int, nullptr, repair_rounds_help.c_str(), 0,
                     40));
    p.push_back(spec("keep-topology", ParameterType::Bool, false,
                     "merge nothing: refine until every surface part, contact, corner and region of the "
                     "input has its counterpart (d_min 0)"));
    p.push_back(spec("cleanup", ParameterType::Bool, true, "clean the dual mesh up: valence-3 vertices, needles, flips, smoothing, repairs (--no-cleanup keeps the raw dual mesh)"));
    p.push_back(spec("tetmesh", ParameterType::Path, nullptr,
                     "then tet-mesh the remeshed model with default settings and write it here (.mesh .vtu .msh)"));
    p.back().output = true;
    p.back().extensions = writable_volume_extensions();
    return p;
  }

  void run(Context& context, const Parameters& parameters) const override {
    if (!context.model) throw ModelError("remesh: no model");
    warn_about_region_signs(*context.model, context.log);
    const std::shared_ptr<const StructuralModel> as_read = context.model;
    SeedOptions options;
    std::string asked;  // the option that sets the resolution, for the memory estimate
    double seed_count = 0.0;
    if (parameters.has("seeds")) {
      options.num_seeds = static_cast<int>(parameters.get_int("seeds"));
      seed_count = options.num_seeds;
      asked = "--seeds " + std::to_string(options.num_seeds);
    } else if (parameters.has("edge-length")) {
      options.edge_length = parameters.get_double("edge-length");
      if (!(options.edge_length > 0.0)) throw ParameterError("parameter --edge-length: must be positive");
      seed_count = context.model->area() /
                   (std::sqrt(3.0) / 2.0 * options.edge_length * options.edge_length);
      char text[96];
      std::snprintf(text, sizeof text, "--edge-length %g (%.3g seeds)", options.edge_length,
                    seed_count);
      asked = text;
    } else {
      throw ParameterError("remesh: give --edge-length or --seeds");
    }
    options.gradation = parameters.get_double("gradation");
    if (parameters.has("size"))
      options.sizes = parse_size_rules(parameters.get_string("size"), "--size");
    if (parameters.has("size-field"))
      options.size_field =
          load_size_field(parameters.get_string("size-field"), context.model->frame.origin);
    // The edge length of a uniform remesh with these seeds: what sizes are relative to.
    const double uniform_h = std::sqrt(2.0 * context.model->area() / (std::sqrt(3.0) * seed_count));
    const std::shared_ptr<const SizeField> user_field = options.size_field;
    double distance_bound = 0.0;
    DistanceSizing distance_sizes;
    if (parameters.has("distance-bound")) {
      distance_bound =
          parse_distance_bound(parameters.get_string("distance-bound"), *context.model);
      distance_sizes = distance_sizing(*context.model, distance_bound, uniform_h, context.threads);
      char line[240];
      std::snprintf(line, sizeof line,
                    "remesh: distance bound %.4g: %d of %d samples of the surfaces and contacts "
                    "need cells finer than %.4g (down to %.4g)",
                    distance_bound, distance_sizes.finer, distance_sizes.samples, uniform_h,
                    distance_sizes.smallest);
      context.log.info(line);
      options.size_field = SizeField::smallest(user_field, distance_sizes.field);
    }
    if (options.sized()) {
      // Sizes finer than the input's triangles need finer triangles to be followed.
      // The sizes change the seed count: the estimate counts the seeds they need, first on the
      // input's triangles (before any work), then on the triangles bisected for the sizes.
      auto sized_seeds = [&](const StructuralModel& model) {
        return seed_count * surface_sizing(model, options.sizes, uniform_h, options.gradation,
                                           options.size_field.get())
                                .seed_factor;
      };
      const double estimate = sized_seeds(*context.model);
      require_memory(
          context,
          estimate * kBytesPerSeed + context.model->num_triangles() * kBytesPerInputTriangle,
          "remesh " + asked + " with sizes (" + std::to_string(std::lround(estimate)) + " seeds)");
      // Input triangles finer than the cells help no one: a few per seed at most.
      auto refined = std::make_shared<StructuralModel>(*context.model);
      const long budget = context.model->num_triangles() +
                          static_cast<long>(kInputTrianglesPerSizedSeed * estimate);
      if (const int split = refine_for_sizes(*refined, options.sizes, uniform_h, options.gradation,
                                             options.size_field.get(), budget);
          split > 0) {
        context.log.info(
            "remesh: sizes finer than the input's triangles: " + std::to_string(split) +
            " input edges bisected (" + std::to_string(refined->num_triangles()) + " triangles)");
        context.model = std::move(refined);
      }
      seed_count = sized_seeds(*context.model);
      asked += " with sizes (" + std::to_string(std::lround(seed_count)) + " seeds)";
    }
    require_memory(
        context,
        seed_count * kBytesPerSeed + context.model->num_triangles() * kBytesPerInputTriangle,
        "remesh " + asked);
    options.optimizer.max_iterations = static_cast<int>(parameters.get_int("iterations"));
    options.optimizer.kind = optimizer_from_string(parameters.get_string("optimizer"));
    options.optimizer.gradient_threshold = parameters.get_double("gradient-threshold");
    options.optimizer.energy_tolerance = parameters.get_double("energy-tolerance");
    options.random_seed = static_cast<std::uint64_t>(parameters.get_int("seed"));
    if (parameters.has("boundary-weight")) options.boundary_weight = parameters.get_double("boundary-weight");
    options.threads = context.threads;
    options.thin_layers = parameters.get_bool("thin-layers");
    options.layer_sizing.ratio = parameters.get_double("layer-ratio");
    options.layer_sizing.max_refinement = parameters.get_double("layer-refinement");
    options.layer_sizing.corner_ratio = parameters.get_double("corner-ratio");

    RemeshOptions remesh_options;
    remesh_options.seeds = options;
    remesh_options.cleanup.min_feature =
        parameters.has("min-feature") ? parameters.get_double("min-feature") : -kDefaultMinFeatureFactor;
    remesh_options.cleanup.fidelity_tolerance =
        parameters.has("fidelity") ? parameters.get_double("fidelity") : -kDefaultFidelityFactor;
    // Under a distance bound the clean-up splits where the remesh strays past it, and merges
    // (which move the surfaces by up to d_min) stay within it.
    if (distance_bound > 0.0 && !parameters.has("fidelity"))
      remesh_options.cleanup.fidelity_tolerance =
          std::min(kDefaultFidelityFactor * uniform_h, distance_bound);
    if (distance_bound > 0.0 && !parameters.has("min-feature"))
      remesh_options.cleanup.min_feature =
          std::min(kDefaultMinFeatureFactor * uniform_h, distance_bound);
    if (distance_bound > 0.0 && parameters.has("min-feature") &&
        parameters.get_double("min-feature") > distance_bound)
      context.log.warning(
          "remesh: --min-feature is larger than --distance-bound: features "
          "merged below it may leave the remesh farther than the bound");
    remesh_options.cleanup.grade = options.sized();
    remesh_options.clean_up = parameters.get_bool("cleanup");
    remesh_options.refinement.max_rounds = static_cast<int>(parameters.get_int("refine-rounds"));
    remesh_options.keep_topology = parameters.get_bool("keep-topology");
    remesh_options.refinement.iterations = static_cast<int>(parameters.get_int("refine-iterations"));
    if (parameters.get_bool("zip-pinch-outs"))
      remesh_options.cleanup.zip_wedge_deg = parameters.get_double("zip-wedge");
    SeedOptimizationResult seeds =
        optimize_seeds(*context.model, options, context.log, context.progress);
    // The seeds are written before mesh building, so that they are there whatever happens next.
    if (parameters.has("dump-seeds")) {
      const std::string path = parameters.get_string("dump-seeds");
      dump_seeds(seeds.seeds, context.model->frame, path, context.input_path);
      context.log.info("remesh: wrote " + std::to_string(seeds.seeds.size()) + " seeds to " + path);
    }
    const std::shared_ptr<const StructuralModel> input_model = context.model;
    const StructuralModel& input = *input_model;
    const WriteOptions write{{context.input_path}};
    const std::string out =
        parameters.has("output") ? parameters.get_string("output") : std::string();
    // As read: the sizes may have bisected its triangles since (same parts, same surfaces).
    const std::unique_ptr<const InputDefects> inherited = defects_to_inherit(*as_read, context.log);
    if (inherited != nullptr) remesh_options.cleanup.crossing_parts = inherited->crossing_parts();
    RemeshResult result =
        remesh_from_seeds(input, std::move(seeds), remesh_options, context.log, context.progress);
    const bool keep_topology = remesh_options.keep_topology;
    ProgressStep judging(context.progress, "remesh: verdict");
    Judgement judgement = judge(input, result, out, write, keep_topology, inherited.get());
    judging.finish(judgement.verdict.valid() ? "valid" : "not valid");
    // Where the remesh came out invalid or closed a pocket, the dual was not faithful there:
    // smaller cells around each place, the seeds optimised again, the mesh built again. Each
    // round refines the last; the remesh with the fewest defects stays.
    nlohmann::json repair_rounds = nlohmann::json::array();
    const size_t seeds_before_repair = result.seeds.seeds.size();
    {
      SeedOptimizationResult last = result.seeds;
      std::vector<Vec3> places = places_to_refine(judgement, result.topology, input.frame);
      BallRefinementOptions repair = remesh_options.refinement;
      repair.min_size = result.min_feature;
      // --no-cleanup asks for the raw dual: judged, not refined.
      const int asked = parameters.has("repair-rounds")
                            ? static_cast<int>(parameters.get_int("repair-rounds"))
                        : keep_topology ? kKeepTopologyRepairRounds
                                        : kRepairRounds;
      const int rounds = remesh_options.clean_up ? asked : 0;
      for (int round = 0; round < rounds && !places.empty(); ++round) {
        const auto t0 = std::chrono::steady_clock::now();
        ProgressStep step(context.progress, "remesh: repair round " + std::to_string(round + 1));
        const int added = refine_at_places(input, last, options, places, repair, round, context.log,
                                           context.progress);
        RemeshResult next =
            remesh_from_seeds(input, last, remesh_options, context.log, context.progress);
        ProgressStep judging_again(context.progress, "remesh: verdict");
        Judgement j = judge(input, next, out, write, keep_topology, inherited.get());
        judging_again.finish();
        const long defects = j.defects();
        step.finish(std::to_string(defects) + " defects left");
        repair_rounds.push_back({{"places", places.size()},
                                 {"seeds_added", added},
                                 {"defects", defects},
                                 {"seconds", seconds_since(t0)}});
        context.log.info("remesh: refined " + std::to_string(places.size()) +
                         " places where the remesh was invalid (" + std::to_string(added) +
                         " seeds added): " + std::to_string(defects) + " defects left");
        places = places_to_refine(j, next.topology, input.frame);
        if (defects < judgement.defects()) {
          result = std::move(next);
          judgement = std::move(j);
        }
      }
    }
    nlohmann::json distance_report;
    if (distance_bound > 0.0) {
      DistanceBound bound{distance_bound, uniform_h, &distance_sizes};
      distance_report = hold_distance_bound(input, bound, options, remesh_options, out, write,
                                            inherited.get(), result, judgement, context);
    }
    const SeedOptimizationResult& r = result.seeds;

    nlohmann::json history = nlohmann::json::array();
    for (const IterationRecord& it : r.run.history)
      history.push_back({{"iteration", it.iteration},
                         {"energy", it.energy},
                         {"cvt", std::isnan(it.cvt) ? nlohmann::json() : nlohmann::json(it.cvt)},
                         {"boundary", std::isnan(it.boundary) ? nlohmann::json() : nlohmann::json(it.boundary)},
                         {"gradient_norm", it.gradient_norm},
                         {"evaluations", it.evaluations},
                         {"seconds", it.seconds}});
    nlohmann::json& report = context.report["remesh"];
    report["seeds"] = r.seeds.size();
    if (options.thin_layers)
      report["thin_layers"] = {{"base_seeds", r.base_seeds},
                               {"seeds_added", static_cast<long>(r.seeds.size()) - r.base_seeds},
                               {"thin_samples", r.thin_layer_samples},
                               {"pinch_vertices", r.pinch_vertices},
                               {"short_contacts", r.short_contacts},
                               {"thinnest", std::isfinite(r.thinnest_layer) ? nlohmann::json(r.thinnest_layer)
                                                                            : nlohmann::json()},
                               {"edge_length", r.edge_length}};
    if (options.sized()) {
      report["sizes"] = sizes_json(input, result.model, r, context.log);
      if (user_field)
        report["sizes"]["field"] = size_field_json(*user_field, input, result.model, context.log);
    }
    if (distance_bound > 0.0) report["distance_bound"] = std::move(distance_report);
    report["refinement"] = refinement_json(result.refinement);
    // The seeds the kept remesh has more than the first one.
    report["repair_refinement"] = {
        {"seeds_added", static_cast<long>(r.seeds.size() - seeds_before_repair)},
        {"rounds", std::move(repair_rounds)}};
    report["optimizer"] = to_string(options.optimizer.kind);
    report["alpha"] = r.alpha;
    report["iterations"] = r.run.history.empty() ? 0 : r.run.history.back().iteration;
    report["evaluations"] = r.run.evaluations;
    report["stop_reason"] = r.run.stop_reason;
    report["history"] = std::move(history);
    report["timings"] = {{"sampling_s", r.sampling_seconds},
                         {"refinement_s", result.refinement_seconds},
                         {"optimization_s", r.optimization_seconds},
                         {"rvd_s", result.rvd_seconds},
                         {"mesh_building_s", result.build_seconds},
                         {"cleanup_s", result.cleanup_seconds},
                         {"evaluation_ms_mean", r.run.evaluations > 0
                                                    ? 1000.0 * r.optimization_seconds / r.run.evaluations
                                                    : 0.0}};
    // The process's memory at the end of each phase of the kept remesh (MB): what the phase
    // still holds, and the peak so far (a phase whose peak is above the one before set it).
    const auto megabytes = [](double bytes) { return std::round(bytes / 1e5) / 10.0; };
    const std::pair<const char*, ProcessMemory> phases[] = {
        {"optimization", r.memory},
        {"refinement", result.refinement_memory},
        {"rvd", result.rvd_memory},
        {"mesh_building", result.build_memory},
        {"cleanup", result.cleanup_memory}};
    double peak = process_memory().peak_bytes;
    for (const auto& [name, m] : phases) {
      report["memory"][name] = {{"resident_mb", megabytes(m.resident_bytes)},
                                {"peak_mb", megabytes(m.peak_bytes)}};
      peak = std::max(peak, m.peak_bytes);  // the counters lag by a few pages
    }
    report["memory"]["peak_mb"] = megabytes(peak);
    report["mesh_building"] = {{"cell_components", result.build.cell_components},
                               {"contact_components", result.build.contact_components},
                               {"junction_triangles", result.build.junction_triangles},
                               {"split_polygons", result.build.split_polygons},
                               {"degenerate_dropped", result.build.degenerate_dropped},
                               {"inconsistencies", result.build.inconsistencies}};
    report["cleanup"] = {{"valence3_removed", result.cleanup.valence3_removed},
                         {"valence3_raised", result.cleanup.valence3_raised},
                         {"needles_collapsed", result.cleanup.needles_collapsed},
                         {"sharp_collapses", result.cleanup.sharp_collapses},
                         {"contact_collapses", result.cleanup.contact_collapses},
                         {"quality_moves", result.cleanup.quality_moves},
                         {"sharp_moves", result.cleanup.sharp_moves},
                         {"wedge_moves", result.cleanup.wedge_moves},
                         {"tips_joined", result.cleanup.tips_joined},
                         {"pinch_zips", result.cleanup.pinch_zips},
                         {"pinch_rungs", result.cleanup.pinch_rungs},
                         {"pinch_pockets", result.cleanup.pinch_pockets},
                         {"pinch_zip_undone", result.cleanup.pinch_zip_undone},
                         {"flips", result.cleanup.flips},
                         {"fidelity_splits", result.cleanup.fidelity_splits},
                         {"grading_splits", result.cleanup.grading_splits},
                         {"coincident_removed", result.cleanup.coincident_removed},
                         {"intersections_found", result.cleanup.intersections_found},
                         {"intersections_left", result.cleanup.intersections_left},
                         {"holes_left", result.cleanup.holes_left},
                         {"leaks_left", result.cleanup.leaks_left},
                         {"degenerate_left", result.cleanup.degenerate_left},
                         {"pinches_left", result.cleanup.pinches_left},
                         {"folds_left", result.cleanup.folds_left}};
    report["cleanup"]["phases"] = phases_json(result.cleanup.phases);
    report["min_feature"] = result.min_feature;
    report["sharp_points"] = result.build.sharp_points;
    // The clean-up's own census, taken before the pockets are opened and the model is read
    // back: what it counts as invalid is a warning only when the verdict on the model as
    // written (below) agrees that something is wrong. Folds only warn, and do so as they are.
    const CleanupReport& left = result.cleanup;
    if (left.invalid_left() > 0) {
      const std::string census = "remesh: the clean-up left " +
                                 std::to_string(left.intersections_left) + " crossing pairs, " +
                                 std::to_string(left.holes_left) + " holes, " +
                                 std::to_string(left.leaks_left) + " leaks, " +
                                 std::to_string(left.degenerate_left) +
                                 " degenerate triangles and " +
                                 std::to_string(left.pinches_left) + " pinched vertices";
      if (judgement.verdict.valid())
        context.log.debug(census + "; the model as written is valid");
      else
        context.log.warning(census);
    }
    if (left.folds_left > 0)
      context.log.warning("remesh: " + std::to_string(left.folds_left) +
                          " folds left (two triangles of a surface at less than 5 deg: flat tets "
                          "in a volume mesh there)");
    report["topology"] = topology_json(result.topology, *context.model);
    print_topology(context.log, result.topology, *context.model);

    // One verdict, `voroseal check`'s, on the model as written; nothing invalid goes to
    // --output, --keep-invalid is where to look at it.
    context.model = std::make_shared<StructuralModel>(std::move(result.model));
    const std::string& text = judgement.text;
    const ValidityReport& verdict = judgement.verdict;
    const bool valid = verdict.valid();
    report["valid"] = valid;
    report["validity"] = verdict_json(verdict);
    if (inherited != nullptr) report["validity"]["inherited"] = inherited->failed();
    if (valid && !out.empty()) {
      write_text(text, out, write);
      context.log.info("remesh: wrote " + out);
    }
    if (!valid) {
      context.exit_code = std::max(context.exit_code, 1);
      std::string kept;
      if (parameters.has("keep-invalid")) {
        const std::string path = parameters.get_string("keep-invalid");
        write_model(*context.model, path, write);
        kept = "; written to " + path + " for inspection";
      } else if (!out.empty()) {
        kept = "; nothing written to " + out + " (--keep-invalid PATH writes it for inspection)";
      }
      context.log.error(
          "remesh: the remeshed model is not valid (what `voroseal check` finds, holes the "
          "input has not, pockets" +
          std::string(keep_topology ? ", input features without a counterpart" : "") +
          "): " + defects_text(verdict) + kept);
    }
    // TetGen on crossing surfaces fails, and through a hole it fills two regions as one: the
    // volume mesh of an invalid model would only hide what went wrong.
    if (parameters.has("tetmesh") && !valid) {
      context.log.error("remesh: --tetmesh not run: the remeshed model is not valid");
      report["tetmesh_skipped"] = true;
    } else if (parameters.has("tetmesh")) {
      if (context.registry == nullptr) throw ParameterError("remesh --tetmesh: no module registry in this run");
      // The model as written, read back as `tetmesh OUT` reads it: the file rounds coordinates
      // and orders vertices and triangles its own way, and TetGen's mesh depends on both.
      if (judgement.written)
        context.model = std::make_shared<StructuralModel>(*judgement.written);
      const Module& tetmesh = context.registry->get("tetmesh");
      tetmesh.run(context, Parameters(tetmesh.parameters(), {{"output", parameters.get_string("tetmesh")}}));
    }
  }

 private:
  // Per input surface: the size asked (its rule's, else the resolution's) against the mean edge
  // length of its counterpart in the output; logged and reported.
  static nlohmann::json sizes_json(const StructuralModel& input, const StructuralModel& output,
                                   const SeedOptimizationResult& seeds, Logger& log) {
    const std::vector<double> realised = mean_edge_per_interface(output);
    nlohmann::json surfaces = nlohmann::json::array();
    for (size_t i = 0; i < input.interfaces.size() && i < seeds.interface_size.size(); ++i) {
      const std::string& name = input.interfaces[i].name;
      double edge = 0.0;
      for (size_t o = 0; o < output.interfaces.size(); ++o)
        if (output.interfaces[o].name == name) edge = realised[o];
      const double asked = seeds.interface_size[i], target = seeds.interface_target[i];
      surfaces.push_back(
          {{"name", name}, {"asked", asked}, {"graded", target}, {"realised", edge}});
      char line[240];
      std::snprintf(line, sizeof line,
                    "remesh: size on %s: asked %.4g, %.4g once graded, mean edge %.4g (%+.1f %%)",
                    name.c_str(), asked, target, edge, 100.0 * (edge / target - 1.0));
      log.info(line);
    }
    return {{"edge_length", seeds.edge_length}, {"surfaces", std::move(surfaces)}};
  }

  /// The output's edges within twice the asked size of a point of the field (the cells around
  /// it), against that size.
  static nlohmann::json size_field_json(const SizeField& field, const StructuralModel& input,
                                        const StructuralModel& output, Logger& log) {
    const Vec3 shift = output.frame.origin - input.frame.origin;  // output local -> input local
    std::unordered_set<std::uint64_t> seen;
    long edges = 0;
    double length = 0.0, asked = 0.0;
    const ModelTriangles flat = flatten(output);
    for (const Triangle& f : flat.triangles)
      for (int i = 0; i < 3; ++i) {
        const int a = f[i], b = f[(i + 1) % 3];
        if (!seen.insert(edge_key(a, b)).second) continue;
        const Vec3 pa = output.vertices[a] + shift, pb = output.vertices[b] + shift;
        const int p = field.nearest(0.5 * (pa + pb));
        const double h = field.sizes()[p];
        if ((0.5 * (pa + pb) - field.points()[p]).norm() > 2.0 * h) continue;
        ++edges;
        length += (pb - pa).norm();
        asked += h;
      }
    const double mean = edges > 0 ? length / edges : 0.0, want = edges > 0 ? asked / edges : 0.0;
    char line[240];
    std::snprintf(line, sizeof line,
                  "remesh: size field of %zu points: %ld edges within two sizes of them, mean %.4g "
                  "against %.4g asked (%+.1f %%)",
                  field.points().size(), edges, mean, want,
                  edges > 0 ? 100.0 * (mean / want - 1.0) : 0.0);
    log.info(line);
    return {{"points", field.points().size()},
            {"edges_near", edges},
            {"asked", want},
            {"realised", mean}};
  }

  static nlohmann::json refinement_json(const BallRefinementResult& refinement) {
    nlohmann::json rounds = nlohmann::json::array();
    for (const BallRefinementRound& r : refinement.rounds)
      rounds.push_back({{"failures", r.total()},
                        {"holes", r.failures[BallViolation::NotADisk]},
                        {"part_pieces", r.failures[BallViolation::PartPieces]},
                        {"contact_pieces", r.failures[BallViolation::ContactPieces]},
                        {"corners", r.failures[BallViolation::Corners]},
                        {"unlinked", r.failures[BallViolation::Unlinked]},
                        {"below_min_feature", r.merges},
                        {"wedges", r.wedges},
                        {"below_min_size", r.unrefinable},
                        {"refined", r.refined},
                        {"seeds_added", r.seeds_added},
                        {"seconds", r.seconds}});
    return {{"seeds_added", refinement.seeds_added},
            {"rounds", std::move(rounds)},
            {"merges_left", refinement.merges_left},
            {"wedges_left", refinement.wedges_left},
            {"failures_left", refinement.failures_left}};
  }
  static nlohmann::json features_json(const std::vector<VertexFeature>& features) {
    nlohmann::json list = nlohmann::json::array();
    for (const VertexFeature& f : features) list.push_back({{"kind", feature_kind(f.kind)}, {"id", f.id}});
    return list;
  }
  static nlohmann::json topology_json(const TopologyReport& t, const StructuralModel& input) {
    auto counts = [](const FeatureCounts& c) {
      return nlohmann::json{{"surfaces", c.surfaces}, {"contacts", c.contacts}, {"corners", c.corners}, {"regions", c.regions}};
    };
    nlohmann::json merges = nlohmann::json::array();
    for (const FeatureMerge& m : t.merges) {
      const Vec3 x = m.location + input.frame.origin;
      merges.push_back({{"reason", to_string(m.reason)},
                        {"seed", m.seed},
                        {"location", {x.x(), x.y(), x.z()}},
                        {"features", features_json(m.features)}});
    }
    const double cell = t.features.resolution;
    nlohmann::json lost = nlohmann::json::array();
    for (const LostRegion& r : t.features.regions_lost)
      lost.push_back({{"index", r.region},
                      {"name", input.regions[static_cast<size_t>(r.region)].name},
                      {"thickness", r.thickness},
                      {"larger_than_resolution", r.thickness >= cell}});
    nlohmann::json gained = nlohmann::json::array();
    for (const GainedRegion& g : t.regions_gained) {
      const Vec3 x = g.location + input.frame.origin;
      gained.push_back({{"index", g.output_region},
                        {"like", g.like_input >= 0 ? nlohmann::json(input.regions[static_cast<size_t>(g.like_input)].name)
                                                   : nlohmann::json()},
                        {"volume", g.volume},
                        {"location", {x.x(), x.y(), x.z()}}});
    }
    nlohmann::json pockets = nlohmann::json::array();
    for (const PocketRemoval& r : t.pockets_removed) {
      const Vec3 x = r.location + input.frame.origin;
      pockets.push_back({{"joined", r.region},
                         {"parts_removed", r.parts},
                         {"parts_relabeled", r.relabeled},
                         {"triangles", r.triangles},
                         {"volume", r.volume},
                         {"thickness", r.thickness},
                         {"neck", r.neck},
                         {"location", {x.x(), x.y(), x.z()}}});
    }
    nlohmann::json contacts_lost = nlohmann::json::array();
    for (const LostRegionContact& c : t.features.region_contacts_lost)
      contacts_lost.push_back({{"regions", {c.a, c.b}},
                               {"names", {input.regions[static_cast<size_t>(c.a)].name,
                                          input.regions[static_cast<size_t>(c.b)].name}},
                               {"width", c.width},
                               {"larger_than_resolution", c.width >= cell}});
    nlohmann::json features = nlohmann::json::array();
    for (const LostFeature& f : t.features.lost) {
      const Vec3 x = f.location + input.frame.origin;
      features.push_back({{"kind", feature_kind(f.kind)},
                          {"id", f.id},
                          {"name", feature_name(f, input)},
                          {"size", f.size},
                          {"larger_than_resolution", f.size >= cell},
                          {"location", {x.x(), x.y(), x.z()}}});
    }
    return {{"before", counts(t.input)},
            {"after", counts(t.output)},
            {"regions_preserved", t.regions_preserved},
            {"regions_lost", lost},
            {"regions_gained", gained},
            {"pockets_removed", pockets},
            {"region_contacts_lost", contacts_lost},
            {"region_contacts_gained", t.contacts_gained},
            {"merges", merges},
            {"resolution", t.features.resolution},
            {"features_lost", features},
            {"features_lost_larger_than_resolution", t.features.larger_than_resolution()}};
  }
  // The clean-up keeps every triangle facing the input's regions: when the input lists a
  // region's sides so that they do not enclose it (a wrong volume sign, what `voroseal check`
  // calls region_orientation), its "leaks" refer to regions that are not there.
  static void warn_about_region_signs(const StructuralModel& model, const Logger& log) {
    std::string wrong;
    for (const Region& r : model.regions)
      if (!r.sides.empty() && !(model.signed_volume(r.sides) < 0.0))
        wrong += (wrong.empty() ? "'" : ", '") + r.name + "'";
    // A set of surfaces bounding no region has a universe of no volume: said once, later.
    if (!model.regions.empty() && !model.universe.sides.empty() &&
        !(model.signed_volume(model.universe.sides) > 0.0))
      wrong += (wrong.empty() ? "'" : ", '") + model.universe.name + "'";
    if (!wrong.empty())
      log.warning("remesh: input regions " + wrong +
                  " do not enclose their volume with the sides listed (run `voroseal check` on the input): the "
                  "clean-up's leak counts refer to them, the output's regions are inferred from its surfaces");
  }
  // A part's name; a contact's parts; a corner's contacts.
  static std::string feature_name(const LostFeature& f, const StructuralModel& input) {
    if (f.kind == VertexFeature::Surface) return input.parts[static_cast<size_t>(f.id)].name;
    std::string name;
    auto add = [&](const std::string& s) { name += (name.empty() ? "" : " / ") + s; };
    if (f.kind == VertexFeature::Contact)
      for (int part : input.contacts[static_cast<size_t>(f.id)].parts) add(input.parts[static_cast<size_t>(part)].name);
    else
      for (int c : input.corners[static_cast<size_t>(f.id)].contacts) add("contact " + std::to_string(c));
    return name;
  }
  static void print_topology(const Logger& log, const TopologyReport& t, const StructuralModel& input) {
    char line[256];
    std::snprintf(line, sizeof line, "remesh: surfaces %d -> %d, contacts %d -> %d, corners %d -> %d, regions %d -> %d%s",
                  t.input.surfaces, t.output.surfaces, t.input.contacts, t.output.contacts, t.input.corners,
                  t.output.corners, t.input.regions, t.output.regions,
                  t.regions_preserved ? " (regions and their adjacency preserved)" : " (REGIONS CHANGED)");
    log.info(line);
    const double cell = t.features.resolution;
    auto compared = [&](double size) {
      std::snprintf(line, sizeof line, "%.4g, %s a cell of %.4g", size, size < cell ? "smaller than" : "LARGER than",
                    cell);
      return std::string(line);
    };
    for (const LostRegion& r : t.features.regions_lost)
      log.warning("remesh: input region " + std::to_string(r.region) + " '" +
                  input.regions[static_cast<size_t>(r.region)].name +
                  "' has no region of its own in the output (thickness 2V/A " + compared(r.thickness) +
                  "): try a finer --edge-length or a smaller --min-feature");
    for (const GainedRegion& g : t.regions_gained) {
      const Vec3 x = g.location + input.frame.origin;
      std::snprintf(line, sizeof line, "volume %.4g, around %.10g %.10g %.10g", g.volume, x.x(), x.y(), x.z());
      log.warning("remesh: output region " + std::to_string(g.output_region) + " (" + line +
                  ") is no input region of its own: a pocket closed between surfaces" +
                  (g.like_input >= 0 ? " inside '" + input.regions[static_cast<size_t>(g.like_input)].name + "'"
                                     : std::string()) +
                  "; try a finer --edge-length");
    }
    if (!t.pockets_removed.empty())
      log.info("remesh: " + std::to_string(t.pockets_removed.size()) +
               " pockets closed between surfaces that lie closer than the resolution (thinner than "
               "a cell, or cut off where the input is thinner than d_min), opened again by "
               "removing sides (JSON: topology.pockets_removed)");
    auto name = [&](int r) { return "'" + input.regions[static_cast<size_t>(r)].name + "'"; };
    for (const LostRegionContact& c : t.features.region_contacts_lost)
      log.warning("remesh: regions " + name(c.a) + " and " + name(c.b) +
                  " touch in the input, not in the output (widest part between them " + compared(c.width) + ")");
    for (const auto& [a, b] : t.contacts_gained)
      log.warning("remesh: regions " + name(a) + " and " + name(b) + " touch in the output, not in the input");
    if (!t.merges.empty())
      log.warning(
          "remesh: " + std::to_string(t.merges.size()) +
          " features merged where the resolution is coarser than them (see the JSON report)");
    const int small = static_cast<int>(std::count_if(t.features.lost.begin(), t.features.lost.end(),
                                                     [&](const LostFeature& f) { return f.size < cell; }));
    if (small > 0) {
      std::snprintf(line, sizeof line,
                    "remesh: %d input surfaces, contacts or corners smaller than a cell (%.4g) have no "
                    "counterpart in the output (JSON: topology.features_lost)",
                    small, t.features.resolution);
      log.warning(line);
    }
    for (const LostFeature& f : t.features.lost) {
      if (f.size < cell) continue;
      const Vec3 x = f.location + input.frame.origin;
      std::snprintf(line, sizeof line, "size %.4g, at %.10g %.10g %.10g", f.size, x.x(), x.y(), x.z());
      log.warning("remesh: input " + std::string(feature_kind(f.kind)) + " " + std::to_string(f.id) + " (" +
                  feature_name(f, input) + ", " + line +
                  ") is larger than a cell and has no counterpart in the output: try a finer --edge-length or a "
                  "smaller --min-feature");
    }
  }
};

}  // namespace

}  // namespace voroseal

void voroseal_register_remesh(voroseal::ModuleRegistry& registry) {
  registry.add(std::make_unique<voroseal::RemeshModule>());
}
