// The scene runner's templates (run.h), instantiated once per number of
// coordinates (run_dof.cc.in). The variational path runs on
// action::ErasedProblem<d>, so that a registered Lagrangian (RunRegistered)
// compiles only its pointwise derivatives, not the runner and the solvers.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "core/action/erased_problem.h"
#include "problems/composed.h"
#include "problems/composed_hamiltonian.h"
#include "scene/reference.h"
#include "scene/register_lagrangian.h"
#include "scene/run.h"
#include "solvers/steppers/integrate.h"
#include "solvers/steppers/methods.h"
#include "solvers/variational/solve.h"

namespace vivp::scene::detail {

using Clock = std::chrono::steady_clock;
inline double Since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The built-in effects of a scene (registered Lagrangians excluded).
std::vector<problems::Effect> BuiltInEffects(const Scene& s);

// The per-node columns a scene asks for: diagnostics from the Lagrangian by
// automatic differentiation (energy v·∂L/∂v − L, momentum ∂L/∂v, angular
// momentum x × p), and the reference with its errors. Every stride-th node
// (and the last) goes to the sink.
template <class P>
class NodeEmitter {
 public:
  static constexpr int d = P::kDim;

  NodeEmitter(const P& problem, const Scene& s, RunSink& sink)
      : problem_(problem), scene_(s), sink_(sink) {
    auto& c = layout_.columns;
    layout_.dof = d;
    if (s.Wants("energy")) c.push_back("energy");
    if (s.Wants("momentum"))
      for (int k = 0; k < d; ++k) c.push_back("p" + std::to_string(k));
    if (s.Wants("angular_momentum")) {
      if (d == 2) c.push_back("angular_momentum");
      if (d == 3)
        for (const char* n :
             {"angular_momentum_x", "angular_momentum_y", "angular_momentum_z"})
          c.push_back(n);
    }
    reference_ = MakeReference(problem, s);
    if (reference_) {
      layout_.reference_x = int(c.size());
      for (int k = 0; k < d; ++k)
        c.push_back("x_reference" + std::to_string(k));
      for (int k = 0; k < d; ++k)
        c.push_back("v_reference" + std::to_string(k));
      if (s.Wants("energy")) c.push_back("energy_reference");
      if (s.Wants("error")) {
        c.push_back("error_x");
        c.push_back("error_v");
      }
    }
    values_.resize(c.size());
    sink_.Begin(layout_);
  }

  const RunLayout& layout() const { return layout_; }
  std::string reference_description() const {
    return reference_ ? reference_->description() : "";
  }

  // Node `index` of the grid (0 … points − 1; under error control the
  // number of nodes is not known in advance, and the last is at t_end).
  void Node(long long index, double t, const double* x, const double* v) {
    const bool last =
        scene_.points > 0 ? index == scene_.points - 1 : t == scene_.t_end;
    if (index % scene_.output.stride != 0 && !last) return;
    int k = 0;
    double p[d] = {};
    if (scene_.Wants("energy") || scene_.Wants("momentum") ||
        scene_.Wants("angular_momentum"))
      Momentum(x, v, p);
    if (scene_.Wants("energy")) values_[k++] = energy_;
    if (scene_.Wants("momentum"))
      for (int c = 0; c < d; ++c) values_[k++] = p[c];
    if (scene_.Wants("angular_momentum")) {
      if constexpr (d == 2) values_[k++] = x[0] * p[1] - x[1] * p[0];
      if constexpr (d == 3) {
        values_[k++] = x[1] * p[2] - x[2] * p[1];
        values_[k++] = x[2] * p[0] - x[0] * p[2];
        values_[k++] = x[0] * p[1] - x[1] * p[0];
      }
    }
    if (reference_) {
      double xr[d], vr[d], pr[d] = {};
      reference_->State(t, xr, vr);
      for (int c = 0; c < d; ++c) values_[k++] = xr[c];
      for (int c = 0; c < d; ++c) values_[k++] = vr[c];
      if (scene_.Wants("energy")) {
        Momentum(xr, vr, pr);
        values_[k++] = energy_;
      }
      if (scene_.Wants("error")) {
        double ex = 0, ev = 0;
        for (int c = 0; c < d; ++c) {
          ex = std::max(ex, std::abs(x[c] - xr[c]));
          ev = std::max(ev, std::abs(v[c] - vr[c]));
        }
        values_[k++] = ex;
        values_[k++] = ev;
      }
    }
    sink_.Node(t, x, v, values_.data());
  }

