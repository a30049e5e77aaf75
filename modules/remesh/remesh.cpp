#include "modules/remesh/remesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>
#include <memory>
#include <set>

#include "framework/core/error.h"
#include "framework/host/process_memory.h"
#include "framework/model/model_builder.h"
#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/seed_sampling.h"
#include "modules/remesh/surface_projection.h"

namespace voroseal {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

FeatureCounts counts_of(const StructuralModel& m) {
  return {static_cast<int>(m.parts.size()), static_cast<int>(m.contacts.size()), static_cast<int>(m.corners.size()),
          static_cast<int>(m.regions.size())};
}

/// Points where two sides of a region meet (its contacts joining two of its parts), about
/// kRimPoints of them spread over those contacts; the model's local frame.
std::vector<Vec3> pocket_rim(const StructuralModel& model, const std::vector<Side>& sides) {
  constexpr size_t kRimPoints = 8;
  std::set<int> parts;
  for (const Side& s : sides) parts.insert(s.part);
  std::vector<int> rim;
  for (const Contact& c : model.contacts) {
    int own = 0;
    for (int p : c.parts) own += static_cast<int>(parts.count(p));
    if (own >= 2) rim.insert(rim.end(), c.vertices.begin(), c.vertices.end());
  }
  std::vector<Vec3> points;
  const size_t stride = std::max<size_t>(1, rim.size() / kRimPoints);
  for (size_t i = stride / 2; i < rim.size(); i += stride) points.push_back(model.vertices[rim[i]]);
  return points;
}

// Where the density is zero the cells are as large as the model allows: a size cap keeps the
// smoothing's weights finite.
constexpr double kMaxRelativeSize = 1e3;

}  // namespace

