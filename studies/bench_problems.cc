// The named problems of the work–precision comparison (bench_problems.h):
// the list, the registered candidates and the sweep. The stepper templates
// for the built-in problems are compiled in bench_oscillators.cc,
// bench_orbits.cc and bench_nldnls.cc, apart so that they compile in
// parallel.
#include "studies/bench_problems.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace vivp::studies {

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

const std::vector<BenchProblem>& BenchProblems() {
  static const std::vector<BenchProblem> problems = [] {
    RegisterVariationalMethods();
    std::vector<BenchProblem> r = OscillatorBenchProblems();
    for (auto& b : OrbitBenchProblems()) r.push_back(std::move(b));
    r.push_back(NldnlsBenchProblem());
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
    // 10⁻³ … 10⁻¹³ as the decimal literals read (tol /= 10 drifts by an ulp
    // from 10⁻⁶ on, and an adaptive march's end error below 10⁻⁹ moves with
    // the last bit of its tolerance: Kepler e = 0.9, SBP84, 9.8e-11 at
    // 1e-7 and 3.3e-12 at 1e-7 + 1 ulp, the same 5520 nodes), so that a
    // sweep's row and `--steps 1e-7` are the same march.
    for (int k = 3; k <= 13; ++k) {
      const double tol = std::stod("1e-" + std::to_string(k));
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
