// The multiplier-corrected end state of a solve (docs/method.md §7): the
// position x_N + M⁻¹λ4, the momentum −λ3 moved to it and the velocity of
// that momentum, and the embedded error estimates of x_N and (Dx)_N. The
// state a march hands from one window to the next.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <limits>
#include <vector>

#include "core/action/density.h"
#include "core/autodiff/pointwise.h"
#include "solvers/variational/ivp_types.h"

namespace vivp::variational {

// The velocity v with ∂L/∂ẋ(x, v) = p, by Newton from the guess v:
// v ← v + M(x, v)⁻¹ (p − ∂L/∂ẋ(x, v)), M = ∂²L/∂ẋ². The guess M⁻¹p is the
// answer when L = ½ẋᵀMẋ − V (no step is taken: the residual is round-off);
// with a term linear in ẋ, a vector potential b(x)·ẋ, p = Mẋ + b and one
// step reaches v = M⁻¹(p − b); a few reach round-off for other L.
template <class Real, class P>
Eigen::Matrix<Real, P::kDim, 1> VelocityOfMomentum(
    const P& problem, const Real* x, Eigen::Matrix<Real, P::kDim, 1> v,
    const Eigen::Matrix<Real, P::kDim, 1>& p) {
  constexpr int d = P::kDim;
  constexpr Real kEps = std::numeric_limits<Real>::epsilon();
  Real z[2 * d];
  for (int c = 0; c < d; ++c) z[c] = x[c];
  for (int step = 0; step < 4; ++step) {
    for (int c = 0; c < d; ++c) z[d + c] = v[c];
    const auto h = action::LagrangianDerivatives<Real>(problem, z);
    const Eigen::Matrix<Real, d, 1> r = p - h.gradient.template tail<d>();
    const Real scale =
        std::max(p.cwiseAbs().maxCoeff(),
                 h.gradient.template tail<d>().cwiseAbs().maxCoeff());
    if (r.cwiseAbs().maxCoeff() <= Real(16) * kEps * scale) break;
    v += h.hessian.template bottomRightCorner<d, d>().fullPivLu().solve(r);
  }
  return v;
}

// M⁻¹b for the mass M of one end state, twice per window. Up to four
// coordinates by Eigen's closed-form inverse: a full-pivoting LU of a 2 × 2
// mass, factored and applied twice, was 2.3 % of an lgl8 march's
// instructions on Kepler e = 0.9 (callgrind); with M = I the inverse is I
// and the products exact, as the LU's solves were. A mass too close to
// singular for the cofactors, and more coordinates, keep the full-pivoting
// LU.
template <class Real, int d>
class MassSolve {
 public:
  using Mat = Eigen::Matrix<Real, d, d>;
  using Vec = Eigen::Matrix<Real, d, 1>;
  explicit MassSolve(const Mat& m) {
    if constexpr (d <= 4) {
      // |det M| against the size of its entries to the power d.
      const Real scale = m.cwiseAbs().maxCoeff();
      Real threshold(1e-12);
      for (int i = 0; i < d; ++i) threshold *= scale;
      bool invertible = false;
      m.computeInverseWithCheck(inverse_, invertible, threshold);
      closed_ = invertible && inverse_.allFinite();
    }
    if (!closed_) lu_.compute(m);
  }
  Vec operator()(const Vec& b) const {
    return closed_ ? Vec(inverse_ * b) : Vec(lu_.solve(b));
  }

 private:
  bool closed_ = false;
  Mat inverse_;
  Eigen::FullPivLU<Mat> lu_;
};

// The multiplier-corrected end state (docs/method.md §7) from the end node
// (x_N, (Dx)_N) and the multipliers: λ3 = −p(T), and x_N + M⁻¹λ4 is the
// quadrature of the integral form of x, one order better than x_N
// (first-order systems: x_N + C⁻¹λ3, C the coefficient of ẋ).
// Into `e`, whose arrays keep their storage (a march corrects every window's
// end); CorrectEnd below returns a new one.
// `hessian`, when given, is L's Hessian in (x, v) at (x_N, (Dx)_N), which the
// caller has already evaluated there (the window engine, for ω at the end).
template <class Real, class P>
void CorrectEndInto(
    const P& problem, int order, const Real* xn, const Real* vn,
    const Real* lambda3, const Real* lambda4, CorrectedEnd<Real>& e,
    const Eigen::Matrix<Real, 2 * P::kDim, 2 * P::kDim>* hessian = nullptr) {
  constexpr int d = P::kDim;
  using Mat = Eigen::Matrix<Real, d, d>;
  using Vec = Eigen::Matrix<Real, d, 1>;
  Vec l3, xv, vv;
  for (int c = 0; c < d; ++c) {
    l3[c] = lambda3[c];
    xv[c] = xn[c];
    vv[c] = vn[c];
  }
  e.Clear();
  if (order == 2) {
    Vec l4;
    for (int c = 0; c < d; ++c) l4[c] = lambda4[c];
    const Eigen::Matrix<Real, 2 * d, 2 * d> h =
        hessian ? *hessian : action::LagrangianHessian<Real>(problem, xn, vn);
    const Mat mass = h.template bottomRightCorner<d, d>();
    const MassSolve<Real, d> solve(mass);
    const Vec shift = solve(l4);
    // −λ3 is the momentum at x_N; moved to the corrected position along
    // ∂²L/∂x∂ẋ (zero unless L couples x and ẋ, as a vector potential does),
    // it keeps the corrected order (docs/method.md §7).
    const Vec momentum = -l3 + Mat(h.template topRightCorner<d, d>()) * shift;
    // At the corrected position: with a vector potential, b(x_N) would
    // carry x_N's lower order into the velocity.
    const Vec position = xv + shift;
    const Vec velocity =
        VelocityOfMomentum(problem, position.data(), solve(momentum), momentum);
    for (int c = 0; c < d; ++c) {
      e.position.push_back(position[c]);
      e.momentum.push_back(momentum[c]);
      e.velocity.push_back(velocity[c]);
    }
    e.position_error_estimate = double(shift.cwiseAbs().maxCoeff());
    e.velocity_error_estimate = double((vv - velocity).cwiseAbs().maxCoeff());
  } else {
    const Mat coeff = action::FirstOrderCoefficient<Real>(problem, xn, vn);
    const Vec shift = coeff.fullPivLu().solve(l3);
    for (int c = 0; c < d; ++c) e.position.push_back(xv[c] + shift[c]);
    e.position_error_estimate = double(shift.cwiseAbs().maxCoeff());
  }
}

template <class Real, class P>
CorrectedEnd<Real> CorrectEnd(const P& problem, int order, const Real* xn,
                              const Real* vn, const Real* lambda3,
                              const Real* lambda4) {
  CorrectedEnd<Real> e;
  CorrectEndInto(problem, order, xn, vn, lambda3, lambda4, e);
  return e;
}

}  // namespace vivp::variational
