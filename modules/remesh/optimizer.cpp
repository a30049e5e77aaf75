#include "modules/remesh/optimizer.h"

#include <LBFGS.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <algorithm>
#include <stdexcept>

#include "framework/core/error.h"

#ifdef VOROSEAL_HAVE_CERES
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/iteration_callback.h>
#endif

namespace voroseal {

const char* to_string(OptimizerKind kind) {
  switch (kind) {
    case OptimizerKind::Lbfgs: return "lbfgs";
    case OptimizerKind::Lloyd: return "lloyd";
    case OptimizerKind::Ceres: return "ceres";
  }
  return "?";
}

OptimizerKind optimizer_from_string(const std::string& name) {
  if (name == "lbfgs") return OptimizerKind::Lbfgs;
  if (name == "lloyd") return OptimizerKind::Lloyd;
  if (name == "ceres") return OptimizerKind::Ceres;
  throw ParameterError("remesh: unknown optimizer '" + name + "' (lbfgs, lloyd, ceres)");
}

bool ceres_available() {
#ifdef VOROSEAL_HAVE_CERES
  return true;
#else
  return false;
#endif
}

double SeedObjective::evaluate(const std::vector<Vec3>& seeds, std::vector<Vec3>& gradient) {
  energy_.evaluate(seeds, last_, alpha_ > 0.0);
  ++evaluations_;
  const int n = static_cast<int>(seeds.size());
  gradient.resize(n);
  for (int i = 0; i < n; ++i)
    gradient[i] = (1.0 - alpha_) * last_.cvt_gradient[i] + alpha_ * last_.boundary_gradient[i];
  return (1.0 - alpha_) * last_.cvt + alpha_ * last_.boundary;
}

double boundary_weight_from_gradients(const EnergyEvaluation& e) {
  double gc = 0.0, gb = 0.0;
  for (const Vec3& g : e.cvt_gradient) gc += g.squaredNorm();
  for (const Vec3& g : e.boundary_gradient) gb += g.squaredNorm();
  gc = std::sqrt(gc);
  gb = std::sqrt(gb);
  if (!(gb > 0.0) || !std::isfinite(gb)) return 0.0;
  return gc / (gc + gb);
}

namespace {

using Clock = std::chrono::steady_clock;

double norm(const std::vector<Vec3>& g) {
  double s = 0.0;
  for (const Vec3& v : g) s += v.squaredNorm();
  return std::sqrt(s);
}

// Thrown by the iteration callback to end a run early (limit or threshold reached).
struct StopRun {
  std::string reason;
};

// The objective in scaled coordinates x = (p − centre) / h, F̂ = F / (A h²), with h the mean
// seed spacing sqrt(A / N): seeds move O(1) per iteration whatever the model's units.
class ScaledProblem {
 public:
  ScaledProblem(SeedObjective& objective, const std::vector<Vec3>& start, const OptimizerOptions& options,
                Logger& log, Progress& progress)
      : objective_(objective), options_(options), log_(log), progress_(progress), started_(Clock::now()) {
    const ModelGeometry& g = objective.energy().geometry();
    n_ = static_cast<int>(start.size());
    centre_ = g.bbox().center();
    h_ = std::sqrt(g.area() / std::max(1, n_));
    if (!(h_ > 0.0)) h_ = 1.0;
    fscale_ = g.area() * h_ * h_;
    seeds_ = start;
    best_seeds_ = start;
    if (!options.fixed.empty()) start_ = start;
  }

  Eigen::VectorXd to_x(const std::vector<Vec3>& seeds) const {
    Eigen::VectorXd x(3 * n_);
    for (int i = 0; i < n_; ++i) x.segment<3>(3 * i) = (seeds[i] - centre_) / h_;
    return x;
  }
  void to_seeds(const double* x, std::vector<Vec3>& seeds) const {
    seeds.resize(n_);
    for (int i = 0; i < n_; ++i)
      seeds[i] = is_fixed(i) ? start_[i] : centre_ + h_ * Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
  }

