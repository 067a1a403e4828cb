// What a window of a charged field (charged_field.h) says about physics:
// the gauge-invariant observables at each node, and Gauss's law in two
// forms (docs/gauge.md §7).
//
// The action's Gauss law is A₀'s Euler–Lagrange equation. The unknown is
// χ with A₀ = Dχ, so χ's rows are Dᵀ applied to A₀'s, and per spatial point
//
//   G(·, j) = (Dᵀ)⁺ (rows of χ at j),
//
// the minimum-norm solution (D annihilates constants, so Dᵀ has one null
// direction w in time, along which χ's rows say nothing about A₀'s; G is
// the part of A₀'s law that the action's χ determines). It splits into the
// gauge field's part Hᵗ_i Hˣ_j (D⁻·E)_ij / e² and the matter's, minus
// Hᵗ_i Hˣ_j times the action's charge density, and its size is measured
// against the terms that cancel in it, slice by slice.
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
      gauss_action;  // |G|/(Hᵗ Hˣ) over the slice's scale (below)
  std::vector<double> gauss_textbook;  // the same for (D⁻·E)/e² − ρ
  // |(D⁻·E)/e² − ρ| itself, a charge density (its order in Δx is not
  // hidden by the scale's 2/h_b).
  std::vector<double> textbook_absolute;
  // χ's rows, Dᵀ G, relative to their two parts: the law as the action
  // states it for the unknown χ, before (Dᵀ)⁺ recovers G.
  std::vector<double> gauss_rows;
  std::vector<double> charge;  // ρ = 2 Im(φ̄ D_0φ)
  // The action's charge density: minus the matter's part of G over Hᵗ Hˣ,
  // so that the action's law reads (D⁻·E)/e² = ρ_action.
  std::vector<double> charge_action;
  std::vector<double> modulus;         // |φ|
  std::vector<double> energy_density;  // (E² + F²)/(2e²) + |D_0φ|² + |Dφ|² + V
  std::vector<double> electric;        // E_b at (i·Nx + j)·d + b
};

// scale_floor: the least scale of a slice (a charge density). Static data
// (E = 0, ρ = 0: a vortex) have no terms that cancel in the law, and the
// relative measure would compare round-off with round-off; the caller then
// states the problem's own charge density scale.
template <class Model, int d>
ChargedNodes ObserveWindow(const ChargedFieldSystem<Model, d>& s,
                           const double* y, double scale_floor = 0) {
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
      out.charge[n] = ChargeDensity(phi, q.value);
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
  // The action's law from χ's rows of each part: Dᵀ, minimum-norm.
  Eigen::MatrixXd dbar_t = Eigen::MatrixXd::Zero(nt, nt);
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < nt; ++k) dbar_t(k, i) = D.Entry(i, k);
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> lu(dbar_t);
  auto rows_of = [&](unsigned parts) {
    std::vector<double> f(s.size());
    s.PartialResidual(y, f.data(), parts);
    Eigen::MatrixXd rows(nt, nx);
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nt; ++i) rows(i, j) = f[s.Phi(i, j, System::kChi)];
    return rows;
  };

  // χ's rows, of each part and of all terms.
  const Eigen::MatrixXd rg = rows_of(System::kGauge),
                        rm = rows_of(System::kMatter),
                        rt = rows_of(System::kAllTerms);
  {  // χ's rows themselves, Dᵀ of the law: no inversion.
    out.gauss_rows.resize(nodes);
    for (int i = 0; i < nt; ++i) {
      double scale = 0;
      for (int j = 0; j < nx; ++j)
        scale = std::max(scale, std::abs(rg(i, j)) + std::abs(rm(i, j)));
      for (int j = 0; j < nx; ++j)
        out.gauss_rows[std::size_t(i) * nx + j] =
            scale > 0 ? std::abs(rt(i, j)) / scale : 0.0;
    }
  }
  // G from the sum of the rows, which cancel to round-off; its gauge
  // field's part is local, Hᵗ Hˣ (D⁻·E)/e², and the matter's part is the
  // rest.
  const Eigen::MatrixXd total = lu.solve(rt);
  out.gauss_action.resize(nodes);
  out.gauss_textbook.resize(nodes);
  out.textbook_absolute.resize(nodes);
  out.charge_action.resize(nodes);
  // Each slice's scale is that of the terms that cancel in the law, as for
  // electromagnetism (field_constraints.h): max |ρ| + Σ_b ‖D_b⁻‖∞ max |E_b|/e²,
  // ‖D_b⁻‖∞ = 2/h_b.
  for (int i = 0; i < nt; ++i) {
    const double inv_g2 = s.model().InverseCouplingSquared(D.t(i));
    const std::size_t n0 = std::size_t(i) * nx;
    std::vector<double> div(nx);
    double flux = 0, rho_max = 0, rho_tb_max = 0;
    for (int b = 0; b < d; ++b) {
      double e_max = 0;
      for (int j = 0; j < nx; ++j)
        e_max = std::max(e_max, std::abs(out.electric[(n0 + j) * d + b]));
      flux += 2 / s.h(b) * e_max * inv_g2;
    }
    for (int j = 0; j < nx; ++j) {
      double dv = 0;
      for (int b = 0; b < d; ++b)
        dv += (out.electric[(n0 + j) * d + b] -
               out.electric[(n0 + s.Previous(j, b)) * d + b]) /
              s.h(b);
      div[j] = dv * inv_g2;
      const double weight = D.NormWeight(i) * s.space_grid().NormWeight(j);
      // ρ_action = (D⁻·E)/e² − G/(Hᵗ Hˣ)
      out.charge_action[n0 + j] = div[j] - total(i, j) / weight;
      rho_max = std::max(rho_max, std::abs(out.charge_action[n0 + j]));
      rho_tb_max = std::max(rho_tb_max, std::abs(out.charge[n0 + j]));
    }
    const double scale = std::max(flux + rho_max, scale_floor),
                 scale_tb = std::max(flux + rho_tb_max, scale_floor);
    for (int j = 0; j < nx; ++j) {
      const double weight = D.NormWeight(i) * s.space_grid().NormWeight(j);
      out.gauss_action[n0 + j] =
          scale > 0 ? std::abs(total(i, j)) / weight / scale : 0.0;
      out.textbook_absolute[n0 + j] = std::abs(div[j] - out.charge[n0 + j]);
      out.gauss_textbook[n0 + j] =
          scale_tb > 0 ? std::abs(div[j] - out.charge[n0 + j]) / scale_tb : 0.0;
    }
  }
  return out;
}

}  // namespace vivp::action