StructuralModel model_from_remeshed(const RemeshedSurface& surface, const StructuralModel& input,
                                    TopologyReport* report, double resolution) {
  SurfaceSoup soup;
  soup.source = input.name;
  soup.points.reserve(surface.vertices.size());
  for (const Vec3& v : surface.vertices) soup.points.push_back(v + input.frame.origin);
  soup.triangles = surface.triangles;
  // One group per input part that still has triangles.
  std::vector<int> group_index(input.parts.size(), -1);
  std::vector<int> part_of_group;
  for (int p : surface.triangle_part) {
    if (group_index[p] >= 0) continue;
    group_index[p] = static_cast<int>(soup.groups.size());
    part_of_group.push_back(p);
    soup.groups.push_back(group_of_part(input, p));
  }
  soup.triangle_group.reserve(surface.triangle_part.size());
  for (int p : surface.triangle_part) soup.triangle_group.push_back(group_index[p]);
  if (soup.triangles.empty()) throw MesherError("remesh: the resolution is too coarse, no triangle was built");

  BuildOptions options;
  options.weld_tolerance = 0.0;  // the remesher's vertices are unique by construction
  StructuralModel out = build_model(soup, options);
  out.name = input.name;

  // Map every output region to the input region its sides came from (majority of side votes).
  const auto input_sides = input.part_regions();
  auto input_region_of_side = [&](const Side& s) {
    const int p = part_of_group[out.parts[s.part].source_group];
    return s.positive ? input_sides[p].first : input_sides[p].second;
  };
  std::vector<int> match(out.regions.size(), -1);
  for (size_t r = 0; r < out.regions.size(); ++r) {
    std::map<int, int> votes;
    for (const Side& s : out.regions[r].sides) ++votes[input_region_of_side(s)];
    int best = -1, best_votes = 0;
    for (const auto& [region, n] : votes)
      if (region >= 0 && n > best_votes) {
        best = region;
        best_votes = n;
      }
    match[r] = best;
  }
  // Order output regions as the input's, the one with most sides first where several match one
  // input region; keep names and layers. The others (pockets the remesh closed between two
  // surfaces) are named after it with a suffix and reported.
  std::vector<int> order(out.regions.size());
  for (size_t r = 0; r < order.size(); ++r) order[r] = static_cast<int>(r);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const int ka = match[a] < 0 ? 1 << 30 : match[a], kb = match[b] < 0 ? 1 << 30 : match[b];
    if (ka != kb) return ka < kb;
    return out.regions[a].sides.size() > out.regions[b].sides.size();
  });
  std::vector<Region> regions;
  std::vector<int> new_index(out.regions.size());
  std::vector<int> output_of_input(input.regions.size(), -1);
  std::vector<GainedRegion> gained;
  for (int r : order) {
    Region region = out.regions[r];
    const int index = static_cast<int>(regions.size());
    if (match[r] >= 0 && output_of_input[match[r]] < 0) {
      region.name = input.regions[match[r]].name;
      output_of_input[match[r]] = index;
    } else {
      region.name = (match[r] >= 0 ? input.regions[match[r]].name : std::string("region")) + "_pocket" +
                    std::to_string(gained.size() + 1);
      BoundingBox box;
      for (const Side& side : region.sides)
        for (int v : out.parts[side.part].model_vertex) box.extend(out.vertices[v]);
      const Vec3 middle = box.empty() ? Vec3(Vec3::Zero()) : box.center();
      const Vec3 shift = out.frame.origin - input.frame.origin;
      gained.push_back({index, match[r], std::abs(out.signed_volume(region.sides)), middle + shift,
                        pocket_rim(out, region.sides)});
      for (Vec3& x : gained.back().rim) x += shift;
    }
    new_index[r] = index;
    regions.push_back(std::move(region));
  }
  out.regions = std::move(regions);
  out.universe.name = input.universe.name.empty() ? "Universe" : input.universe.name;
  out.layers.clear();
  for (const Layer& layer : input.layers) {
    Layer l{layer.name, {}};
    for (int r : layer.regions)
      if (output_of_input[r] >= 0) l.regions.push_back(output_of_input[r]);
    out.layers.push_back(std::move(l));
  }

  if (report != nullptr) {
    report->input = counts_of(input);
    report->output = counts_of(out);
    report->output_region_of_input = output_of_input;
    report->regions_gained = gained;
    bool preserved = out.regions.size() == input.regions.size();
    for (int r : output_of_input) preserved = preserved && r >= 0;
    // Adjacency through the matching: pairs of input regions that touch in one model only.
    const auto a_in = input.region_adjacency();
    const auto a_out = out.region_adjacency();
    std::vector<int> input_of_output(out.regions.size(), -1);
    for (size_t r = 0; r < output_of_input.size(); ++r)
      if (output_of_input[r] >= 0) input_of_output[output_of_input[r]] = static_cast<int>(r);
    std::set<std::pair<int, int>> touch_in, touch_out;
    for (size_t r = 0; r < a_in.size(); ++r)
      for (int n : a_in[r])
        if (static_cast<int>(r) < n && output_of_input[r] >= 0 && output_of_input[n] >= 0)
          touch_in.insert({static_cast<int>(r), n});
    for (size_t r = 0; r < a_out.size(); ++r)
      for (int n : a_out[r]) {
        const int a = input_of_output[r], b = input_of_output[n];
        if (a >= 0 && b >= 0 && a < b) touch_out.insert({a, b});
      }
    std::set_difference(touch_in.begin(), touch_in.end(), touch_out.begin(), touch_out.end(),
                        std::back_inserter(report->contacts_lost));
    std::set_difference(touch_out.begin(), touch_out.end(), touch_in.begin(), touch_in.end(),
                        std::back_inserter(report->contacts_gained));
    report->regions_preserved = preserved && report->contacts_lost.empty() && report->contacts_gained.empty();
    std::vector<int>& input_part = report->input_part_of_output;
    input_part.resize(out.parts.size());
    for (size_t p = 0; p < out.parts.size(); ++p) input_part[p] = part_of_group[out.parts[p].source_group];
    std::vector<int> lost;
    for (size_t r = 0; r < output_of_input.size(); ++r)
      if (output_of_input[r] < 0) lost.push_back(static_cast<int>(r));
    report->features = audit_features(input, out, input_part, lost, report->contacts_lost, resolution);
  }
  return out;
}

RemeshResult remesh(const StructuralModel& input, const RemeshOptions& options, Logger& log, Progress& progress) {
  return remesh_from_seeds(input, optimize_seeds(input, options.seeds, log, progress), options, log,
                           progress);
}

