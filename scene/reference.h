// Reference solutions for a scene's `[output] reference`, computed only when
// the scene asks for one:
//   exact  closed forms — linear systems (kinetic, spring, gravity, damping,
//          growth, chain with β = 0) through the matrix exponential of the
//          affine equation of motion; kinetic + quartic (dof 1, Jacobi cn);
//          kinetic + pendulum (dof 1, libration, Jacobi sn); kinetic +
//          central (dof 2, bound orbit, Kepler's equation);
//   ode    the Euler–Lagrange equations from automatic differentiation of the
//          scene's own L and Λ (core/action/euler_lagrange.h), integrated by
//          Boost.Odeint's Runge–Kutta–Fehlberg 7(8), error-controlled to
//          1e-13 absolute and relative, stepped onto every output time.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/action/euler_lagrange.h"
#include "scene/scene.h"
#include "solvers/variational/ode_reference.h"

namespace vivp::scene {

class Reference {
 public:
  virtual ~Reference() = default;
  // The reference state at t; t does not decrease from call to call.
  virtual void State(double t, double* x, double* v) = 0;
  virtual std::string description() const = 0;
};

// Empty if reference = "exact" is available for the scene, else why not.
std::string ExactSolutionUnavailable(const Scene& scene);
// True when every effect is linear (the exact reference is a matrix
// exponential).
bool LinearScene(const Scene& scene);
// The non-linear closed forms (anharmonic, pendulum, Kepler), or nullptr.
std::unique_ptr<Reference> MakeClosedForm(const Scene& scene);

namespace detail {

// y = (x, ẋ, 1) (first order: (x, 1)) obeys ẏ = A y for a linear problem:
// y(t) = exp(A (t − t0)) y(t0), the matrix exponential compiled once
// (reference.cc) for every size.
class LinearReference : public Reference {
 public:
  LinearReference(Eigen::MatrixXd a, Eigen::VectorXd y0, double t0, int d)
      : a_(std::move(a)), y0_(std::move(y0)), t0_(t0), d_(d) {}
  void State(double t, double* x, double* v) override;
  std::string description() const override;

 private:
  Eigen::MatrixXd a_;
  Eigen::VectorXd y0_;
  double t0_;
  int d_;
};

// A is read off the Euler–Lagrange equation at the origin, where the
// derivatives of an affine equation are exact.
template <class P>
std::unique_ptr<Reference> MakeLinearReference(const P& problem,
                                               const Scene& s) {
  constexpr int d = P::kDim;
  const int n = s.order * d + 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd y0 = Eigen::VectorXd::Zero(n);
  const double zero[2 * d] = {};
  const auto g = action::DiagonalDerivatives<double>(problem, zero);
  const Eigen::Matrix<double, d, d> gxx = g.dmp.template block<d, d>(0, 0);
  const Eigen::Matrix<double, d, d> gxv = g.dmp.template block<d, d>(0, d);
  const Eigen::Matrix<double, d, d> gvx = g.dmp.template block<d, d>(d, 0);
  const Eigen::Matrix<double, d, d> gvv = g.dmp.template block<d, d>(d, d);
  const Eigen::Matrix<double, d, 1> g0 = g.dm.template head<d>();
  if (s.order == 2) {
    // ẍ = G_vv⁻¹(g0 + G_xx x + (G_xv − G_vx) ẋ)
    const auto lu = gvv.partialPivLu();
    a.block(0, d, d, d).setIdentity();
    a.block(d, 0, d, d) = lu.solve(gxx);
    a.block(d, d, d, d) = lu.solve(gxv - gvx);
    a.block(d, 2 * d, d, 1) = lu.solve(g0);
    for (int c = 0; c < d; ++c) y0[d + c] = s.v0[c];
  } else {
    // 0 = g0 + G_xx x + (G_xv − G_vx) ẋ
    const auto lu = (gxv - gvx).partialPivLu();
    a.block(0, 0, d, d) = -lu.solve(gxx);
    a.block(0, d, d, 1) = -lu.solve(g0);
  }
  for (int c = 0; c < d; ++c) y0[c] = s.x0[c];
  y0[n - 1] = 1;
  return std::make_unique<LinearReference>(std::move(a), std::move(y0),
                                           s.t_start, d);
}

// The Euler–Lagrange reference of solvers/variational/ode_reference.h
// behind the scene's Reference interface.
template <class P>
class OdeReference : public Reference {
 public:
  OdeReference(const P& problem, const Scene& s)
      : ode_(problem, s.order, s.t_start, s.x0, s.v0, s.t_end - s.t_start) {}

  void State(double t, double* x, double* v) override {
    try {
      ode_.State(t, x, v);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(std::string(e.what()) +
                               ", or reference = \"none\"");
    }
  }

  std::string description() const override {
    return vivp::variational::OdeReference<P>::Description();
  }

 private:
  vivp::variational::OdeReference<P> ode_;
};

}  // namespace detail

// The reference the scene asks for (nullptr for "none"). `problem` must
// outlive the reference.
template <class P>
std::unique_ptr<Reference> MakeReference(const P& problem, const Scene& s) {
  if (s.output.reference == "ode")
    return std::make_unique<detail::OdeReference<P>>(problem, s);
  if (s.output.reference == "exact") {
    if (LinearScene(s)) return detail::MakeLinearReference(problem, s);
    return MakeClosedForm(s);
  }
  return nullptr;
}

}  // namespace vivp::scene
