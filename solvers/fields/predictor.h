// An independent integration of a field window's semi-discrete equations:
// the Newton start of the window and the reference its result is checked
// against, as in point mechanics (solvers/variational/predictor.h, whose
// Dormand–Prince integration and error bound it shares). The equations are
// those of the method of lines on the same spatial operator
// (method_of_lines.h: M φ̈_j = ∂ℒ/∂φ(j) + (D_xᵀ Hˣ ∂ℒ/∂φ_x)_j / Hˣ_j), so
// nothing is derived by hand here either.
#pragma once

#include <span>
#include <vector>

#include "core/autodiff/pointwise.h"
#include "core/sbp/space.h"
#include "solvers/fields/method_of_lines.h"
#include "solvers/variational/predictor.h"

namespace vivp::fields {

template <class Density>
class FieldPredictor {
 public:
  static constexpr int m = Density::kComponents;
  using State = std::vector<double>;

  // phi0, pi0: a state at which the density's form is checked (the march's
  // initial data; method_of_lines.h).
  FieldPredictor(const Density& density, const sbp::SpaceDerivative<double>& dx,
                 std::span<const double> phi0, std::span<const double> pi0)
      : density_(density),
        dx_(dx),
        n_(std::size_t(dx.points()) * m),
        acceleration_(density, dx, phi0, pi0),
        acc_(n_) {}

  int dim() const { return int(n_); }

  // From (φ, φ_t) = (x0, v0) at τ = 0 to the nodes tau[0 … count), writing
  // φ and φ_t slice-major into x and v (count·n values each).
  variational::PredictorReport Run(const double* x0, const double* v0,
                                   const double* tau, int count, double tol_abs,
                                   double tol_rel, double* x, double* v) {
    State s(2 * n_);
    std::copy(x0, x0 + n_, s.begin());
    std::copy(v0, v0 + n_, s.begin() + n_);
    auto rhs = [this](const State& y, State& dy, double) {
      std::copy(y.begin() + n_, y.end(), dy.begin());
      acceleration_(std::span<const double>(y.data(), n_),
                    std::span<double>(acc_));
      std::copy(acc_.begin(), acc_.end(), dy.begin() + n_);
    };
    double scale_x = 0, scale_v = 0;
    return variational::IntegrateToNodes(
        s, rhs, tau, count, tol_abs, tol_rel, step_,
        [&](const State& y, int i) {
          for (std::size_t k = 0; k < n_; ++k) {
            x[i * n_ + k] = y[k];
            v[i * n_ + k] = y[n_ + k];
            scale_x = std::max(scale_x, std::abs(y[k]));
            scale_v = std::max(scale_v, std::abs(y[n_ + k]));
          }
        },
        scale_x, scale_v);
  }

  // ∂ℒ/∂φ_t at each point of the slice (φ, φ_t): the momentum density, the
  // continuum value of −λ3 at a window's end (the Newton start of λ3).
  void Momentum(const double* phi, const double* phi_t, double* p) const {
    phi_x_.resize(n_);
    dx_.ApplyComponents(m, std::span<const double>(phi, n_), phi_x_);
    auto call = [&](const auto* w) { return density_(w, w + m, w + 2 * m); };
    for (std::size_t j = 0; j < n_ / m; ++j) {
      double z[3 * m];
      for (int a = 0; a < m; ++a) {
        z[a] = phi[j * m + a];
        z[m + a] = phi_t[j * m + a];
        z[2 * m + a] = phi_x_[j * m + a];
      }
      const auto g = autodiff::Gradient<double, 3 * m>(call, z).second;
      for (int a = 0; a < m; ++a) p[j * m + a] = g[m + a];
    }
  }

 private:
  const Density& density_;
  const sbp::SpaceDerivative<double>& dx_;
  std::size_t n_;
  FieldAcceleration<Density> acceleration_;
  std::vector<double> acc_;
  mutable std::vector<double> phi_x_;
  double step_ = 0;  // last accepted step, the next run's first
};

}  // namespace vivp::fields