  // F̂(x) and ∇F̂(x). A non-finite trial point (a wild line-search step) gets F = +inf, which
  // every line search rejects, instead of reaching the k-d tree.
  double evaluate(const double* x, double* grad) {
    for (int i = 0; i < 3 * n_; ++i)
      if (!std::isfinite(x[i])) {
        if (grad != nullptr) std::fill(grad, grad + 3 * n_, 0.0);
        return std::numeric_limits<double>::infinity();
      }
    to_seeds(x, seeds_);
    const double f = objective_.evaluate(seeds_, gradient_);
    hold_fixed(gradient_);
    const double gs = h_ / fscale_;
    if (grad != nullptr)
      for (int i = 0; i < n_; ++i)
        for (int k = 0; k < 3; ++k) grad[3 * i + k] = gs * gradient_[i][k];
    last_f_ = f;
    last_gnorm_ = norm(gradient_);
    const double scaled = f / fscale_;
    remember(scaled, f);
    if (history_.empty()) record(0, f, last_gnorm_);  // the start
    return scaled;
  }

  // An accepted iteration at x with scaled value fx and scaled gradient norm gnorm_scaled.
  // Throws StopRun when the run must end.
  void accept(const double* x, double fx, double gnorm_scaled) {
    double f = fx * fscale_;
    for (const Terms& t : recent_)
      if (t.scaled == fx) f = t.f;  // the exact unscaled value
    const double gnorm = gnorm_scaled * fscale_ / h_;
    to_seeds(x, best_seeds_);
    record(++iteration_, f, gnorm);
    progress_.advance();
    if (iteration_ >= options_.max_iterations) throw StopRun{"iterations"};
    if (gnorm <= options_.gradient_threshold * history_.front().gradient_norm) throw StopRun{"gradient"};
    if (energy_stalled()) throw StopRun{"energy"};
  }

  // F fell by less than energy_tolerance · (F_0 − F) over the last kEnergyStopWindow
  // iterations: relative to the decrease so far, so it does not depend on F's scale.
  bool energy_stalled() const {
    const int n = static_cast<int>(history_.size());
    if (options_.energy_tolerance <= 0.0 || n <= kEnergyStopWindow) return false;
    const double now = history_.back().energy;
    const double recent = history_[n - 1 - kEnergyStopWindow].energy - now;
    return recent < options_.energy_tolerance * (history_.front().energy - now);
  }

  // Lloyd: plain iterations on seeds.
  OptimizationRun lloyd(std::vector<Vec3>& seeds) {
    OptimizationRun run;
    std::vector<Vec3> current = seeds;
    for (int it = 0;; ++it) {
      const double f = objective_.evaluate(current, gradient_);
      hold_fixed(gradient_);
      const double gnorm = norm(gradient_);
      remember(f / fscale_, f);
      record(it, f, gnorm);
      iteration_ = it;
      seeds = current;
      if (it > 0) progress_.advance();
      if (it >= options_.max_iterations) {
        run.stop_reason = "iterations";
        break;
      }
      if (it > 0 && gnorm <= options_.gradient_threshold * history_.front().gradient_norm) {
        run.stop_reason = "gradient";
        break;
      }
      if (energy_stalled()) {
        run.stop_reason = "energy";
        break;
      }
      const EnergyEvaluation& e = objective_.last();
      for (int i = 0; i < n_; ++i)
        if (e.mass[i] > 0.0 && !is_fixed(i)) current[i] = e.centroid[i];
    }
    run.history = history_;
    run.evaluations = objective_.evaluations();
    return run;
  }

  double h() const { return h_; }
  double fscale() const { return fscale_; }
  int iteration() const { return iteration_; }
  const std::vector<Vec3>& best_seeds() const { return best_seeds_; }
  const std::vector<IterationRecord>& history() const { return history_; }
  double last_gnorm() const { return last_gnorm_; }
  Logger& log() { return log_; }

