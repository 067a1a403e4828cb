// How a problem joins the registry (registry.h): the solver templates for
// one problem struct, wrapped in type-erased functions, with its closed form
// or, without one, a reference computed from its Lagrangian.
#pragma once

#include <memory>

#include "problems/phase_space.h"
#include "solvers/variational/ode_reference.h"
#include "solvers/variational/solve.h"
#include "studies/registry.h"

namespace vivp::studies {

namespace detail {

template <class P, class ExactFn>
NamedProblem Entry(std::string name, std::string description, P problem,
                   variational::InitialData initial, ExactFn exact_fn,
                   std::string reference = "exact") {
  NamedProblem e;
  e.name = std::move(name);
  e.description = std::move(description);
  e.initial = initial;
  e.reference = std::move(reference);
  e.solve = [problem, initial](const variational::Grid& g,
                               const variational::SolveOptions& o) {
    return Solve(problem, initial, g, o);
  };
  e.march = [problem, initial](const variational::Grid& g,
                               const variational::MarchOptions& o,
                               const variational::NodeObserver& observer) {
    return Solve(problem, initial, g, o, observer);
  };
  e.momentum = [problem](const double* x, const double* v) {
    // ∂L/∂ẋ: with a vector potential it is not Mẋ.
    constexpr int d = P::kDim;
    double z[2 * d];
    for (int c = 0; c < d; ++c) {
      z[c] = x[c];
      z[d + c] = v[c];
    }
    const auto g = autodiff::Gradient<double, 2 * d>(
        [&](const auto* y) { return problem(y, y + d); }, z);
    return std::vector<double>(g.second.data() + d, g.second.data() + 2 * d);
  };
  e.exact = [exact_fn, problem, momentum = e.momentum](double t) {
    ExactState s = exact_fn(problem, t);
    // The momentum is the quantity −λ3 approximates (docs/method.md §7).
    if (!s.v.empty()) s.p = momentum(s.x.data(), s.v.data());
    return s;
  };
  return e;
}

// A problem without a closed form: the Euler–Lagrange equations of its
// Lagrangian integrated from its initial data at t = 0 to t
// (ode_reference.h), one integration kept for the whole study.
template <class P>
NamedProblem EntryWithReference(std::string name, std::string description,
                                P problem, variational::InitialData initial) {
  struct Shared {
    explicit Shared(P p) : problem(std::move(p)) {}
    P problem;
    std::unique_ptr<variational::OdeReference<P>> ode;  // refers to `problem`
  };
  const std::vector<double> zero(P::kDim, 0.0);
  const int order = action::SystemOrder<double>(
      problem, initial.x.data(),
      initial.v.empty() ? zero.data() : initial.v.data());
  auto shared = std::make_shared<Shared>(problem);
  shared->ode = std::make_unique<variational::OdeReference<P>>(
      shared->problem, order, 0.0, initial.x, initial.v, 1.0);
  auto exact = [shared](const P&, double t) {
    ExactState s{
        std::vector<double>(P::kDim), std::vector<double>(P::kDim), {}};
    shared->ode->State(t, s.x.data(), s.v.data());
    return s;
  };
  return Entry(std::move(name), std::move(description), std::move(problem),
               std::move(initial), exact,
               variational::OdeReference<P>::Description());
}

}  // namespace detail

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
