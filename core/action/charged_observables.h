// What a window of a charged field (charged_field.h) says about physics:
// the gauge-invariant observables at each node, and Gauss's law in two
// forms (docs/gauge.md §7).
//
// The action's Gauss law is A₀'s Euler–Lagrange equation. The unknown is
// χ with A₀ = D̄χ, so χ's rows are D̄ᵀ applied to A₀'s, and per spatial point
//
//   G(·, j) = D̄⁻ᵀ (rows of χ at j),
//
// split into the gauge field's part Hᵗ_i Hˣ_j (D⁻·E)_ij / e² and the
// matter's, minus Hᵗ_i Hˣ_j times the action's charge density. Its size is
// measured against the two parts that cancel in it, slice by slice.
// The textbook law beside it is (D⁻·E)/e² − ρ with ρ = 2 Im(φ̄ D_0φ) at the
// node, the covariant time difference of the action: they differ at
// O(Δt^p) (Ipp & Müller 2018).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "core/action/charged_field.h"

namespace vivp::action {

// At each node (i·Nx + j) of a window.
struct ChargedNodes {
  std::vector<double>
      gauss_action;  // |G| / the slice's max(|gauge| + |matter|)
  std::vector<double> gauss_textbook;  // the same for (D⁻·E)/e² − ρ
  std::vector<double> charge;          // ρ = 2 Im(φ̄ D_0φ)
  std::vector<double> modulus;         // |φ|
  std::vector<double> energy_density;  // (E² + F²)/(2e²) + |D_0φ|² + |Dφ|² + V
  std::vector<double> electric;        // E_b at (i·Nx + j)·d + b
};

template <class Model, int d>
ChargedNodes ObserveWindow(const ChargedFieldSystem<Model, d>& s,
                           const double* y) {
  using System = ChargedFieldSystem<Model, d>;
  const int nt = s.time_points(), nx = s.space_points();
  const auto& D = s.time_operator().base();
  const std::size_t nodes = std::size_t(nt) * nx;
  ChargedNodes out;
  out.charge.resize(nodes);
  out.modulus.resize(nodes);
  out.energy_density.resize(nodes);
  out.electric.resize(nodes * d);
  LocalComplex q;
  LocalReal t;
  for (int i = 0; i < nt; ++i) {
    const double inv_g2 = s.model().InverseCouplingSquared(D.t(i));
    for (int j = 0; j < nx; ++j) {
      const std::size_t n = std::size_t(i) * nx + j;
      const Complex phi(y[s.Phi(i, j, System::kRe)],
                        y[s.Phi(i, j, System::kIm)]);
      s.TimeDifference(y, i, j, true, q);
      out.charge[n] = 2 * (std::conj(phi) * q.value).imag();
      out.modulus[n] = std::abs(phi);
      double e = std::norm(q.value) + s.model().Potential(std::norm(phi));
      double field = 0;
      for (int b = 0; b < d; ++b) {
        s.SpaceDifference(y, i, j, b, q);
        e += std::norm(q.value);
        s.Electric(y, i, j, b, t);
        out.electric[n * d + b] = t.value;
        field += t.value * t.value;
        for (int c = b + 1; c < d; ++c) {
          s.Magnetic(y, i, j, b, c, t);
          field += t.value * t.value;
        }
      }
      out.energy_density[n] = e + 0.5 * inv_g2 * field;
    }
  }
  // The action's law from χ's rows of each part.
  Eigen::MatrixXd dbar_t = Eigen::MatrixXd::Zero(nt, nt);
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < nt; ++k) dbar_t(k, i) = D.Entry(i, k);
  dbar_t(0, 0) += s.time_operator().penalty();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(dbar_t);
  auto part = [&](unsigned parts) {
    std::vector<double> f(s.size());
    s.PartialResidual(y, f.data(), parts);
    Eigen::MatrixXd rows(nt, nx);
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nt; ++i) rows(i, j) = f[s.Phi(i, j, System::kChi)];
    return Eigen::MatrixXd(lu.solve(rows));
  };
  const Eigen::MatrixXd gauge = part(System::kGauge),
                        matter = part(System::kMatter);
  out.gauss_action.resize(nodes);
  out.gauss_textbook.resize(nodes);
  for (int i = 0; i < nt; ++i) {
    const double inv_g2 = s.model().InverseCouplingSquared(D.t(i));
    double scale = 0, scale_tb = 0;
    std::vector<double> div(nx);
    for (int j = 0; j < nx; ++j) {
      scale = std::max(scale, std::abs(gauge(i, j)) + std::abs(matter(i, j)));
      double dv = 0;
      for (int b = 0; b < d; ++b) {
        const int back = s.Previous(j, b);
        const std::size_t n = std::size_t(i) * nx;
        dv +=
            (out.electric[(n + j) * d + b] - out.electric[(n + back) * d + b]) /
            s.h(b);
      }
      div[j] = dv * inv_g2;
      scale_tb =
          std::max(scale_tb, std::abs(div[j]) +
                                 std::abs(out.charge[std::size_t(i) * nx + j]));
    }
    for (int j = 0; j < nx; ++j) {
      const std::size_t n = std::size_t(i) * nx + j;
      out.gauss_action[n] =
          scale > 0 ? std::abs(gauge(i, j) + matter(i, j)) / scale : 0.0;
      out.gauss_textbook[n] =
          scale_tb > 0 ? std::abs(div[j] - out.charge[n]) / scale_tb : 0.0;
    }
  }
  return out;
}

}  // namespace vivp::action
