// Speed of the seed optimisation (paper §3.1): one evaluation of F and ∇F (restricted Voronoi
// diagram + F_CVT + F_B), and a 100-iteration L-BFGS run, on
//   sphere50k   a bumpy sphere of 50,700 triangles with 5k and 30k seeds,
//   sphere500k  the same with 499,392 triangles and 50k seeds,
//   cloudspin   ../shared/models/ring/CloudSpin_fixed.ml (30,751 triangles) with 5k and 10k seeds.
// Evaluate: at the initial random sampling, after two warm-up calls (start seeds of the
// triangles known, neighbour lists kept: the steady state inside an optimisation).
// EvaluateRebuild: the same, but the neighbour lists are searched anew at every call.
// Lbfgs100: 100 L-BFGS iterations from the random sampling (counters: evaluations, mean time
// per evaluation, share of evaluations that rebuilt the neighbour lists).
// Project: 100,000 closest points on sphere500k's surface, single-threaded, from points moved
// off its vertices by up to 3 input edges, each searched from its vertex (SurfaceProjector's
// hinted query, as the clean-up makes it after a move) and without a hint.
// Threads: OpenMP's default (OMP_NUM_THREADS). Counter cpu_ms: CPU time of all threads per
// iteration (on a loaded machine the wall time of a parallel run mostly measures the load).
#include <benchmark/benchmark.h>

#include <time.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/optimizer.h"
#include "modules/remesh/seed_energy.h"
#include "modules/remesh/seed_sampling.h"
#include "modules/remesh/surface_projection.h"
#include "tests/modules/remesh/synthetic_surfaces.h"

namespace {

using namespace voroseal;

// CPU time of the whole process (all threads), in ms: on a loaded machine wall-clock times of
// multi-threaded runs mostly measure the other processes, this does not.
double process_cpu_ms() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

struct Case {
  std::string model;  // "sphere50k", "sphere500k", "cloudspin"
  int seeds;
};

struct Loaded {
  StructuralModel model;
  std::unique_ptr<ModelGeometry> geometry;
};

std::string cloudspin_path() {
  if (const char* s = std::getenv("VOROSEAL_SHARED_MODELS")) return std::string(s) + "/ring/CloudSpin_fixed.ml";
  return std::string(VOROSEAL_SOURCE_DIR) + "/../shared/models/ring/CloudSpin_fixed.ml";
}

// Models are built once per process and shared by the benchmarks.
const Loaded* load(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Loaded>> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second.get();
  auto l = std::make_unique<Loaded>();
  if (name == "sphere50k") {
    l->model = build_model(test::bumpy_sphere(65));
  } else if (name == "sphere500k") {
    l->model = build_model(test::bumpy_sphere(204));
  } else if (name == "cloudspin") {
    if (!std::filesystem::exists(cloudspin_path())) return nullptr;
    l->model = read_model(cloudspin_path());
  }
  l->geometry = std::make_unique<ModelGeometry>(l->model);
  return (cache[name] = std::move(l)).get();
}

void evaluate(benchmark::State& state, const Case& c, bool reuse_lists) {
  const Loaded* m = load(c.model);
  if (m == nullptr) {
    state.SkipWithError("model not found");
    return;
  }
  const std::vector<Vec3> seeds = sample_seeds(*m->geometry, c.seeds, 1);
  SeedEnergy energy(*m->geometry);
  energy.set_reuse_neighbour_lists(reuse_lists);
  EnergyEvaluation e;
  energy.evaluate(seeds, e);
  energy.evaluate(seeds, e);
  const double cpu0 = process_cpu_ms();
  for (auto _ : state) {
    energy.evaluate(seeds, e);
    benchmark::DoNotOptimize(e.cvt);
  }
  state.counters["cpu_ms"] = (process_cpu_ms() - cpu0) / static_cast<double>(state.iterations());
  state.counters["triangles"] = static_cast<double>(m->geometry->triangles().size());
  state.counters["polygons"] = static_cast<double>(e.polygons);
  state.counters["threads"] = energy.threads();
}

void lbfgs100(benchmark::State& state, const Case& c) {
  const Loaded* m = load(c.model);
  if (m == nullptr) {
    state.SkipWithError("model not found");
    return;
  }
  long evaluations = 0, rebuilds = 0;
  double final_energy = 0.0, first_energy = 0.0;
  const double cpu0 = process_cpu_ms();
  for (auto _ : state) {
    std::vector<Vec3> seeds = sample_seeds(*m->geometry, c.seeds, 1);
    SeedEnergy energy(*m->geometry);
    EnergyEvaluation start;
    energy.evaluate(seeds, start);
    SeedObjective objective(energy, boundary_weight_from_gradients(start));
    OptimizerOptions options;
    options.max_iterations = 100;
    options.gradient_threshold = 0.0;
    Logger log(LogLevel::Quiet);
    Progress progress(false);
    const OptimizationRun run = minimize_seed_energy(objective, seeds, options, log, progress);
    evaluations = energy.evaluations();
    rebuilds = energy.list_rebuilds();
    first_energy = run.history.front().energy;
    final_energy = run.history.back().energy;
  }
  state.counters["cpu_ms"] = (process_cpu_ms() - cpu0) / static_cast<double>(state.iterations());
  state.counters["evaluations"] = static_cast<double>(evaluations);
  state.counters["rebuilt_share"] = evaluations > 0 ? static_cast<double>(rebuilds) / evaluations : 0.0;
  state.counters["F_ratio"] = first_energy > 0 ? final_energy / first_energy : 0.0;
  state.counters["ms_per_eval"] =
      benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kIsIterationInvariantRate |
                                                               benchmark::Counter::kInvert);
}