RemeshResult remesh_from_seeds(const StructuralModel& input, SeedOptimizationResult seeds,
                               const RemeshOptions& options, Logger& log, Progress& progress) {
  RemeshResult result;
  result.seeds = std::move(seeds);
  CleanupOptions cleanup = options.cleanup;
  // The density the seeds were optimised for (the options' when the seeds do not say).
  auto seed_density = [&]() -> const std::vector<double>& {
    return result.seeds.vertex_density.empty() ? options.seeds.vertex_density
                                               : result.seeds.vertex_density;
  };
  auto t0 = std::chrono::steady_clock::now();
  // d_min from the resolution asked for; the refinement splits every cell whose pieces are
  // farther apart than that (all of them with keep_topology) before the mesh is built.
  const double h0 =
      result.seeds.edge_length > 0.0
          ? result.seeds.edge_length
          : edge_length_for_seeds(ModelGeometry(input, seed_density()).root_mass(),
                                  static_cast<int>(result.seeds.seeds.size()));
  if (options.keep_topology) cleanup.min_feature = 0.0;
  if (cleanup.min_feature < 0.0) cleanup.min_feature = -cleanup.min_feature * h0;
  BallRefinementOptions refine = options.refinement;
  refine.min_feature = cleanup.min_feature;
  refine.threads = options.seeds.threads;
  if (options.keep_topology) {
    refine.min_size = h0 / kKeepTopologyRefinement;
  } else {
    refine.min_size = std::max(refine.min_size, cleanup.min_feature);
  }
  if (refine.max_rounds > 0) {
    ProgressStep step(progress, "remesh: topological ball refinement", refine.max_rounds);
    result.refinement =
        refine_until_ball_property(input, result.seeds, options.seeds, refine, log, progress);
    step.finish();
  }
  result.refinement_seconds = seconds_since(t0);
  result.refinement_memory = process_memory();

  t0 = std::chrono::steady_clock::now();
  ProgressStep building(progress, "remesh: mesh building");
  std::unique_ptr<const SurfaceProjector> projector;
  double resolution = 0.0;  // the length lost features are compared with (FeatureAudit)
  {
    const ModelGeometry geometry(input, seed_density());
    RvdOptions rvd_options;
    rvd_options.threads = options.seeds.threads;
    const RestrictedVoronoiDiagram rvd =
        compute_restricted_voronoi_diagram(geometry, result.seeds.seeds, rvd_options);
    result.rvd_seconds = seconds_since(t0);
    result.rvd_memory = process_memory();
    // What the refinement left, on the diagram the mesh is built from.
    record_ball_failures(input, geometry, rvd, refine, log, result.refinement);
    result.refinement_seconds += result.refinement.rounds.back().seconds;

    t0 = std::chrono::steady_clock::now();
    projector = std::make_unique<const SurfaceProjector>(input);
    // The mean edge length where ρ = 1: what the user's resolution asks for.
    const double h =
        edge_length_for_seeds(geometry.root_mass(), static_cast<int>(result.seeds.seeds.size()));
    MeshBuildOptions build = options.build;
    if (build.sharp_scale == 0.0) build.sharp_scale = 0.5 * h;
    if (cleanup.fidelity_tolerance < 0.0)
      cleanup.fidelity_tolerance = -cleanup.fidelity_tolerance * h;
    result.min_feature = cleanup.min_feature;
    result.build = build_remeshed_surface(input, geometry, rvd, *projector, build);
    result.build_memory = process_memory();
    resolution = 2.0 * h / std::sqrt(3.0);
  }  // The clean-up needs neither the diagram nor the flattened input: freed before it runs.
  result.build_seconds = seconds_since(t0);
  building.finish();
  log.debug("remesh: " + std::to_string(result.build.cell_components) + " cell components, " +
            std::to_string(result.build.contact_components) + " contact components, " +
            std::to_string(result.build.surface.triangles.size()) + " triangles built");
  if (result.build.inconsistencies > 0)
    log.warning("remesh: " + std::to_string(result.build.inconsistencies) +
                " restricted Voronoi vertices could not be matched between cells");

  t0 = std::chrono::steady_clock::now();
  if (options.clean_up) {
    ProgressStep step(progress, "remesh: clean-up");
    // A graded remesh keeps its grading through the smoothing: sizes ρ^(-1/4) of the density.
    if (const std::vector<double>& rho = seed_density(); !rho.empty()) {
      std::vector<double> size(rho.size());
      for (size_t v = 0; v < rho.size(); ++v)
        size[v] =
            rho[v] > 0.0 ? std::min(kMaxRelativeSize, std::pow(rho[v], -0.25)) : kMaxRelativeSize;
      cleanup.target_size = std::make_shared<const SizeField>(input.vertices, std::move(size));
    }
    // The zip (experimental) works inside surfaces the clean-up has not finished repairing, and
    // the last repair can then fail where it succeeds without it (modelA6 with --thin-layers: the
    // zip closed a coincident pair of triangles next to a leak the mesh building had left, and
    // the leak stayed). A clean-up that left the surfaces invalid runs again without the zip,
    // and the more valid result stays.
    const bool zips = cleanup.zip_wedge_deg > 0.0;
    RemeshedSurface built = zips ? result.build.surface : RemeshedSurface{};
    result.cleanup = clean_up(result.build.surface, input, *projector, cleanup, &progress);
    const int zipped_edits = result.cleanup.pinch_zips + result.cleanup.pinch_rungs + result.cleanup.pinch_pockets;
    if (zips && zipped_edits > 0 && result.cleanup.invalid_left() > 0) {
      CleanupOptions plain = cleanup;
      plain.zip_wedge_deg = 0.0;
      CleanupReport without = clean_up(built, input, *projector, plain, &progress);
      if (without.invalid_left() < result.cleanup.invalid_left()) {
        log.warning("remesh: the pinch-out zip left the surfaces invalid (" +
                    std::to_string(result.cleanup.invalid_left()) + " defects, " +
                    std::to_string(without.invalid_left()) + " without it): its " + std::to_string(zipped_edits) +
                    " edits were undone");
        without.pinch_zips = result.cleanup.pinch_zips;
        without.pinch_rungs = result.cleanup.pinch_rungs;
        without.pinch_pockets = result.cleanup.pinch_pockets;
        without.pinch_zip_undone = true;
        result.cleanup = std::move(without);
        result.build.surface = std::move(built);
      }
    }
    step.finish();
  }
  result.cleanup_seconds = seconds_since(t0);
  result.cleanup_memory = process_memory();

  result.model = model_from_remeshed(result.build.surface, input, &result.topology, resolution);
  // Pockets thinner than a cell are the resolution's doing: one side goes (a few rounds, as
  // pockets next to each other open one by one). A round is kept only when the regions got
  // closer to the input's: fewer pockets, and no region or region contact lost or gained.
  std::vector<PocketRemoval> pockets;
  auto departures = [](const TopologyReport& t) {
    return std::count(t.output_region_of_input.begin(), t.output_region_of_input.end(), -1) +
           static_cast<long>(t.contacts_lost.size() + t.contacts_gained.size());
  };
  for (int round = 0; options.clean_up && round < 3 && !result.topology.regions_gained.empty(); ++round) {
    RemeshedSurface before = result.build.surface;
    const std::vector<PocketRemoval> removed = remove_pockets(
        result.build.surface, input, result.model, result.topology.input_part_of_output,
        result.topology.output_region_of_input, *projector, resolution, result.min_feature);
    if (removed.empty()) break;
    TopologyReport topology;
    StructuralModel model = model_from_remeshed(result.build.surface, input, &topology, resolution);
    if (topology.regions_gained.size() >= result.topology.regions_gained.size() ||
        departures(topology) > departures(result.topology)) {
      log.debug("remesh: opening " + std::to_string(removed.size()) + " pockets changed other regions; undone");
      result.build.surface = std::move(before);
      break;
    }
    pockets.insert(pockets.end(), removed.begin(), removed.end());
    result.topology = std::move(topology);
    result.model = std::move(model);
  }
  result.topology.pockets_removed = std::move(pockets);
  result.topology.merges = result.build.merges;
  result.topology.merges.insert(result.topology.merges.end(), result.cleanup.merges.begin(), result.cleanup.merges.end());
  result.build.surface = RemeshedSurface{};
  return result;
}

}  // namespace voroseal
