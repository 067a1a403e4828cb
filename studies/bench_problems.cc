// The named problems of the work–precision comparison (bench_problems.h).
#include "studies/bench_problems.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "problems/anharmonic.h"
#include "problems/harmonic_oscillator.h"
#include "problems/henon_heiles.h"
#include "problems/kepler.h"
#include "problems/nldnls.h"
#include "problems/pendulum.h"
#include "problems/phase_space.h"
#include "studies/bench_problem_of.h"
#include "studies/work_precision.h"

namespace vivp::studies {

namespace {

// The anharmonic oscillator of problems/anharmonic.h with what the steppers
// need besides H: initial state, quadratic invariants ŷ = (p², q²) with
// Ĥ = ½ŷ₀ + ¼κŷ₁², and no further invariants.
struct AnharmonicHamiltonian : problems::Anharmonic {
  static constexpr bool kSeparable = true;
  static constexpr int kInvariantCount = 2;
  template <class T>
  void QuadraticInvariants(const T* q, const T* p, T* y) const {
    y[0] = p[0] * p[0];
    y[1] = q[0] * q[0];
  }
  template <class T>
  T HamiltonianOfInvariants(const T* y) const {
    return T(0.5) * y[0] + T(0.25 * kappa) * y[1] * y[1];
  }
  std::vector<double> Initial() const { return {x0, v0}; }
  std::vector<double> ExactState(double t) const {
    const auto s = Exact(t);
    return {s.x, s.v};
  }
};

}  // namespace

namespace {

// Function-local, so that registrations in any translation unit find them
// constructed whatever the order of static initialization; a map keeps the
// candidates in the order of their names.
std::map<std::string, std::function<BenchProblem()>>& Candidates() {
  static std::map<std::string, std::function<BenchProblem()>> candidates;
  return candidates;
}
std::map<std::string, std::string>& Unavailable() {
  static std::map<std::string, std::string> reasons;
  return reasons;
}

}  // namespace

namespace detail {

// Gauss–Legendre s = 3 with n steps: the reference for problems without a
// closed form.
template <class Problem>
std::vector<double> GaussReference(const Problem& problem, double t_end,
                                   long n) {
  using System = steppers::HamiltonianSystem<Problem>;
  const System system(problem);
  steppers::RungeKutta<Problem> stepper(system, steppers::Gauss3());
  const auto init = problems::InitialState(problem);
  typename System::Vector y = System::Vector::Map(init.data());
  const steppers::RunReport r = Integrate(stepper, y, t_end / n, n);
  if (r.status != steppers::Status::kOk)
    throw std::runtime_error("reference run failed: " + ToString(r.status));
  return std::vector<double>(y.data(), y.data() + y.size());
}

}  // namespace detail

const std::vector<BenchProblem>& BenchProblems() {
  static const std::vector<BenchProblem> problems = [] {
    RegisterVariationalMethods();
    using detail::MakeBenchProblem;
    std::vector<BenchProblem> r;
    const double orbit = 2 * M_PI;
    r.push_back(MakeBenchProblem(
        "harmonic", "harmonic oscillator H = ½p² + ½q², 10 periods",
        problems::HarmonicOscillator{}, 10 * orbit, 64, "exact",
        [=] { return problems::HarmonicOscillator{}.Exact(10 * orbit); }));
    r.push_back(MakeBenchProblem(
        "pendulum",
        "pendulum H = ½p² − cos q, q(0)=0, p(0)=1, 10 periods of 2π",
        problems::Pendulum{}, 10 * orbit, 64, "exact (Jacobi sn, cn)",
        [=] { return problems::Pendulum{}.Exact(10 * orbit); }));
    r.push_back(MakeBenchProblem(
        "anharmonic",
        "anharmonic oscillator H = ½p² + 5q⁴ (Rothkopf & Nordström 2023), "
        "t = 10",
        AnharmonicHamiltonian{}, 10.0, 64, "exact (Jacobi cn)",
        [] { return AnharmonicHamiltonian{}.ExactState(10.0); }));
    r.push_back(MakeBenchProblem(
        "kepler", "Kepler e = 0.6, 10 orbits", problems::Kepler{}, 10 * orbit,
        1000, "exact (Kepler's equation)",
        [=] { return problems::Kepler{}.Exact(10 * orbit); }));
    problems::Kepler hard;
    hard.e = 0.9;
    r.push_back(MakeBenchProblem("kepler_e09", "Kepler e = 0.9, 3 orbits", hard,
                                 3 * orbit, 1000, "exact (Kepler's equation)",
                                 [=] { return hard.Exact(3 * orbit); }));
    r.push_back(MakeBenchProblem(
        "henon_heiles", "Hénon–Heiles, q = p = (0.18, 0.18), t = 100",
        problems::HenonHeiles{}, 100.0, 100, "Gauss–Legendre s = 3, h = 0.005",
        [] {
          return detail::GaussReference(problems::HenonHeiles{}, 100.0, 20000);
        }));
    r.push_back(MakeBenchProblem(
        "nldnls",
        "NLDNLS eq. (6), 32 periodic sites, κ = 1, 2A sech(A n), A = 0.5, t = "
        "10",
        problems::Nldnls{}, 10.0, 50, "Gauss–Legendre s = 3, h = 0.001", [] {
          return detail::GaussReference(problems::Nldnls{}, 10.0, 10000);
        }));
    r.push_back(DampedBenchProblem());
    for (const auto& candidate : Candidates()) {
      const std::string& name = candidate.first;
      if (std::any_of(r.begin(), r.end(),
                      [&](const BenchProblem& b) { return b.name == name; }))
        continue;
      try {
        r.push_back(candidate.second());
      } catch (const std::domain_error& e) {
        Unavailable()[name] = e.what();
      }
    }
    return r;
  }();
  return problems;
}

void AddBenchCandidate(std::string name, std::function<BenchProblem()> make) {
  Candidates()[std::move(name)] = std::move(make);
}

const BenchProblem& FindBenchProblem(const std::string& name) {
  std::string valid;
  for (const auto& p : BenchProblems()) {
    if (p.name == name) return p;
    valid += valid.empty() ? "" : ", ";
    valid += p.name;
  }
  const auto why = Unavailable().find(name);
  if (why != Unavailable().end())
    throw std::invalid_argument("'" + name +
                                "' has no Hamiltonian form for the steppers: " +
                                why->second + "; valid: " + valid);
  throw std::invalid_argument("unknown problem '" + name +
                              "'; valid: " + valid);
}

std::vector<WorkPoint> Sweep(const BenchProblem& p, const std::string& method,
                             int repeats, double budget_seconds, double floor) {
  std::vector<WorkPoint> rows;
  if (IsAdaptive(method)) {
    for (double tol = 1e-3; tol >= 1e-13; tol /= 10) {
      rows.push_back(p.measure(method, tol, repeats));
      if (rows.back().seconds > budget_seconds) break;
    }
    return rows;
  }
  double previous = INFINITY;
  for (long n = p.first_steps; n <= (1L << 24); n *= 2) {
    rows.push_back(p.measure(method, static_cast<double>(n), repeats));
    const WorkPoint& w = rows.back();
    // An unstable coarse step is a result, and finer steps may be stable.
    const bool ok = w.status == "ok";
    // Stagnation is judged only near round-off (below 1e-9); above that a
    // slow fall is the pre-asymptotic regime, not a floor.
    const bool stagnated = w.error < 1e-9 && w.error > 0.5 * previous;
    if ((ok && !(w.error > floor)) || (ok && stagnated) ||
        w.seconds > budget_seconds)
      break;
    if (ok) previous = w.error;
  }
  return rows;
}

}  // namespace vivp::studies
