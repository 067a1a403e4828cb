// One statement makes a Lagrangian known by name wherever vivp takes one:
//
//   namespace {
//   const bool registered = vivp::Register<Spring>({
//       .name = "spring",
//       .description = "harmonic spring, L = ½ẋ² − ½kx²",
//       .initial = {{1.0}, {0.0}},
//       .parameters = {{"k", &Spring::k}},
//   });
//   }  // namespace
//
// written below the struct, in a file of its own in lagrangians/ (every file
// there is compiled into the programs: no list, no CMakeLists to edit). The
// Lagrangian is then `vivp converge --problem spring` — measured against
// `exact` when given, otherwise against a reference integration of its
// Euler–Lagrange equations, and the study says which — a scene
// `type = "spring"` with the listed parameters, and `vivp bench --problem
// spring` when L = ½ẋᵀMẋ + b(x)·ẋ − V has a Hamiltonian form
// (studies/legendre.h).
//
// Registration runs during static initialization; the registries it fills
// are function-local statics, so the order of the files does not matter.
// What the file compiles is L's pointwise derivatives (action::Erase): the
// solvers and the scene runner are compiled once per number of coordinates
// in VIVP_DIMS, which L::kDim must be one of.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/action/erased_problem.h"
#include "scene/register_lagrangian.h"
#include "studies/bench_lagrangian.h"
#include "studies/registry_entry.h"

namespace vivp {

// Closed forms for Registration::exact (studies/registry_entry.h).
using studies::CanonicalExact;
using studies::CanonicalInitial;
using studies::ExactState;
using studies::ScalarExact;

// Every field has a default, so that a registration names only what it
// has (and -Wmissing-field-initializers stays quiet).
template <class L>
struct Registration {
  std::string name = {};         // the name on the command line and in scenes
  std::string description = {};  // one line, shown by `vivp converge`
  variational::InitialData initial = {};  // of `vivp converge` and the figures
  // Members a scene may set (`type = "NAME"` with `member = value`).
  std::vector<std::pair<std::string, double L::*>> parameters = {};
  // The closed form, if there is one: position and velocity at t for the
  // initial data above.
  std::function<studies::ExactState(const L&, double)> exact = {};
  // The span of `vivp bench` (from t = 0), where L has a Hamiltonian form.
  double bench_t_end = 10.0;
};

// The second argument of Register for a Lagrangian not offered as a scene
// type: a variant of another registration, or a system the built-in effects
// already compose. (The scene runner is then not compiled for it.)
struct NotInScenes {};
inline constexpr NotInScenes kNotInScenes{};

namespace detail {

// Offers L to `vivp bench`: its Legendre form is found when the bench's
// problems are first listed (legendre.h), not at start-up.
template <class L>
void AddToBench(const Registration<L>& r) {
  constexpr int d = L::kDim;
  std::function<studies::BenchProblem()> make;
  if constexpr (action::HasLambda<L>) {
    make = []() -> studies::BenchProblem {
      throw std::domain_error("L has a dissipative term Λ");
    };
  } else if constexpr (d > studies::kMaxBenchDim) {
    make = []() -> studies::BenchProblem {
      throw std::domain_error("the bench is compiled for 1 to 3 coordinates");
    };
  } else {
    make = [l = L{}, name = r.name, init = r.initial, t = r.bench_t_end] {
      const studies::LegendreForm<d> form = studies::FindLegendreForm(l, init);
      if (form.separable)
        return studies::LagrangianBenchProblem<d, true>(
            name, studies::ErasedHamiltonian<d, true>::Of(l, form, init), t);
      return studies::LagrangianBenchProblem<d, false>(
          name, studies::ErasedHamiltonian<d, false>::Of(l, form, init), t);
    };
  }
  studies::AddBenchCandidate(r.name, std::move(make));
}

}  // namespace detail

namespace detail {

// Adds L, behind its pointwise derivatives, to the registry: the solvers it
// is handed to are compiled once per dimension in the libraries.
template <class L>
void AddToRegistry(const Registration<L>& r) {
  static_assert(action::IsPrecompiledDim(L::kDim),
                "L::kDim is not among the numbers of coordinates the "
                "libraries are compiled for: add it to VIVP_DIMS "
                "(cmake -DVIVP_DIMS=\"1;2;3;8;...\")");
  std::function<studies::ExactState(double)> exact;
  if (r.exact) exact = [f = r.exact, l = L{}](double t) { return f(l, t); };
  studies::AddProblem(studies::Entry(r.name, r.description, action::Erase(L{}),
                                     r.initial, std::move(exact)));
}

}  // namespace detail

// Adds L to the problems of `vivp converge`, `vivp bench`, the figures and
// the tests.
template <class L>
bool Register(Registration<L> r, NotInScenes) {
  detail::AddToBench(r);
  detail::AddToRegistry(r);
  return true;
}

// Adds L everywhere (see above); returns true so that a namespace-scope
// constant can hold the call. A name taken twice ends the program at start
// with std::logic_error naming it.
template <class L>
bool Register(Registration<L> r) {
  scene::AddRegistered(
      scene::MakeRegistered<L>(r.name, r.description, r.parameters));
  return Register(std::move(r), kNotInScenes);
}

}  // namespace vivp
