// An independent integration of a window's Euler–Lagrange equations: the
// Newton start of a time-slab window and the reference its result is checked
// against (march.h).
//
// A window of W points can span most of an oscillation period; started from
// a Taylor polynomial, Newton may converge to another critical point of the
// discrete action (anharmonic oscillator, SBP42, 449 points in windows of 48:
// every window "converged", the end error was 1.39). The predictor integrates
// the equations of motion of the same Lagrangian, ẍ = G_vv⁻¹(g_x − G_vx ẋ)
// from automatic differentiation of the density (core/action/
// euler_lagrange.h; first-order systems ẋ = f(x)), with Boost.Odeint's
// Dormand–Prince 5(4) and its dense output, so it is accurate to order 5 at
// every node whatever the node spacing, and takes as few steps as its
// tolerance allows (a window that is a small part of a period: one or two).
//
// Its error: each accepted step keeps the local error estimate of component i
// below tol_abs + tol_rel·(|y_i| + h|ẏ_i|) (odeint's default error checker);
// over k steps of a window, where the flow does not amplify much, the error is
// about k times that at the steps' ends and more at the nodes between them
// (the dense output). error_x/error_v report 10·k times that allowance.
#pragma once

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <exception>
#include <string>

#include "core/action/density.h"
#include "core/action/euler_lagrange.h"