 private:
  std::vector<Vec3> start_;  // where the fixed seeds stay (scaling back and forth rounds)
  bool is_fixed(int i) const {
    return static_cast<size_t>(i) < options_.fixed.size() && options_.fixed[i] != 0;
  }
  // A fixed seed's gradient is zero: no optimiser moves it, and the stop tests ignore it.
  void hold_fixed(std::vector<Vec3>& gradient) const {
    for (int i = 0; i < n_; ++i)
      if (is_fixed(i)) gradient[i].setZero();
  }
  // Terms of recent evaluations, to report F_CVT and F_B of the point an optimiser accepted
  // (the accepted point is almost always the last evaluated one, but not by contract).
  struct Terms {
    double scaled, f, cvt, boundary;
  };
  void remember(double scaled, double f) {
    recent_[next_recent_++ % recent_.size()] = {scaled, f, objective_.last().cvt, objective_.last().boundary};
  }
  void record(int iteration, double f, double gnorm) {
    IterationRecord r;
    r.iteration = iteration;
    r.energy = f;
    r.gradient_norm = gnorm;
    r.cvt = r.boundary = std::nan("");
    for (const Terms& t : recent_)
      if (t.f == f) {
        r.cvt = t.cvt;
        r.boundary = t.boundary;
      }
    r.evaluations = objective_.evaluations();
    r.seconds = std::chrono::duration<double>(Clock::now() - started_).count();
    history_.push_back(r);
    char line[200];
    std::snprintf(line, sizeof line, "remesh: iteration %3d  F = %.10g  (F_CVT %.6g, F_B %.6g)  |grad F| = %.4g",
                  iteration, f, r.cvt, r.boundary, gnorm);
    log_.debug(line);
  }

  SeedObjective& objective_;
  const OptimizerOptions& options_;
  Logger& log_;
  Progress& progress_;
  Clock::time_point started_;
  int n_ = 0;
  Vec3 centre_ = Vec3::Zero();
  double h_ = 1.0;
  double fscale_ = 1.0;
  std::vector<Vec3> seeds_, best_seeds_, gradient_;
  std::vector<IterationRecord> history_;
  std::array<Terms, 16> recent_{};
  size_t next_recent_ = 0;
  int iteration_ = 0;
  double last_f_ = 0.0, last_gnorm_ = 0.0;
};

// ---- L-BFGS (LBFGS++) ----

struct LineSearchFailed {};

// The functor LBFGS++ calls.
struct LbfgsFunctor {
  ScaledProblem* problem;
  double operator()(const Eigen::VectorXd& x, Eigen::VectorXd& grad) {
    return problem->evaluate(x.data(), grad.data());
  }
  void accept(const Eigen::VectorXd& x, double fx, const Eigen::VectorXd& grad) {
    problem->accept(x.data(), fx, grad.norm());
  }
};

// LBFGS++'s strong-Wolfe line search, checked and reported: LBFGS++ has no iteration callback,
// and its line search may return a point without sufficient decrease after too many trials.
// Here every accepted step satisfies the Armijo condition (so F decreases monotonically) and
// s·y > 0 (so the L-BFGS update stays positive definite); otherwise the run stops.
template <typename Scalar>
class CheckedLineSearch {
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

 public:
  template <typename Foo>
  static void LineSearch(Foo& f, Scalar& fx, Vector& x, Vector& grad, Scalar& step, const Vector& drt,
                         const Vector& xp, const LBFGSpp::LBFGSParam<Scalar>& param) {
    const Scalar fx0 = fx;
    const Scalar dg0 = grad.dot(drt);
    LBFGSpp::LineSearchNocedalWright<Scalar>::LineSearch(f, fx, x, grad, step, drt, xp, param);
    if (!(fx <= fx0 + param.ftol * step * dg0) || !(fx < fx0) || !(grad.dot(drt) > dg0)) throw LineSearchFailed{};
    f.accept(x, fx, grad);
  }
};

OptimizationRun run_lbfgs(ScaledProblem& problem, std::vector<Vec3>& seeds, const OptimizerOptions& options) {
  LBFGSpp::LBFGSParam<double> param;
  param.m = std::max(1, options.lbfgs_memory);
  param.epsilon = 0.0;  // stopping is decided by ScaledProblem::accept
  param.epsilon_rel = 0.0;
  param.max_iterations = 0;
  param.max_linesearch = 30;
  param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
  param.ftol = 1e-4;
  param.wolfe = 0.9;
  LBFGSpp::LBFGSSolver<double, CheckedLineSearch> solver(param);
  LbfgsFunctor functor{&problem};
  Eigen::VectorXd x = problem.to_x(seeds);
  double fx = 0.0;
  OptimizationRun run;
  try {
    if (options.max_iterations <= 0) {
      Eigen::VectorXd g(x.size());
      functor(x, g);
      run.stop_reason = "iterations";
    } else {
      solver.minimize(functor, x, fx);
      run.stop_reason = "gradient";  // LBFGS++ found a zero gradient
    }
  } catch (const StopRun& stop) {
    run.stop_reason = stop.reason;
  } catch (const LineSearchFailed&) {
    run.stop_reason = "line search";
  } catch (const std::logic_error&) {
    run.stop_reason = "line search";  // not a descent direction: rounding level reached
  } catch (const std::runtime_error&) {
    run.stop_reason = "line search";
  }
  seeds = problem.best_seeds();
  run.history = problem.history();
  return run;
}

// ---- Ceres ----

#ifdef VOROSEAL_HAVE_CERES
class CeresFunction final : public ceres::FirstOrderFunction {
 public:
  CeresFunction(ScaledProblem* problem, int n) : problem_(problem), n_(n) {}
  bool Evaluate(const double* x, double* cost, double* gradient) const override {
    *cost = problem_->evaluate(x, gradient);
    return std::isfinite(*cost);
  }
  int NumParameters() const override { return 3 * n_; }