 private:
  // p = ∂L/∂v and energy_ = v·p − L at (x, v).
  void Momentum(const double* x, const double* v, double* p) {
    double z[2 * d];
    for (int c = 0; c < d; ++c) {
      z[c] = x[c];
      z[d + c] = v[c];
    }
    const auto [lagrangian, grad] =
        action::LagrangianGradient<double>(problem_, z);
    energy_ = -lagrangian;
    for (int c = 0; c < d; ++c) {
      p[c] = grad[d + c];
      energy_ += v[c] * p[c];
    }
  }

  const P& problem_;
  const Scene& scene_;
  RunSink& sink_;
  RunLayout layout_;
  std::unique_ptr<Reference> reference_;
  std::vector<double> values_;
  double energy_ = 0;
};

// One global solve of the whole span: the nodes go to `emit` afterwards.
template <class P>
void SolveGlobal(const P& problem, const Scene& s,
                 const variational::InitialData& initial,
                 const variational::Grid& grid, NodeEmitter<P>& emit,
                 RunOutcome& out) {
  constexpr int d = P::kDim;
  nlohmann::json& j = out.solver;
  const auto start = Clock::now();
  variational::SolveOptions options;
  options.path = variational::ParseSolver(s.method.solver);
  const variational::IvpSolution<double> sol =
      Solve(problem, initial, grid, options);
  out.seconds = Since(start);
  out.converged = sol.status.converged;
  out.status = sol.status.converged ? "converged" : sol.status.reason;
  j["iterations"] = sol.iterations;
  j["gradient_norm"] = sol.gradient_norm;
  j["residual_norm"] = sol.residual_norm;
  j["max_path_difference"] = sol.max_path_difference;
  j["end_position_error_estimate"] = sol.corrected.position_error_estimate;
  j["end_velocity_error_estimate"] = sol.corrected.velocity_error_estimate;
  out.end_x = sol.corrected.position;
  out.end_v =
      s.order == 2 ? sol.corrected.velocity : std::vector<double>(d, 0.0);
  out.points = sol.points();
  for (int i = 0; i < sol.points(); ++i) {
    double x[d], v[d];
    for (int c = 0; c < d; ++c) {
      x[c] = sol.x1(i, c);
      v[c] = sol.velocity(i, c);
    }
    emit.Node(i, sol.t[i], x, v);
  }
}

// The march's options from [method]: windows of slab_points, and the error
// control of its tolerance when there is one (run_variational.cc).
variational::MarchOptions MarchOptionsFor(const Scene& s);
// ", marched in windows of N points" and the error control, if any, for the
// outcome's method.
std::string MarchDescription(const Scene& s,
                             const variational::MarchOptions& options);
// The march's status, counts and end state in the outcome (the time is the
// caller's: it excludes the output).
void RecordMarch(const variational::MarchResult& r,
                 const variational::MarchOptions& options, RunOutcome& out);

// A march in windows: each node goes to `emit` as it is accepted.
template <class P>
void SolveMarched(const P& problem, const Scene& s,
                  const variational::InitialData& initial,
                  const variational::Grid& grid, NodeEmitter<P>& emit,
                  RunSink& sink, RunOutcome& out) {
  const auto start = Clock::now();
  const variational::MarchOptions options = MarchOptionsFor(s);
  out.method += MarchDescription(s, options);
  long long index = 0;
  double output_seconds = 0;
  const double span = s.t_end - s.t_start;
  const variational::MarchResult r =
      Solve(problem, initial, grid, options,
            [&](double t, const double* x, const double* v) {
              const auto t0 = Clock::now();
              emit.Node(index++, t, x, v);
              sink.Progress((t - s.t_start) / span);
              output_seconds += Since(t0);
            });
  out.seconds = Since(start) - output_seconds;
  RecordMarch(r, options, out);
}

template <class P>
RunOutcome RunVariational(const P& problem, const Scene& s, RunSink& sink) {
  const variational::Grid grid{.op = s.method.op,
                               .points = s.points,
                               .t_start = s.t_start,
                               .t_end = s.t_end};
  const variational::InitialData initial{s.x0, s.v0};
  NodeEmitter<P> emit(problem, s, sink);
  RunOutcome out;
  out.method = "variational, " + s.method.op + ", " + s.method.solver;
  out.solver["reference"] = emit.reference_description();
  if (s.method.slab_points == 0)
    SolveGlobal(problem, s, initial, grid, emit, out);
  else
    SolveMarched(problem, s, initial, grid, emit, sink, out);
  return out;
}

template <int D>
RunOutcome RunStepper(const problems::Composed<D>& lagrangian, const Scene& s,
                      RunSink& sink) {
  const action::ErasedProblem<D> erased = action::Erase(lagrangian);
  using H = problems::ComposedHamiltonian<D>;
  const H hamiltonian(lagrangian.effects);
  const steppers::HamiltonianSystem<H> system(hamiltonian);
  auto stepper = steppers::MakeStepper<H>(s.method.kind, system);
  NodeEmitter<action::ErasedProblem<D>> emit(erased, s, sink);
  RunOutcome out;
  out.method = "stepper " + s.method.kind;
  out.solver["reference"] = emit.reference_description();
  typename steppers::HamiltonianSystem<H>::Vector y;
  const Eigen::Map<const Eigen::Matrix<double, D, 1>> x0(s.x0.data()),
      v0(s.v0.data());
  y << x0, hamiltonian.mass() * v0;
  const long steps = long(s.points - 1);
  const double h = (s.t_end - s.t_start) / double(steps);
  long long index = 0;
  double output_seconds = 0;
  const auto start = Clock::now();
  const steppers::RunReport r = steppers::Integrate(
      stepper, y, h, steps, [&](double t, const auto& state) {
        const auto t0 = Clock::now();
        const Eigen::Matrix<double, D, 1> v =
            hamiltonian.inverse_mass() * state.template tail<D>();
        // The last node lands on end exactly, whatever n·h rounds to.
        const double time = index == steps ? s.t_end : s.t_start + t;
        emit.Node(index++, time, state.data(), v.data());
        sink.Progress(t / (s.t_end - s.t_start));
        output_seconds += Since(t0);
      });
  out.seconds = Since(start) - output_seconds;
  out.converged = r.status == steppers::StepOutcome::kOk;
  out.status = out.converged
                   ? "completed"
                   : steppers::ToString(r.status) +
                         " at t = " + std::to_string(s.t_start + r.failed_at);
  out.solver["step"] = h;
  out.solver["steps"] = r.steps;
  out.solver["iterations"] = r.iterations;
  out.solver["iterations_per_step"] = r.iterations_per_step();
  out.solver["max_iterations_per_step"] = r.max_iterations;
  out.solver["evaluations"] = r.evaluations;
  out.points = r.steps + 1;
  out.end_x.assign(y.data(), y.data() + D);
  const Eigen::Matrix<double, D, 1> v_end =
      hamiltonian.inverse_mass() * y.template tail<D>();
  out.end_v.assign(v_end.data(), v_end.data() + D);
  return out;
}

// A scene of built-in effects with D degrees of freedom.
template <int D>
RunOutcome RunEffects(const Scene& s, RunSink& sink) {
  const problems::Composed<D> composed{BuiltInEffects(s)};
  if (s.variational()) return RunVariational(action::Erase(composed), s, sink);
  return RunStepper<D>(composed, s, sink);
}

// A scene with a registered Lagrangian (variational only): the sum of its
// model and the built-in effects' (erased_problem.h), each compiled once.
template <int D>
RunOutcome RunRegistered(const action::ErasedProblem<D>& user, const Scene& s,
                         RunSink& sink) {
  return RunVariational(
      user + action::Erase(problems::Composed<D>{BuiltInEffects(s)}), s, sink);
}

#define VIVP_EXTERN_RUN(D)                                                   \
  extern template RunOutcome RunVariational(const action::ErasedProblem<D>&, \
                                            const Scene&, RunSink&);         \
  extern template RunOutcome RunEffects<D>(const Scene&, RunSink&);          \
  extern template RunOutcome RunRegistered(const action::ErasedProblem<D>&,  \
                                           const Scene&, RunSink&);
VIVP_PRECOMPILED_DIMS(VIVP_EXTERN_RUN)
#undef VIVP_EXTERN_RUN

}  // namespace vivp::scene::detail
