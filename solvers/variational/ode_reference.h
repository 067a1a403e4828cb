// A reference trajectory for a problem without a closed form: the
// Euler–Lagrange equations of its Lagrangian, obtained by automatic
// differentiation (core/action/euler_lagrange.h), integrated by
// Runge–Kutta–Fehlberg 7(8) (Boost.Odeint) at a tolerance of 1e-13. It is
// independent of the SBP discretization it checks: another method, another
// error.
//
// States are asked for at increasing times, and each call continues from the
// last; asking for an earlier time starts again from the initial data.
#pragma once

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/erased_problem.h"
#include "core/action/euler_lagrange.h"

namespace vivp::variational {

template <class P>
class OdeReference {
 public:
  static constexpr int d = P::kDim;
  using Vec = std::vector<double>;
  static constexpr double kTolerance = 1e-13;
  static constexpr long kMaxSteps = 10'000'000;

  // `order` is the problem's (2: x and ẋ given, 1: x only); `span` sets the
  // first trial step, span/1024. `problem` must outlive the reference.
  OdeReference(const P& problem, int order, double t0, Vec x0, Vec v0,
               double span)
      : problem_(problem),
        order_(order),
        t0_(t0),
        first_dt_(span / 1024),
        x0_(std::move(x0)),
        v0_(std::move(v0)) {
    Restart();
  }

  static std::string Description() {
    return "ode: Euler–Lagrange equations by automatic differentiation, "
           "Runge–Kutta–Fehlberg 7(8) (Boost.Odeint) at tolerance 1e-13";
  }

  // x(t) and ẋ(t) into x[d], v[d]. Throws std::runtime_error when the
  // integration cannot keep its tolerance or needs more than 10^7 steps.
  // (Defined out of the class body, like the two below, so that the extern
  // templates at the end keep the compiler from instantiating them wherever
  // a reference is only used.)
  void State(double t, double* x, double* v);

 private:
  void Restart();
  void Rhs(const Vec& y, Vec& dy) const;

  const P& problem_;
  int order_;
  double t0_, first_dt_;
  Vec x0_, v0_;
  double t_ = 0, dt_ = 0;
  long steps_ = 0;
  Vec y_;
  mutable action::StateVector<P> velocity_ = action::StateVector<P>::Zero();
  boost::numeric::odeint::controlled_runge_kutta<
      boost::numeric::odeint::runge_kutta_fehlberg78<Vec>>
      stepper_;
};

template <class P>
void OdeReference<P>::State(double t, double* x, double* v) {
  namespace odeint = boost::numeric::odeint;
  if (t < t_) Restart();
  auto rhs = [this](const Vec& y, Vec& dy, double) { Rhs(y, dy); };
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
          " at tolerance 1e-13 (a stiff or fast system); use a shorter "
          "time span");
    if (last)
      t_ = t;  // exactly, whatever round-off the step added
    else
      dt_ = h;
  }
  for (int c = 0; c < d; ++c) x[c] = y_[c];
  if (order_ == 2) {
    for (int c = 0; c < d; ++c) v[c] = y_[d + c];
  } else {
    const auto vel = action::FirstOrderVelocity(problem_, y_.data(),
                                                action::StateVector<P>::Zero());
    for (int c = 0; c < d; ++c) v[c] = vel[c];
  }
}

template <class P>
void OdeReference<P>::Restart() {
  t_ = t0_;
  dt_ = first_dt_;
  steps_ = 0;
  y_ = x0_;
  if (order_ == 2) y_.insert(y_.end(), v0_.begin(), v0_.end());
  velocity_ = action::StateVector<P>::Zero();
  stepper_ = boost::numeric::odeint::make_controlled(
      kTolerance, kTolerance,
      boost::numeric::odeint::runge_kutta_fehlberg78<Vec>());
}

template <class P>
void OdeReference<P>::Rhs(const Vec& y, Vec& dy) const {
  // A first-order state holds x only; the equations take (x, ẋ).
  double full[2 * d] = {}, rate[2 * d];
  std::copy(y.begin(), y.end(), full);
  action::EquationsOfMotion(problem_, order_, full, rate, velocity_);
  dy.assign(rate, rate + y.size());
}

}  // namespace vivp::variational

// Compiled once per dimension in the library (precompiled_dim.cc.in).
namespace vivp::variational {
#define VIVP_EXTERN_REFERENCE(D) \
  extern template class OdeReference<action::ErasedProblem<D>>;
VIVP_PRECOMPILED_DIMS(VIVP_EXTERN_REFERENCE)
#undef VIVP_EXTERN_REFERENCE
}  // namespace vivp::variational