void project(benchmark::State& state, bool hinted) {
  const Loaded* m = load("sphere500k");
  const SurfaceProjector projector(m->model);
  const SurfacePart& part = m->model.parts.front();
  double edge = 0.0;
  for (const auto e : part.mesh.edges()) edge += part.mesh.calc_edge_length(e);
  edge /= static_cast<double>(part.mesh.n_edges());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> offset(-3.0 * edge, 3.0 * edge);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(part.model_vertex.size()) - 1);
  std::vector<Vec3> from, query;
  for (int i = 0; i < 100000; ++i) {
    from.push_back(m->model.vertices[part.model_vertex[vertex(rng)]]);
    query.push_back(from.back() + Vec3(offset(rng), offset(rng), offset(rng)));
  }
  const double cpu0 = process_cpu_ms();
  for (auto _ : state) {
    double sum = 0.0;
    for (size_t i = 0; i < query.size(); ++i)
      sum += hinted ? projector.distance_to_part(0, query[i], from[i])
                    : projector.distance_to_part(0, query[i]);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["cpu_ms"] = (process_cpu_ms() - cpu0) / static_cast<double>(state.iterations());
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::RegisterBenchmark("Project/hinted", [](benchmark::State& s) {
    project(s, true);
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Project/unhinted", [](benchmark::State& s) {
    project(s, false);
  })->Unit(benchmark::kMillisecond);
  const Case cases[] = {{"sphere50k", 5000}, {"sphere50k", 30000}, {"sphere500k", 50000},
                        {"cloudspin", 5000}, {"cloudspin", 10000}};
  for (const Case& c : cases) {
    const std::string name = c.model + "/" + std::to_string(c.seeds);
    benchmark::RegisterBenchmark(("Evaluate/" + name).c_str(), [c](benchmark::State& s) { evaluate(s, c, true); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(1.0);
    benchmark::RegisterBenchmark(("EvaluateRebuild/" + name).c_str(),
                                 [c](benchmark::State& s) { evaluate(s, c, false); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(1.0);
    benchmark::RegisterBenchmark(("Lbfgs100/" + name).c_str(), [c](benchmark::State& s) { lbfgs100(s, c); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
