// Time-slab marching of a charged field and its gauge field
// (core/action/charged_field.h, docs/gauge.md §8): each window is the
// doubled action's initial value problem on `window` nodes, solved by the
// one Newton with damped normal equations (normal_solver.h), and hands its
// end state to the next.
//
// The hand-off: the multiplier-corrected end state of every field
// (end_state.h: −λ3 the momentum, x_N + M⁻¹λ4 the position; for φ the
// covariant velocity −λ3/2), with the electric field E_b(N) = −e²λ3 as the
// velocity of A_b: the next window starts in the gauge A₀ = 0 at its first
// node, the start that keeps the gauge from drifting for electromagnetism
// (docs/gauge.md §5), and its own A₀ is an unknown again at every node.
// Newton starts from the leapfrog's path in the gauge A₀ = 0
// (charged_leapfrog.h), χ = 0, multipliers 0, and holds χ past node 1
// (the representative, charged_field.h); no gauge condition anywhere.
//
// Before the first window the data's total charge is checked: on a torus
// Gauss's law makes every slice neutral, and charged data have no solution.
// After each window, the action's Gauss law at every node
// (charged_observables.h) must hold to `gauss_tolerance`, or the march
// stops and says why.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "core/action/charged_observables.h"
#include "core/sbp/builder.h"
#include "solvers/spacetime/charged_leapfrog.h"
#include "solvers/spacetime/normal_solver.h"
#include "solvers/variational/newton.h"

