// The problems of the work–precision comparison by name, each with its end
// time, initial state, reference at t_end and the step count to start the
// sweeps from:
//   harmonic, pendulum, anharmonic, kepler (e = 0.6), kepler_e09,
//   henon_heiles, nldnls (32 sites, A = 0.5), damped (Rothkopf & Nordström
//   2023, eq. 43).
// References are exact where a closed form exists (harmonic, pendulum,
// anharmonic, Kepler); Hénon–Heiles and the NLDNLS use Gauss–Legendre s = 3
// at a step 4–20× below the finest in the sweeps (stated in `reference`).
// The damped oscillator is not Hamiltonian, so only the variational solver
// covers it. After these, every registered Lagrangian with a Hamiltonian
// form (AddBenchCandidate), in the order of their names.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "studies/work_point.h"

namespace vivp::studies {

struct BenchProblem {
  std::string name, description, reference;
  double t_end = 0;
  long first_steps = 0;  // coarsest step count of the sweeps
  std::vector<std::string> methods;
  std::vector<std::string> invariant_names;
  std::function<WorkPoint(const std::string& method, double knob, int repeats)>
      measure;
};

// Compiled once (bench_problems.cc): the stepper templates for every problem
// and method are instantiated there, not in each program that lists them.
const std::vector<BenchProblem>& BenchProblems();

// Registers the variational solver (time-slab marching with the default
// window) as external methods for the bench problems that are in its
// registry with the same setup (anharmonic, pendulum, kepler, kepler_e09):
// variational_sbp21 … variational_sbp84 under error control (the knob a
// tolerance, absolute = relative, like odeint_dopri5's) and
// variational_sbp21_uniform … on a uniform grid (the knob a step count).
// Called by BenchProblems(); idempotent.
void RegisterVariationalMethods();

// The points per window of the variational methods' marches from now on (0:
// the solver's default, 48 on a uniform grid and 24 under error control):
// the window length is part of a variational configuration, as the step is.
// Throws std::invalid_argument for a negative count.
void SetVariationalWindowPoints(long long points);
// Whether `method` is one of the variational methods (its operator the name
// after "variational_", e.g. sbp84 for variational_sbp84_uniform).
bool IsVariationalMethod(const std::string& method);
std::string VariationalOperator(const std::string& method);

// The damped oscillator of Rothkopf & Nordström 2023 (not Hamiltonian): the
// variational solver's four operators only. Part of BenchProblems().
BenchProblem DampedBenchProblem();

// The built-in Hamiltonian problems, part of BenchProblems() in this order,
// each group in a translation unit of its own (bench_oscillators.cc,
// bench_orbits.cc, bench_nldnls.cc) so that their stepper templates compile
// in parallel (18 s in one unit, 7.5 s at most apart; Clang 14, -O3):
// harmonic, pendulum, anharmonic; kepler, kepler_e09, henon_heiles; nldnls.
std::vector<BenchProblem> OscillatorBenchProblems();
std::vector<BenchProblem> OrbitBenchProblems();
BenchProblem NldnlsBenchProblem();

// A registered Lagrangian (lagrangians/register.h) offered to the bench:
// `make` builds its bench problem, or throws std::domain_error saying why it
// has no Hamiltonian form the steppers can use. Called when BenchProblems()
// is first built; a name the built-in list has is skipped (the built-in
// problem has more: quadratic invariants, further invariants).
void AddBenchCandidate(std::string name, std::function<BenchProblem()> make);

// Throws std::invalid_argument naming the valid problems (and, for a
// registered Lagrangian without a Hamiltonian form, why).
const BenchProblem& FindBenchProblem(const std::string& name);

// The default sweep of one method: step counts doubling from first_steps (or
// tolerances 1e-3 … 1e-13 for adaptive methods) until the error reaches the
// round-off floor or stops falling (accumulated round-off), or a run takes
// longer than `budget_seconds`.
std::vector<WorkPoint> Sweep(const BenchProblem& p, const std::string& method,
                             int repeats, double budget_seconds,
                             double floor = 1e-13);

}  // namespace vivp::studies
