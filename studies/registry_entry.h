// How a problem joins the registry (registry.h): the solver templates for
// one problem struct, wrapped in type-erased functions.
#pragma once

#include "solvers/variational/ceres_lm.h"
#include "solvers/variational/march.h"
#include "solvers/variational/solve_ivp.h"
#include "studies/registry.h"

namespace vivp {

namespace detail {

template <class P, class ExactFn>
NamedProblem Entry(std::string name, std::string description, P problem,
                   InitialData initial, ExactFn exact_fn) {
  NamedProblem e;
  e.name = std::move(name);
  e.description = std::move(description);
  e.initial = initial;
  e.solve = [problem, initial](const Grid& g, const SolveOptions& o) {
    if (o.path == Path::kCeresLm) return SolveIvpCeres(problem, initial, g, o);
    return SolveIvp(problem, initial, g, o);
  };
  e.march = [problem, initial](const Grid& g, const MarchOptions& o,
                               const NodeObserver& observer) {
    return MarchIvp(problem, initial, g, o, observer);
  };
  e.exact = [problem, exact_fn](double t) {
    ExactState s = exact_fn(problem, t);
    if (!s.v.empty()) {
      const auto m =
          action::MassMatrix<double>(problem, s.x.data(), s.v.data());
      for (int r = 0; r < P::kDim; ++r) {
        double p = 0;
        for (int c = 0; c < P::kDim; ++c) p += m(r, c) * s.v[c];
        s.p.push_back(p);
      }
    }
    return s;
  };
  return e;
}

template <class P>
ExactState Scalar(const P& p, double t) {
  const auto s = p.Exact(t);
  return {{s.x}, {s.v}, {}};
}

}  // namespace detail

}  // namespace vivp