 private:
  ScaledProblem* problem_;
  int n_;
};

class CeresCallback final : public ceres::IterationCallback {
 public:
  CeresCallback(ScaledProblem* problem, const double* x) : problem_(problem), x_(x) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (s.iteration == 0 || !s.step_is_successful) return ceres::SOLVER_CONTINUE;
    try {
      problem_->accept(x_, s.cost, s.gradient_norm);
    } catch (const StopRun& stop) {
      reason = stop.reason;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  std::string reason;

 private:
  ScaledProblem* problem_;
  const double* x_;
};

OptimizationRun run_ceres(ScaledProblem& problem, std::vector<Vec3>& seeds, const OptimizerOptions& options) {
  const int n = static_cast<int>(seeds.size());
  Eigen::VectorXd x = problem.to_x(seeds);
  OptimizationRun run;
  if (options.max_iterations <= 0) {
    Eigen::VectorXd g(x.size());
    problem.evaluate(x.data(), g.data());
    run.stop_reason = "iterations";
    run.history = problem.history();
    return run;
  }
  ceres::GradientProblem gp(new CeresFunction(&problem, n));
  ceres::GradientProblemSolver::Options o;
  o.line_search_direction_type = ceres::LBFGS;
  o.line_search_type = ceres::WOLFE;
  o.max_lbfgs_rank = std::max(1, options.lbfgs_memory);
  // Scale the initial inverse Hessian by s·y / y·y as LBFGS++ does (Ceres defaults to the identity,
  // which converges far more slowly on the CVT energy).
  o.use_approximate_eigenvalue_bfgs_scaling = true;
  o.max_num_iterations = options.max_iterations + 1;  // the callback stops at max_iterations
  o.function_tolerance = 1e-16;
  o.gradient_tolerance = 1e-300;
  o.parameter_tolerance = 1e-16;
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  o.update_state_every_iteration = true;  // so the callback sees the accepted parameters
  CeresCallback callback(&problem, x.data());
  o.callbacks.push_back(&callback);
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(o, gp, x.data(), &summary);
  run.stop_reason = !callback.reason.empty() ? callback.reason : "no progress";
  problem.log().debug("remesh: " + summary.BriefReport() + " (" + summary.message + ")");
  problem.to_seeds(x.data(), seeds);
  run.history = problem.history();
  return run;
}
#endif

}  // namespace

OptimizationRun minimize_seed_energy(SeedObjective& objective, std::vector<Vec3>& seeds,
                                     const OptimizerOptions& options, Logger& log, Progress& progress) {
  if (options.kind == OptimizerKind::Ceres && !ceres_available())
    throw ParameterError("remesh: optimizer 'ceres' is not available: voroseal was built without Ceres");
  if (seeds.empty()) throw ParameterError("remesh: no seed to optimise");
  ScaledProblem problem(objective, seeds, options, log, progress);
  ProgressStep step(progress, "remesh: optimising seeds", std::max(0, options.max_iterations));
  OptimizationRun run;
  switch (options.kind) {
    case OptimizerKind::Lbfgs: run = run_lbfgs(problem, seeds, options); break;
    case OptimizerKind::Lloyd: run = problem.lloyd(seeds); break;
    case OptimizerKind::Ceres:
#ifdef VOROSEAL_HAVE_CERES
      run = run_ceres(problem, seeds, options);
#endif
      break;
  }
  step.finish();
  run.evaluations = objective.evaluations();
  return run;
}

}  // namespace voroseal
