// How a problem joins the registry (registry.h): the problem behind its
// pointwise derivatives (core/action/erased_problem.h), so that the solvers
// it is handed to are the ones compiled once per dimension, with its closed
// form or, without one, a reference computed from its Lagrangian. A light
// header: the solvers are not parsed where a Lagrangian is registered.
#pragma once

#include <functional>
#include <string>

#include "core/action/erased_problem.h"
#include "problems/phase_space.h"
#include "studies/registry.h"

namespace vivp::studies {

// The registry's entry for a problem of d coordinates behind its pointwise
// derivatives: its solves and marches are the solvers compiled once per
// dimension, its momentum ∂L/∂ẋ comes from the model, and `exact` is the
// closed form, or when empty the Euler–Lagrange equations integrated from
// the initial data at t = 0 (ode_reference.h), one integration kept for
// the whole study. Compiled per dimension in VIVP_DIMS (registry_entry.cc).
template <int d>
NamedProblem Entry(std::string name, std::string description,
                   action::ErasedProblem<d> problem,
                   variational::InitialData initial,
                   std::function<ExactState(double)> exact);

// Closed forms in the shape Register's `exact` takes (lagrangians/
// register.h). A scalar problem whose Exact(t) returns {x, v}:
template <class P>
ExactState ScalarExact(const P& p, double t) {
  const auto s = p.Exact(t);
  return {{s.x}, {s.v}, {}};
}

// Canonical systems (L = ½|ẋ|² − V) whose Exact(t) returns (q, p): the
// momentum is the velocity.
template <class P>
ExactState CanonicalExact(const P& p, double t) {
  const std::vector<double> y = p.Exact(t);
  const std::size_t d = y.size() / 2;
  return {{y.begin(), y.begin() + d}, {y.begin() + d, y.end()}, {}};
}

// The initial data of a Hamiltonian problem's state (q, p) for such a
// system.
template <class P>
variational::InitialData CanonicalInitial(const P& p) {
  const std::vector<double> y = problems::InitialState(p);
  const std::size_t d = y.size() / 2;
  return {{y.begin(), y.begin() + d}, {y.begin() + d, y.end()}};
}

}  // namespace vivp::studies