namespace vivp::spacetime {

struct ChargedMarchOptions {
  std::string time_operator = "sbp42";
  int window = 16;  // nodes per window
  double dt = 0.05;
  int windows = 1;
  double t0 = 0;
  double gauss_tolerance = 1e-10;
  // The least charge density the law is measured against
  // (charged_observables.h): 0 for data with charges, the problem's own
  // scale for static data, whose terms in the law all vanish.
  double gauss_scale_floor = 0;
  int predictor_substeps = 4;  // leapfrog steps per node spacing; 0: none
  // From the straight path (predictor_substeps = 0) give refinement_steps
  // = 0: far from the solution the chord steps diverged where full Newton
  // steps converge.
  variational::NewtonOptions newton;
};

struct ChargedWindowReport {
  double t0 = 0;
  long long iterations = 0;
  double residual = 0, gauss = 0;
  int retries = 0;  // solved again with full Newton steps (never silent)
};

struct ChargedMarch {
  bool ok = false;
  std::string reason;
  std::vector<ChargedWindowReport> windows;
  std::vector<double> phi, pi;  // the state handed on by the last window
};

// Σ_j Hˣ_j ρ_j of data (φ, π as charged_field.h's per point), and the
// scale Σ_j Hˣ_j |ρ_j|.
template <class System>
std::pair<double, double> DataCharge(const sbp::SpaceGrid<double>& grid,
                                     const std::vector<double>& phi,
                                     const std::vector<double>& pi) {
  double q = 0, scale = 0;
  for (int j = 0; j < grid.points(); ++j) {
    const std::complex<double> p(phi[j * System::m + System::kRe],
                                 phi[j * System::m + System::kIm]);
    const std::complex<double> v(pi[j * System::m + System::kRe],
                                 pi[j * System::m + System::kIm]);
    const double rho = action::ChargeDensity(p, v);
    q += grid.NormWeight(j) * rho;
    scale += grid.NormWeight(j) * std::abs(rho);
  }
  return {q, scale};
}

// Why data (φ, π) cannot be marched on a torus, or "" when they are
// neutral: Gauss's law makes every slice's total charge vanish, so a net
// charge beyond 1e-10 of Σ|ρ| (the round-off of mirrored packets is far
// below it) has no solution.
template <class System>
std::string NetChargeReason(const sbp::SpaceGrid<double>& grid,
                            const std::vector<double>& phi,
                            const std::vector<double>& pi) {
  const auto [charge, scale] = DataCharge<System>(grid, phi, pi);
  if (std::abs(charge) <= 1e-10 * std::max(scale, 1e-300)) return "";
  return "the initial slice carries a total charge " + std::to_string(charge) +
         " (of Σ|ρ| = " + std::to_string(scale) +
         "); on a periodic grid Gauss's law makes every slice neutral: give "
         "pairs of opposite charge";
}

// Newton's start for a window from the handed state: the leapfrog in the
// gauge A₀ = 0 (charged_leapfrog.h) at the nodes, `predictor_substeps`
// steps per node spacing, or the straight path when that is 0; χ = 0 and
// the multipliers 0.
template <class System, class Model>
std::vector<double> Start(const System& sys, const Model& model,
                          const sbp::SpaceGrid<double>& grid,
                          const std::vector<double>& phi,
                          const std::vector<double>& pi, double t,
                          const ChargedMarchOptions& o) {
  constexpr int m = System::m;
  std::vector<double> y(sys.size(), 0.0);
  ChargedSliceState s{phi, pi};
  for (int i = 0; i < o.window; ++i) {
    if (i > 0 && o.predictor_substeps > 0)
      LeapfrogCharged<System::kSpaceDim>(
          model, grid, t + (i - 1) * o.dt, o.dt / o.predictor_substeps,
          o.predictor_substeps, ChargedLeapfrog::kCanonical, s,
          [](double, const ChargedSliceState&) {});
    for (int j = 0; j < grid.points(); ++j)
      for (int a = 0; a < System::kChi; ++a)
        y[sys.Phi(i, j, a)] = o.predictor_substeps > 0
                                  ? s.x[j * m + a]
                                  : phi[j * m + a] + i * o.dt * pi[j * m + a];
  }
  return y;
}

// on_window(system, y, nodes, handed) after each solved window, with the
// state it hands on (the data it was solved from if it failed its check).
// Solver: Newton's linear solver (normal_solver.h and its factorization).
template <class Model, int d, class Solver = NormalEquationsSolver,
          class OnWindow>
ChargedMarch MarchCharged(const Model& model,
                          const sbp::SpaceGrid<double>& grid,
                          std::vector<double> phi, std::vector<double> pi,
                          const ChargedMarchOptions& o, OnWindow&& on_window) {
  using System = action::ChargedFieldSystem<Model, d>;
  constexpr int m = System::m;
  ChargedMarch out;
  out.reason = NetChargeReason<System>(grid, phi, pi);
  if (!out.reason.empty()) return out;
  Solver solver;
  double t = o.t0;
  for (int w = 0; w < o.windows; ++w) {
    const sbp::RegularizedOperator<double> dbar(sbp::MakeOperator<double>(
        o.time_operator, o.window, t, t + o.dt * (o.window - 1)));
    const System sys(model, dbar, grid, phi, pi);
    std::vector<double> y = Start(sys, model, grid, phi, pi, t, o);
    solver.Invalidate();
    const std::vector<double> start = y;
    variational::NewtonOptions chord = o.newton;
    if (chord.refinement_steps > 0)  // give up on chord steps early
      chord.max_iterations = std::min(chord.max_iterations, 12);
    auto r = variational::Newton<double>(sys, y, chord, solver);
    ChargedWindowReport rep{t, r.iterations, r.last_residual, 0};
    if (!r.converged && o.newton.refinement_steps > 0) {
      // Chord steps far from the solution (a first window whose data carry
      // no Coulomb field: A₀ must build it) can diverge where full Newton
      // steps converge: once more from the same start without them.
      y = start;
      variational::NewtonOptions full = o.newton;
      full.refinement_steps = 0;
      solver.Invalidate();
      r = variational::Newton<double>(sys, y, full, solver);
      rep = {t, rep.iterations + r.iterations, r.last_residual, 0, 1};
    }
    if (!r.converged) {
      out.reason = "window " + std::to_string(w) +
                   " at t = " + std::to_string(t) +
                   ": Newton did not converge (" + r.reason + ")";
      out.windows.push_back(rep);
      return out;
    }
    const auto nodes =
        action::ObserveWindow(sys, y.data(), o.gauss_scale_floor);
    rep.gauss =
        *std::max_element(nodes.gauss_action.begin(), nodes.gauss_action.end());
    out.windows.push_back(rep);
    if (!(rep.gauss <= o.gauss_tolerance)) {
      on_window(sys, y, nodes, ChargedSliceState{phi, pi});
      out.reason = "window " + std::to_string(w) +
                   " at t = " + std::to_string(t) +
                   ": the action's Gauss law holds only to " +
                   std::to_string(rep.gauss) + " relative (tolerance " +
                   std::to_string(o.gauss_tolerance) + ")";
      return out;
    }
    // The hand-off: the multiplier-corrected end state (as for every
    // field, end_state.h), in the gauge A₀ = 0 at the junction. −λ3 is the
    // momentum, 2(D_0φ) for φ and E_b/e² for A_b; x_N + M⁻¹λ4 the position.
    const int last = o.window - 1;
    const double g2 = 1.0 / model.InverseCouplingSquared(dbar.base().t(last));
    for (int j = 0; j < grid.points(); ++j) {
      // φ's multipliers live in the Wilson line's frame (ψ = e^{−iχ}φ).
      const std::complex<double> frame =
          std::polar(1.0, y[sys.Phi(last, j, System::kChi)]);
      const std::complex<double> x =
          std::complex<double>(y[sys.Phi(last, j, System::kRe)],
                               y[sys.Phi(last, j, System::kIm)]) +
          frame * 0.5 *
              std::complex<double>(y[sys.Lambda4(j, System::kRe)],
                                   y[sys.Lambda4(j, System::kIm)]);
      const std::complex<double> v =
          frame * -0.5 *
          std::complex<double>(y[sys.Lambda3(j, System::kRe)],
                               y[sys.Lambda3(j, System::kIm)]);
      phi[j * m + System::kRe] = x.real();
      phi[j * m + System::kIm] = x.imag();
      pi[j * m + System::kRe] = v.real();
      pi[j * m + System::kIm] = v.imag();
      for (int b = 0; b < d; ++b) {
        const int a = System::A(b);
        phi[j * m + a] = y[sys.Phi(last, j, a)] + g2 * y[sys.Lambda4(j, a)];
        pi[j * m + a] = -g2 * y[sys.Lambda3(j, a)];
      }
    }
    t += o.dt * (o.window - 1);
    on_window(sys, y, nodes, ChargedSliceState{phi, pi});
  }
  out.ok = true;
  out.phi = std::move(phi);
  out.pi = std::move(pi);
  return out;
}

}  // namespace vivp::spacetime
