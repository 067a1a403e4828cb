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
#include <boost/numeric/odeint.hpp>
#include <memory>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "scene/scene.h"
#include "core/action/euler_lagrange.h"

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
// A is read off the Euler–Lagrange equation at the origin, where the
// derivatives of an affine equation are exact.
template <class P>
class LinearReference : public Reference {
 public:
  static constexpr int d = P::kDim;
  LinearReference(const P& problem, const Scene& s) : t0_(s.t_start) {
    const int n = s.order * d + 1;
    a_ = Eigen::MatrixXd::Zero(n, n);
    y0_ = Eigen::VectorXd::Zero(n);
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
      a_.block(0, d, d, d).setIdentity();
      a_.block(d, 0, d, d) = lu.solve(gxx);
      a_.block(d, d, d, d) = lu.solve(gxv - gvx);
      a_.block(d, 2 * d, d, 1) = lu.solve(g0);
      for (int c = 0; c < d; ++c) y0_[d + c] = s.v0[c];
    } else {
      // 0 = g0 + G_xx x + (G_xv − G_vx) ẋ
      const auto lu = (gxv - gvx).partialPivLu();
      a_.block(0, 0, d, d) = -lu.solve(gxx);
      a_.block(0, d, d, 1) = -lu.solve(g0);
    }
    for (int c = 0; c < d; ++c) y0_[c] = s.x0[c];
    y0_[n - 1] = 1;
  }

  void State(double t, double* x, double* v) override {
    const Eigen::VectorXd y = (a_ * (t - t0_)).exp() * y0_;
    for (int c = 0; c < d; ++c) x[c] = y[c];
    if (a_.rows() == 2 * d + 1)
      for (int c = 0; c < d; ++c) v[c] = y[d + c];
    else
      for (int c = 0; c < d; ++c) v[c] = (a_.row(c) * y)(0);
  }

  std::string description() const override {
    return "exact: matrix exponential of the linear equation of motion";
  }

 private:
  double t0_;
  Eigen::MatrixXd a_;
  Eigen::VectorXd y0_;
};

template <class P>
class OdeReference : public Reference {
 public:
  static constexpr int d = P::kDim;
  using Vec = std::vector<double>;
  static constexpr double kTolerance = 1e-13;
  static constexpr long kMaxSteps = 10'000'000;

  OdeReference(const P& problem, const Scene& s)
      : problem_(problem),
        order_(s.order),
        t_(s.t_start),
        dt_((s.t_end - s.t_start) / 1024),
        y_(s.x0),
        stepper_(boost::numeric::odeint::make_controlled(
            kTolerance, kTolerance,
            boost::numeric::odeint::runge_kutta_fehlberg78<Vec>())) {
    if (order_ == 2) y_.insert(y_.end(), s.v0.begin(), s.v0.end());
  }

  void State(double t, double* x, double* v) override {
    namespace odeint = boost::numeric::odeint;
    auto rhs = [this](const std::vector<double>& y, std::vector<double>& dy,
                      double) { Rhs(y, dy); };
    int failures = 0;
    while (t_ < t) {
      // Land exactly on t; keep the controller's own step size for later.
      const bool last = t_ + dt_ >= t;
      double h = last ? t - t_ : dt_;
      if (stepper_.try_step(rhs, y_, t_, h) == odeint::fail) {
        dt_ = h;
        if (++failures > 1000)
          throw std::runtime_error(
              "the ode reference cannot keep its error below 1e-13 near t = " +
              std::to_string(t_));
        continue;
      }
      failures = 0;
      if (++steps_ > kMaxSteps)
        throw std::runtime_error(
            "the ode reference needs more than 10^7 steps to reach t = " +
            std::to_string(t) +
            " at tolerance 1e-13 (a stiff or fast system); use reference = "
            "\"none\" or a shorter time span");
      if (last)
        t_ = t;  // exactly, whatever round-off the step added
      else
        dt_ = h;
    }
    for (int c = 0; c < d; ++c) x[c] = y_[c];
    if (order_ == 2) {
      for (int c = 0; c < d; ++c) v[c] = y_[d + c];
    } else {
      const auto vel = action::FirstOrderVelocity(
          problem_, y_.data(), Eigen::Matrix<double, d, 1>::Zero());
      for (int c = 0; c < d; ++c) v[c] = vel[c];
    }
  }

  std::string description() const override {
    return "ode: Euler–Lagrange equations by automatic differentiation, "
           "Runge–Kutta–Fehlberg 7(8) (Boost.Odeint) at tolerance 1e-13";
  }

 private:
  void Rhs(const std::vector<double>& y, std::vector<double>& dy) const {
    // A first-order state holds x only; the equations take (x, ẋ).
    double full[2 * d] = {}, rate[2 * d];
    std::copy(y.begin(), y.end(), full);
    action::EquationsOfMotion(problem_, order_, full, rate, velocity_);
    dy.assign(rate, rate + y.size());
  }

  const P& problem_;
  int order_;
  double t_, dt_;
  long steps_ = 0;
  std::vector<double> y_;
  mutable action::StateVector<P> velocity_ = action::StateVector<P>::Zero();
  boost::numeric::odeint::controlled_runge_kutta<
      boost::numeric::odeint::runge_kutta_fehlberg78<Vec>>
      stepper_;
};

}  // namespace detail

// The reference the scene asks for (nullptr for "none"). `problem` must
// outlive the reference.
template <class P>
std::unique_ptr<Reference> MakeReference(const P& problem, const Scene& s) {
  if (s.output.reference == "ode")
    return std::make_unique<detail::OdeReference<P>>(problem, s);
  if (s.output.reference == "exact") {
    if (LinearScene(s))
      return std::make_unique<detail::LinearReference<P>>(problem, s);
    return MakeClosedForm(s);
  }
  return nullptr;
}

}  // namespace vivp::scene