namespace vivp::variational {

struct PredictorReport {
  bool ok = true;
  std::string failure;  // why the integration stopped (ok = false)
  long steps = 0;       // accepted Dormand–Prince steps
  double error_x = 0;   // bound on the position error at the nodes
  double error_v = 0;   // bound on the velocity error (second order)
};

// The integration every predictor shares: Dormand–Prince 5(4) with dense
// output from s at τ = tau[0] to the nodes tau[0 … n), calling
// store(state, i) at each; `step` is the first step to try and receives the
// last accepted one (the next window's first). The error bound is that of
// the header: 10·k times the steps' allowance, from the largest |x| and |v|
// stored (scale_x, scale_v) over the window's span.
template <class State, class Rhs, class Store>
PredictorReport IntegrateToNodes(State& s, const Rhs& rhs, const double* tau,
                                 int n, double tol_abs, double tol_rel,
                                 double& step, const Store& store,
                                 const double& scale_x, const double& scale_v) {
  namespace odeint = boost::numeric::odeint;
  // Far beyond any window of a non-stiff problem at a sane tolerance.
  constexpr long kMaxSteps = 100000;
  PredictorReport r;
  auto fail = [&](std::string why) {
    step = 0;
    r.ok = false;
    r.failure =
        "the predictor (Dormand–Prince 5(4) on the Euler–Lagrange "
        "equations) failed: " +
        std::move(why);
    return r;
  };
  auto finite = [](const State& y) {
    for (double e : y)
      if (!std::isfinite(e)) return false;
    return true;
  };
  auto stepper = odeint::make_dense_output(tol_abs, tol_rel,
                                           odeint::runge_kutta_dopri5<State>());
  const double span = tau[n - 1] - tau[0];
  // The last window's final step size is a good first guess for this one.
  const double first = step > 0 ? std::min(step, span) : span / 8;
  try {
    stepper.initialize(s, tau[0], first);
    store(s, 0);
    for (int i = 1; i < n; ++i) {
      while (stepper.current_time() < tau[i]) {
        stepper.do_step(rhs);
        if (++r.steps > kMaxSteps)
          return fail(
              "more than 10^5 steps in one window (a stiff or singular "
              "equation of motion)");
        if (!finite(stepper.current_state()))
          return fail("non-finite state " +
                      std::to_string(stepper.current_time()) +
                      " after the window's start");
      }
      stepper.calc_state(tau[i], s);
      store(s, i);
    }
    step = stepper.current_time_step();
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  // Ten times the steps' error allowance: the allowance bounds the error
  // estimate of dopri5's 4th-order member at each step's end, while the
  // nodes come from its dense output between steps (measured: at 1e-4 an
  // end velocity 2.5 times off the undamped bound, anharmonic oscillator,
  // SBP84 grid of 4097 points).
  const double k = 10.0 * double(std::max(r.steps, 1L));
  r.error_x = k * (tol_abs + tol_rel * (scale_x + span * scale_v));
  r.error_v = k * (tol_abs + tol_rel * scale_v * 2);
  return r;
}

template <class P>
class Predictor {
 public:
  static constexpr int d = P::kDim;
  using State = std::array<double, 2 * d>;

  // `constant_mass`: take ẍ = M⁻¹ ∂L/∂x when L declares kConstantMass
  // (action::Accelerator), for a caller whose solves check the declaration
  // at every node (the reduced system's assembly, reduced_system.h).
  Predictor(const P& problem, int order, bool constant_mass = false)
      : problem_(problem),
        order_(order),
        acceleration_(problem, constant_mass) {}

  // Integrates from (x0, v0) at τ = 0 to the times tau[0 … n) (tau[0] = 0,
  // increasing) and writes positions and velocities node-major into x and v
  // (n·d values each; v is ẋ = f(x) for a first-order system).
  PredictorReport Run(const double* x0, const double* v0, const double* tau,
                      int n, double tol_abs, double tol_rel, double* x,
                      double* v) {
    State s{};
    for (int c = 0; c < d; ++c) {
      s[c] = x0[c];
      s[d + c] = order_ == 2 ? v0[c] : 0.0;
    }
    auto rhs = [this](const State& y, State& dy, double) { Rhs(y, dy); };
    double scale_x = 0, scale_v = 0;
    return IntegrateToNodes(
        s, rhs, tau, n, tol_abs, tol_rel, step_,
        [&](const State& y, int i) { Store(y, i, x, v, scale_x, scale_v); },
        scale_x, scale_v);
  }

  // ∂L/∂ẋ at (x, v): the momentum, the continuum value of −λ3 at a window's
  // end (the Newton start of λ3).
  std::array<double, d> Momentum(const double* x, const double* v) const {
    double z[2 * d];
    for (int c = 0; c < d; ++c) {
      z[c] = x[c];
      z[d + c] = v[c];
    }
    const auto g = action::LagrangianGradient<double>(problem_, z).second;
    std::array<double, d> p;
    for (int c = 0; c < d; ++c) p[c] = g[d + c];
    return p;
  }

 private:
  // ẍ through the Accelerator (M⁻¹ ∂L/∂x for a constant mass), ẋ = f(x)
  // as EquationsOfMotion solves it.
  void Rhs(const State& y, State& dy) {
    if (order_ != 2) {
      action::EquationsOfMotion(problem_, order_, y.data(), dy.data(),
                                velocity_);
      return;
    }
    const auto a = acceleration_(y.data(), y.data() + d);
    for (int c = 0; c < d; ++c) {
      dy[c] = y[d + c];
      dy[d + c] = a[c];
    }
  }

  void Store(const State& s, int i, double* x, double* v, double& scale_x,
             double& scale_v) {
    if (order_ == 1)
      velocity_ = action::FirstOrderVelocity(problem_, s.data(), velocity_);
    for (int c = 0; c < d; ++c) {
      x[i * d + c] = s[c];
      v[i * d + c] = order_ == 2 ? s[d + c] : velocity_[c];
      scale_x = std::max(scale_x, std::abs(x[i * d + c]));
      scale_v = std::max(scale_v, std::abs(v[i * d + c]));
    }
  }

  const P& problem_;
  int order_;
  action::Accelerator<P> acceleration_;
  double step_ = 0;  // last accepted step, the next run's first
  mutable action::StateVector<P> velocity_ = action::StateVector<P>::Zero();
};

}  // namespace vivp::variational
