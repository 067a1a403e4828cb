// What the gauge-field tests share: a window's Jacobian as a dense matrix
// (tests on a few hundred unknowns; the solves never form it), and for
// electromagnetism in 2 + 1 D on a periodic grid the gauge parts of a
// march, its observables at every slice, and random gauges (the plane wave
// and the fields E, B are studies/gauge_waves.h's).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "core/action/field_charges.h"
#include "core/action/field_system.h"
#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "problems/fields/gauge.h"
#include "solvers/spacetime/assembly.h"
#include "solvers/spacetime/solve.h"
#include "studies/gauge_waves.h"

namespace gauge_test {

template <class System>
Eigen::MatrixXd DenseJacobian(const System& sys, const std::vector<double>& y) {
  vivp::spacetime::PatternedMatrix jac;
  jac.Assemble(sys.size(), [&](auto& sink) { sys.Jacobian(y.data(), sink); });
  return Eigen::MatrixXd(jac.matrix());
}

using Grid = vivp::sbp::SpaceGrid<double>;

// One window of electromagnetism in d + 1 D on `g`: `op` with nt points
// (Δt = 0.1), every potential and velocity of the data `data`, every
// unknown `unknown`, and its Jacobian there as a dense matrix.
template <int d>
struct MaxwellWindow {
  using Density = vivp::fields::MaxwellIn<d>;
  static constexpr int m = d + 1;
  vivp::sbp::RegularizedOperator<double> dbar;
  Density density;
  vivp::action::FieldSystem<Density> sys;
  std::vector<double> y;
  Eigen::MatrixXd J;
  MaxwellWindow(const std::string& op, const Grid& g, int nt, double data,
                double velocity, double unknown)
      : dbar(vivp::sbp::MakeOperator<double>(op, nt, 0.0, 0.1 * (nt - 1))),
        sys(density, dbar, g, std::vector<double>(g.points() * m, data),
            std::vector<double>(g.points() * m, velocity)),
        y(sys.size(), unknown),
        J(DenseJacobian(sys, y)) {}
};

using Slices = vivp::studies::MaxwellSlice;
using Fields = vivp::studies::MaxwellFields;
using PlaneWave = vivp::studies::MaxwellPlaneWave;
using vivp::studies::FieldsOf;

// How far the march's gauge moved: max |A₀| and max |D·A| over the slices
// (both 0 for the transverse wave's data).
struct Gauge {
  double a0 = 0, longitudinal = 0;
};
inline Gauge GaugeParts(const Grid& g,
                        const vivp::spacetime::FieldSolution& s) {
  const int n = g.points();
  std::vector<double> grad(std::size_t(n) * 6);
  Grid::GradientWork<double> w;
  Gauge r;
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    const std::span<const double> phi(&s.phi[k * n * 3], std::size_t(n) * 3);
    g.Gradient<double>(3, phi, grad, w);
    for (int j = 0; j < n; ++j) {
      r.a0 = std::max(r.a0, std::abs(phi[j * 3]));
      r.longitudinal =
          std::max(r.longitudinal,
                   std::abs(grad[(j * 2) * 3 + 1] + grad[(j * 2 + 1) * 3 + 2]));
    }
  }
  return r;
}

// E, B and the energy at every kept slice.
struct Observed {
  std::vector<Fields> fields;
  std::vector<double> energy;
};
inline Observed Observables(const Grid& g,
                            const vivp::spacetime::FieldSolution& s) {
  const std::size_t n = std::size_t(g.points()) * 3;
  Observed o;
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    const std::span<const double> phi(&s.phi[k * n], n),
        phi_t(&s.phi_t[k * n], n);
    o.fields.push_back(FieldsOf(g, phi, phi_t));
    o.energy.push_back(vivp::action::ChargesOfSlice(
                           vivp::fields::MaxwellIn<2>{}, g, phi, phi_t)
                           .energy);
  }
  return o;
}

// The largest difference of E, B or the energy, each relative to its
// largest value.
inline double Difference(const Observed& a, const Observed& b) {
  if (a.fields.size() != b.fields.size()) return INFINITY;
  double e = 0, emax = 0, f = 0, fmax = 0, w = 0, wmax = 0;
  for (std::size_t k = 0; k < a.fields.size(); ++k) {
    for (std::size_t i = 0; i < a.fields[k].e.size(); ++i) {
      e = std::max(e, std::abs(a.fields[k].e[i] - b.fields[k].e[i]));
      emax = std::max(emax, std::abs(a.fields[k].e[i]));
    }
    for (std::size_t i = 0; i < a.fields[k].b.size(); ++i) {
      f = std::max(f, std::abs(a.fields[k].b[i] - b.fields[k].b[i]));
      fmax = std::max(fmax, std::abs(a.fields[k].b[i]));
    }
    w = std::max(w, std::abs(a.energy[k] - b.energy[k]));
    wmax = std::max(wmax, std::abs(a.energy[k]));
  }
  return std::max({e / emax, f / fmax, w / wmax});
}

// The data in another gauge: A_b + D_bχ, ∂_tA_b + D_bχ̇, A₀ − χ̇, with χ
// and χ̇ smooth (random Fourier modes up to |q| = 3, amplitude about 1),
// and an arbitrary start for A₀'s velocity, which is no datum.
inline Slices RandomGauge(const Grid& g, const Slices& data,
                          std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = g.points();
  auto smooth = [&] {
    std::vector<double> chi(n, 0.0);
    for (int q0 = 0; q0 <= 3; ++q0)
      for (int q1 = 0; q1 <= 3; ++q1) {
        const double a = 0.3 * u(rng), p = 3 * u(rng);
        for (int j = 0; j < n; ++j)
          chi[j] += a * std::sin(q0 * g.x(j, 0) + q1 * g.x(j, 1) + p);
      }
    return chi;
  };
  const auto chi = smooth(), chi_t = smooth(), a0_t = smooth();
  Slices s = data;
  std::vector<double> d(n);
  for (int b = 0; b < 2; ++b) {
    g.Apply<double>(b, chi, d);
    for (int j = 0; j < n; ++j) s.phi[j * 3 + 1 + b] += d[j];
    g.Apply<double>(b, chi_t, d);
    for (int j = 0; j < n; ++j) s.phi_t[j * 3 + 1 + b] += d[j];
  }
  for (int j = 0; j < n; ++j) {
    s.phi[j * 3] -= chi_t[j];
    s.phi_t[j * 3] += a0_t[j];
  }
  return s;
}

}  // namespace gauge_test
