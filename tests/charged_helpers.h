// Helpers of the tests of charged fields (core/action/charged_field.h): a
// discrete gauge transformation of a window's unknowns and data, the rows
// of φ rotated back, and the Jacobian against central differences.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "core/action/charged_field.h"
#include "solvers/spacetime/assembly.h"

namespace charged_test {

using vivp::action::Complex;

struct Moved {
  std::vector<double> y, phi0, pi0;
};

// Rotates the complex pair (re, im) of v at positions r, i by e^{iθ}.
inline void Rotate(std::vector<double>& v, int r, int i, double theta) {
  const Complex z = std::polar(1.0, theta) * Complex(v[r], v[i]);
  v[r] = z.real();
  v[i] = z.imag();
}

// The gauge α (alpha[i·Nx + j]) applied to the unknowns y and the system's
// data (docs/gauge.md §7); shift_chi = false leaves χ in place, a wrong
// transformation (the control: the transport phases no longer cancel).
template <int d, class System>
Moved Gauge(const System& s, const std::vector<double>& y,
            const std::vector<double>& alpha, bool shift_chi = true) {
  constexpr int m = System::m;
  const int nt = s.time_points(), nx = s.space_points();
  const auto& D = s.time_operator().base();
  auto at = [&](int i, int j) { return alpha[std::size_t(i) * nx + j]; };
  Moved out{y, s.phi0(), s.pi0()};
  for (int j = 0; j < nx; ++j) {
    for (int i = 0; i < nt; ++i) {
      Rotate(out.y, s.Phi(i, j, System::kRe), s.Phi(i, j, System::kIm),
             at(i, j));
      for (int b = 0; b < d; ++b)
        out.y[s.Phi(i, j, System::A(b))] +=
            (at(i, s.Next(j, b)) - at(i, j)) / s.h(b);
      if (shift_chi) out.y[s.Phi(i, j, System::kChi)] += at(i, j);
    }
    Rotate(out.phi0, j * m + System::kRe, j * m + System::kIm, at(0, j));
    Rotate(out.pi0, j * m + System::kRe, j * m + System::kIm, at(0, j));
    for (int b = 0; b < d; ++b) {
      const int k = s.Next(j, b);
      out.phi0[j * m + System::A(b)] += (at(0, k) - at(0, j)) / s.h(b);
      double dk = 0, dj = 0;  // (Dα)(0) at k and j
      const auto r = D.row(0);
      for (std::size_t e = 0; e < r.coeffs.size(); ++e) {
        dk += r.coeffs[e] * D.inv_dt() * at(r.first + int(e), k);
        dj += r.coeffs[e] * D.inv_dt() * at(r.first + int(e), j);
      }
      out.pi0[j * m + System::A(b)] += (dk - dj) / s.h(b);
    }
  }
  return out;
}

// The rows of φ of a transformed window rotated back by e^{−iα}: node rows
// by their node's α, the data rows by α(0) (all other rows are invariant).
template <int d, class System>
void RotateRowsBack(const System& s, const std::vector<double>& alpha,
                    std::vector<double>& f) {
  const int nt = s.time_points(), nx = s.space_points();
  for (int j = 0; j < nx; ++j) {
    for (int i = 0; i < nt; ++i)
      Rotate(f, s.Phi(i, j, System::kRe), s.Phi(i, j, System::kIm),
             -alpha[std::size_t(i) * nx + j]);
    for (auto row : {&System::Lambda3, &System::Lambda4})
      Rotate(f, (s.*row)(j, System::kRe), (s.*row)(j, System::kIm),
             -alpha[std::size_t(j)]);
  }
}

// max |J v − (F(y + εv) − F(y − εv))/2ε| / max |J v| over three random v.
template <class System>
double JacobianError(const System& s, const std::vector<double>& y,
                     std::mt19937& rng) {
  vivp::spacetime::PatternedMatrix jac;
  jac.Assemble(s.size(), [&](auto& sink) { s.Jacobian(y.data(), sink); });
  std::normal_distribution<double> g;
  double worst = 0;
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd v(s.size());
    for (auto& x : v) x = g(rng);
    const Eigen::VectorXd jv = jac.matrix() * v;
    const double eps = 1e-6;
    std::vector<double> yp(y), ym(y), fp(y.size()), fm(y.size());
    for (std::size_t k = 0; k < y.size(); ++k) {
      yp[k] += eps * v[k];
      ym[k] -= eps * v[k];
    }
    s.Residual(yp.data(), fp.data());
    s.Residual(ym.data(), fm.data());
    double diff = 0;
    for (std::size_t k = 0; k < y.size(); ++k)
      diff = std::max(diff, std::abs(jv[k] - (fp[k] - fm[k]) / (2 * eps)));
    worst = std::max(worst, diff / jv.cwiseAbs().maxCoeff());
  }
  return worst;
}

}  // namespace charged_test
