// The one-degree-of-freedom problems of the work–precision comparison
// (bench_problems.h): harmonic, pendulum, anharmonic.
#include <cmath>
#include <vector>

#include "problems/anharmonic.h"
#include "problems/harmonic_oscillator.h"
#include "problems/pendulum.h"
#include "studies/bench_problem_of.h"
#include "studies/bench_problems.h"

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

std::vector<BenchProblem> OscillatorBenchProblems() {
  using detail::MakeBenchProblem;
  std::vector<BenchProblem> r;
  const double orbit = 2 * M_PI;
  r.push_back(MakeBenchProblem(
      "harmonic", "harmonic oscillator H = ½p² + ½q², 10 periods",
      problems::HarmonicOscillator{}, 10 * orbit, 64, "exact",
      [=] { return problems::HarmonicOscillator{}.Exact(10 * orbit); }));
  r.push_back(MakeBenchProblem(
      "pendulum", "pendulum H = ½p² − cos q, q(0)=0, p(0)=1, 10 periods of 2π",
      problems::Pendulum{}, 10 * orbit, 64, "exact (Jacobi sn, cn)",
      [=] { return problems::Pendulum{}.Exact(10 * orbit); }));
  r.push_back(MakeBenchProblem(
      "anharmonic",
      "anharmonic oscillator H = ½p² + 5q⁴ (Rothkopf & Nordström 2023), "
      "t = 10",
      AnharmonicHamiltonian{}, 10.0, 64, "exact (Jacobi cn)",
      [] { return AnharmonicHamiltonian{}.ExactState(10.0); }));
  return r;
}

}  // namespace vivp::studies
