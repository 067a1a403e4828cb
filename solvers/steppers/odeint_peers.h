// Boost.Odeint steppers behind the same interface as the vivp steppers
// (Step, evaluations, name, order), driven on the same problems by the same
// harness: runge_kutta4, velocity_verlet, symplectic_rkn_sb3a_mclachlan, and
// runge_kutta_dopri5 (adaptive; its knob is a tolerance, not a step).
// The Nyström forms assume H = ½|p|² + V(q) (unit mass, p = q̇), which holds
// for every separable problem in problems/. Odeint's own order() is recorded
// next to the measured one: velocity_verlet reports 1.
#pragma once

#include <array>
#include <boost/numeric/odeint.hpp>
#include <utility>

#include "solvers/steppers/hamiltonian_system.h"
#include "solvers/steppers/integrate.h"
#include "solvers/steppers/step_result.h"

namespace vivp::steppers::odeint_peers {

namespace odeint = boost::numeric::odeint;

template <class Problem>
class Rk4 {
 public:
  using System = HamiltonianSystem<Problem>;
  using Vector = typename System::Vector;
  using State = std::array<double, System::kN>;
  explicit Rk4(const System& system) : system_(system) {}
  std::string name() const { return "odeint_rk4"; }
  int order() const { return odeint::runge_kutta4<State>::order_value; }
  long evaluations() const { return system_.evaluations(); }
  // The odeint stepper is stateless between steps; making it here keeps its
  // uninitialised scratch arrays out of copies of this object.
  StepReport Step(Vector& y, double h) {
    State x;
    Vector::Map(x.data()) = y;
    odeint::runge_kutta4<State> stepper;
    stepper.do_step(
        [this](const State& s, State& d, double) {
          Vector::Map(d.data()) = system_.Field(Vector::Map(s.data()));
        },
        x, 0.0, h);
    y = Vector::Map(x.data());
    return {};
  }

 private:
  System system_;
};

// Shared by the two Nyström steppers: the force −∂H/∂q at q.
template <class Problem>
class NystromBase {
 public:
  using System = HamiltonianSystem<Problem>;
  using Vector = typename System::Vector;
  static constexpr int kDim = System::kDim;
  using Coor = std::array<double, kDim>;
  explicit NystromBase(const System& system) : system_(system) {}
  long evaluations() const { return system_.evaluations(); }

 protected:
  void Force(const Coor& q, Coor& a) const {
    Vector y = Vector::Zero();
    for (int i = 0; i < kDim; ++i) y[i] = q[i];
    const Vector g = system_.Gradient(y);
    for (int i = 0; i < kDim; ++i) a[i] = -g[i];
  }
  static std::pair<Coor, Coor> Split(const Vector& y) {
    std::pair<Coor, Coor> s;
    for (int i = 0; i < kDim; ++i) {
      s.first[i] = y[i];
      s.second[i] = y[kDim + i];
    }
    return s;
  }
  static void Join(const std::pair<Coor, Coor>& s, Vector& y) {
    for (int i = 0; i < kDim; ++i) {
      y[i] = s.first[i];
      y[kDim + i] = s.second[i];
    }
  }
  System system_;
};

template <class Problem>
class VelocityVerlet : public NystromBase<Problem> {
 public:
  using Base = NystromBase<Problem>;
  using Base::Base;
  using typename Base::Coor;
  using typename Base::Vector;
  std::string name() const { return "odeint_velocity_verlet"; }
  int order() const { return stepper_.order(); }  // odeint says 1
  StepReport Step(Vector& y, double h) {
    auto s = Base::Split(y);
    stepper_.do_step([this](const Coor& q, const Coor&, Coor& a,
                            double) { this->Force(q, a); },
                     s, 0.0, h);
    Base::Join(s, y);
    return {};
  }

 private:
  odeint::velocity_verlet<Coor> stepper_;
};

template <class Problem>
class McLachlan : public NystromBase<Problem> {
 public:
  using Base = NystromBase<Problem>;
  using Base::Base;
  using typename Base::Coor;
  using typename Base::Vector;
  std::string name() const { return "odeint_mclachlan"; }
  int order() const { return stepper_.order(); }
  StepReport Step(Vector& y, double h) {
    auto s = Base::Split(y);
    auto drift = [](const Coor& p, Coor& dq) { dq = p; };
    auto kick = [this](const Coor& q, Coor& dp) { this->Force(q, dp); };
    stepper_.do_step(std::make_pair(drift, kick), s, 0.0, h);
    Base::Join(s, y);
    return {};
  }

 private:
  odeint::symplectic_rkn_sb3a_mclachlan<Coor> stepper_;
};

// Dense-free adaptive Dormand–Prince 5(4) from 0 to t_end with absolute and
// relative tolerance tol; the run report counts accepted steps and ∇H calls.
template <class Problem>
RunReport Dopri5(const HamiltonianSystem<Problem>& system,
                 typename HamiltonianSystem<Problem>::Vector& y, double t_end,
                 double tol) {
  using System = HamiltonianSystem<Problem>;
  using Vector = typename System::Vector;
  using State = std::array<double, System::kN>;
  if (!std::isfinite(tol) || !(tol > 0))
    throw std::invalid_argument("tolerance must be finite and positive");
  CheckRunArguments(t_end, 0);
  State x;
  Vector::Map(x.data()) = y;
  const long e0 = system.evaluations();
  RunReport report;
  report.steps = static_cast<long>(odeint::integrate_adaptive(
      odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<State>()),
      [&](const State& s, State& d, double) {
        Vector::Map(d.data()) = system.Field(Vector::Map(s.data()));
      },
      x, 0.0, t_end, t_end * 1e-3));
  y = Vector::Map(x.data());
  report.evaluations = system.evaluations() - e0;
  if (!y.allFinite()) report.status = StepOutcome::kUnstable;
  return report;
}

}  // namespace vivp::steppers::odeint_peers
