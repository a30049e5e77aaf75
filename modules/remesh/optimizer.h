// Minimisation of the seed energy F = (1 − α) F_CVT + α F_B (paper §3.1, Algorithm 1):
//  - L-BFGS (default; LBFGS++ with a strong-Wolfe line search, Nocedal & Wright), every
//    accepted iteration lowers F;
//  - Lloyd (for comparison): every seed moves to the centroid of its restricted cell; it
//    minimises F_CVT only (α is ignored);
//  - Ceres GradientProblemSolver (LBFGS direction, Wolfe line search) when voroseal is built
//    with Ceres.
// All stop after `max_iterations` iterations, when ‖∇F‖ ≤ gradient_threshold · ‖∇F(start)‖,
// when F fell by less than energy_tolerance · (F(start) − F) over the last
// kEnergyStopWindow iterations (the rest of the run would buy too little), or earlier when the
// line search cannot lower F any more (converged to rounding).
// Internally seeds are scaled to unit mean spacing and F to O(1) so tolerances do not depend
// on the model's units; everything reported is in model units.
#pragma once

#include <string>
#include <vector>

#include "framework/core/types.h"
#include "framework/host/log.h"
#include "modules/remesh/seed_energy.h"

namespace voroseal {

/// Iterations over which the energy stop measures the decrease of F: long enough that one
/// short L-BFGS step (a curvature correction) does not end the run.
constexpr int kEnergyStopWindow = 10;

enum class OptimizerKind { Lbfgs, Lloyd, Ceres };

const char* to_string(OptimizerKind kind);
/// "lbfgs", "lloyd" or "ceres". \throws ParameterError otherwise.
OptimizerKind optimizer_from_string(const std::string& name);
/// True when this build includes the Ceres optimiser.
bool ceres_available();

struct OptimizerOptions {
  OptimizerKind kind = OptimizerKind::Lbfgs;
  int max_iterations = 100;
  double gradient_threshold = 1e-6;  // relative to the gradient norm at the start
  double energy_tolerance = 0.0;     // relative to the decrease so far; 0: never stop on F
  int lbfgs_memory = 7;              // corrections kept by L-BFGS
  /// Seeds that stay where they are (their gradient is taken as zero); empty: all move. A
  /// repair round re-optimises the seeds around the places it refined, not the others.
  std::vector<char> fixed;
};

/// F = (1 − α) F_CVT + α F_B on top of a SeedEnergy. α is fixed at construction, so F is one
/// fixed function during a run.
class SeedObjective {
 public:
  SeedObjective(SeedEnergy& energy, double alpha) : energy_(energy), alpha_(alpha) {}
  double alpha() const { return alpha_; }
  SeedEnergy& energy() { return energy_; }
  /// F at `seeds`; `gradient` receives ∇F (one Vec3 per seed).
  double evaluate(const std::vector<Vec3>& seeds, std::vector<Vec3>& gradient);
  /// The terms of the last evaluation.
  const EnergyEvaluation& last() const { return last_; }
  long evaluations() const { return evaluations_; }

 private:
  SeedEnergy& energy_;
  double alpha_;
  EnergyEvaluation last_;
  long evaluations_ = 0;
};

/// α from the gradient-norm ratio at `seeds`: chosen so that both terms pull with the same
/// strength at the start, (1 − α)‖∇F_CVT‖ = α‖∇F_B‖, i.e. α = ‖∇F_CVT‖ / (‖∇F_CVT‖ + ‖∇F_B‖)
/// (0 when the model has no contact or F_B has no gradient there).
double boundary_weight_from_gradients(const EnergyEvaluation& at_start);

/// One line of the optimisation log.
struct IterationRecord {
  int iteration = 0;       // 0: the start
  double energy = 0.0;     // F
  double cvt = 0.0;        // F_CVT
  double boundary = 0.0;   // F_B
  double gradient_norm = 0.0;  // ‖∇F‖ (Euclidean over all seeds)
  long evaluations = 0;    // energy evaluations so far
  double seconds = 0.0;    // since the start of the run
};

struct OptimizationRun {
  std::vector<IterationRecord> history;
  long evaluations = 0;
  std::string stop_reason;  // "iterations", "gradient", "energy", "line search", "no progress"
};

/// Minimises `objective` starting from `seeds` (updated in place with the best point found).
/// Logs F and ‖∇F‖ per iteration (debug level while a progress bar is shown, else info) and
/// advances `progress`. \throws ParameterError for Ceres when not built with it.
OptimizationRun minimize_seed_energy(SeedObjective& objective, std::vector<Vec3>& seeds,
                                     const OptimizerOptions& options, Logger& log, Progress& progress);

}  // namespace voroseal
