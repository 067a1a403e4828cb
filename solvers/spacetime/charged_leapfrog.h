// The method of lines for a charged field in the gauge A₀ = 0: the lattice
// of charged_field.h (links, covariant forward differences) in space, the
// Störmer–Verlet leapfrog in time. It is the comparison of docs/gauge.md §8
// and the Newton start of each window of the variational march
// (charged_march.h).
//
// With L = Σ_j Hˣ_j [|φ̇|² + Ȧ²/(2e(t)²)] − U(φ, A), U the slice's potential
// energy (charged_terms.h), the momenta are 2φ̇ and P = Ȧ/e² = E/e². Two
// ways of stepping with a coupling that depends on time:
//
//   canonical  kick P ← P − τ ∂U/∂A, drift A ← A + h e(t+½)² P: the
//              symplectic leapfrog of the canonical pair (A, P). Gauss's
//              law D⁻·P = ρ (ρ = 2 Im(φ̄ φ̇)) is preserved by every kick and
//              every drift exactly, because U is gauge invariant;
//   electric   the electric field E as the stored variable and the coupling
//              updated per step, kick E ← E − τ e(t)² ∂U/∂A, drift A ← A + hE:
//              what a code written for constant e does when e(t) is swapped
//              in. It drops the term −2(ė/e)E of d(E)/dt, so D⁻·E/e² − ρ drifts
//              with e(t) (CosmoLattice's open issue #13 reports violations of
//              this kind up to 70 %).
// Both coincide for constant e.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "core/action/charged_terms.h"

namespace vivp::spacetime {

enum class ChargedLeapfrog { kCanonical, kElectric };

// One slice's state: x the values (j·m + a: Re φ, Im φ, A_b; χ unused) and
// v their velocities (φ̇, and E_b = Ȧ_b for the links).
struct ChargedSliceState {
  std::vector<double> x, v;
};

// Gauss's law of a slice, max_j |(D⁻·E)_j/e² − ρ_j| relative to
// max_j (|D⁻·E|/e² + |ρ|).
template <int d>
double SliceGauss(const sbp::SpaceGrid<double>& grid,
                  const ChargedSliceState& s, double inv_g2) {
  using L = action::ChargedLayout<d>;
  double worst = 0, scale = 0;
  for (int j = 0; j < grid.points(); ++j) {
    double div = 0;
    for (int b = 0; b < d; ++b)
      div += (s.v[j * L::m + L::A(b)] -
              s.v[action::PreviousOn(grid, j, b) * L::m + L::A(b)]) /
             grid.axis(b).dx();
    div *= inv_g2;
    const std::complex<double> phi(s.x[j * L::m + L::kRe],
                                   s.x[j * L::m + L::kIm]);
    const std::complex<double> dphi(s.v[j * L::m + L::kRe],
                                    s.v[j * L::m + L::kIm]);
    const double rho = action::ChargeDensity(phi, dphi);
    worst = std::max(worst, std::abs(div - rho));
    scale = std::max(scale, std::abs(div) + std::abs(rho));
  }
  return scale > 0 ? worst / scale : 0.0;
}

// The energy of a slice at time t: U + Σ_j Hˣ_j (|φ̇|² + E²/(2e(t)²)).
template <int d, class Model>
double SliceEnergy(const Model& model, const sbp::SpaceGrid<double>& grid,
                   double t, const ChargedSliceState& s) {
  using L = action::ChargedLayout<d>;
  const double inv_g2 = model.InverseCouplingSquared(t);
  double e = action::ChargedSlicePotential<d>(model, grid, inv_g2, s.x.data(),
                                              nullptr);
  for (int j = 0; j < grid.points(); ++j) {
    double k = 0;
    for (int a : {L::kRe, L::kIm}) k += s.v[j * L::m + a] * s.v[j * L::m + a];
    for (int b = 0; b < d; ++b)
      k += 0.5 * inv_g2 * s.v[j * L::m + L::A(b)] * s.v[j * L::m + L::A(b)];
    e += grid.NormWeight(j) * k;
  }
  return e;
}

// `steps` leapfrog steps of h from t0; after each, on_step(t, state).
template <int d, class Model, class OnStep>
void LeapfrogCharged(const Model& model, const sbp::SpaceGrid<double>& grid,
                     double t0, double h, long long steps, ChargedLeapfrog kind,
                     ChargedSliceState& s, OnStep&& on_step) {
  using L = action::ChargedLayout<d>;
  constexpr int m = L::m;
  const int n = grid.points();
  std::vector<double> grad(std::size_t(n) * m);
  // The canonical scheme steps P = E/e², the electric one E itself.
  auto kick = [&](double t, double tau) {
    const double inv_g2 = model.InverseCouplingSquared(t);
    action::ChargedSlicePotential<d>(model, grid, inv_g2, s.x.data(),
                                     grad.data());
    for (int j = 0; j < n; ++j) {
      const double hx = grid.NormWeight(j);
      for (int a : {L::kRe, L::kIm})
        s.v[j * m + a] -= tau * 0.5 * grad[j * m + a] / hx;
      for (int b = 0; b < d; ++b) {
        const double force = grad[j * m + L::A(b)] / hx;
        s.v[j * m + L::A(b)] -=
            tau *
            (kind == ChargedLeapfrog::kCanonical ? force : force / inv_g2);
      }
    }
  };
  auto scale_links = [&](double factor) {
    for (int j = 0; j < n; ++j)
      for (int b = 0; b < d; ++b) s.v[j * m + L::A(b)] *= factor;
  };
  for (long long k = 0; k < steps; ++k) {
    const double t = t0 + double(k) * h;
    if (kind == ChargedLeapfrog::kCanonical)
      scale_links(model.InverseCouplingSquared(t));  // E → P
    kick(t, 0.5 * h);
    const double g2_mid = 1.0 / model.InverseCouplingSquared(t + 0.5 * h);
    for (int j = 0; j < n; ++j) {
      for (int a : {L::kRe, L::kIm}) s.x[j * m + a] += h * s.v[j * m + a];
      for (int b = 0; b < d; ++b)
        s.x[j * m + L::A(b)] +=
            h * s.v[j * m + L::A(b)] *
            (kind == ChargedLeapfrog::kCanonical ? g2_mid : 1.0);
    }
    kick(t + h, 0.5 * h);
    if (kind == ChargedLeapfrog::kCanonical)
      scale_links(1.0 / model.InverseCouplingSquared(t + h));  // P → E
    on_step(t + h, s);
  }
}

}  // namespace vivp::spacetime
