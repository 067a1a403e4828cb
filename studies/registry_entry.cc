#include "studies/registry_entry.h"

#include <memory>
#include <utility>
#include <vector>

#include "solvers/variational/ode_reference.h"
#include "solvers/variational/solve.h"

namespace vivp::studies {

namespace {

// The Euler–Lagrange reference of a problem without a closed form, shared
// by the entry's copies (it refers to `problem`).
template <int d>
std::function<ExactState(double)> OdeExact(
    const action::ErasedProblem<d>& problem,
    const variational::InitialData& initial) {
  using Erased = action::ErasedProblem<d>;
  struct Shared {
    explicit Shared(Erased p) : problem(std::move(p)) {}
    Erased problem;
    std::unique_ptr<variational::OdeReference<Erased>> ode;
  };
  const std::vector<double> zero(d, 0.0);
  auto shared = std::make_shared<Shared>(problem);
  const int order = action::SystemOrder<double>(
      shared->problem, initial.x.data(),
      initial.v.empty() ? zero.data() : initial.v.data());
  shared->ode = std::make_unique<variational::OdeReference<Erased>>(
      shared->problem, order, 0.0, initial.x, initial.v, 1.0);
  return [shared](double t) {
    ExactState s{std::vector<double>(d), std::vector<double>(d), {}};
    shared->ode->State(t, s.x.data(), s.v.data());
    return s;
  };
}

}  // namespace

template <int d>
NamedProblem Entry(std::string name, std::string description,
                   action::ErasedProblem<d> problem,
                   variational::InitialData initial,
                   std::function<ExactState(double)> exact) {
  NamedProblem e;
  e.name = std::move(name);
  e.description = std::move(description);
  e.initial = initial;
  e.reference =
      exact
          ? "exact"
          : variational::OdeReference<action::ErasedProblem<d>>::Description();
  if (!exact) exact = OdeExact(problem, initial);
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
    double z[2 * d];
    for (int c = 0; c < d; ++c) {
      z[c] = x[c];
      z[d + c] = v[c];
    }
    const auto g = action::LagrangianGradient<double>(problem, z);
    return std::vector<double>(g.second.data() + d, g.second.data() + 2 * d);
  };
  e.exact = [exact, momentum = e.momentum](double t) {
    ExactState s = exact(t);
    // The momentum is the quantity −λ3 approximates (docs/method.md §7).
    if (!s.v.empty()) s.p = momentum(s.x.data(), s.v.data());
    return s;
  };
  return e;
}

#define VIVP_ENTRY(D)                                     \
  template NamedProblem Entry(                            \
      std::string, std::string, action::ErasedProblem<D>, \
      variational::InitialData, std::function<ExactState(double)>);
VIVP_PRECOMPILED_DIMS(VIVP_ENTRY)
#undef VIVP_ENTRY

}  // namespace vivp::studies
