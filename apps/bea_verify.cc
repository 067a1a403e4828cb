// `vivp bea verify`: runs the method over a sweep of step sizes and measures
// how well it conserves the modified Hamiltonian and charge (McLachlan &
// Offen 2023).
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/bea_command.h"
#include "apps/command.h"
#include "solvers/bea/conservation.h"
#include "solvers/bea/multistep.h"

namespace vivp::apps {
namespace {

// The stability of a method that verify can run: numeric coefficients and
// stable, else the user's error.
bea::Stability CheckVerifiable(const bea::Method& method) {
  const auto coefficients = [&] {
    try {
      return bea::NumericCoefficients(method);
    } catch (const std::invalid_argument&) {
      throw UsageError(
          "verify needs numeric coefficients: give --alpha or "
          "--matrix as numbers");
    }
  }();
  // derive only warns (the modified equation of an unstable method is still
  // a formula); verify would integrate it and measure nothing but the
  // blow-up of the parasitic root, ending in overflow.
  const auto stability = bea::CheckStability(coefficients);
  if (!stability.stable)
    throw UsageError(
        "verify cannot measure conservation with an unstable "
        "method: " +
        stability.reason);
  return stability;
}

// The initial state (--x0, --v0, defaults by dimension), the end time and
// the order of the differences of the runs.
bea::ConservationSetup VerifySetup(const BeaOptions& o) {
  bea::ConservationSetup s;
  std::vector<double> x0 =
      o.x0.empty() ? std::vector<double>{} : ParseNumberList(o.x0, "--x0");
  std::vector<double> v0 =
      o.v0.empty() ? std::vector<double>{} : ParseNumberList(o.v0, "--v0");
  if (x0.empty())
    x0 = o.dim == 2 ? std::vector<double>{1, -1}
                    : std::vector<double>(o.dim, 1.0);
  if (v0.empty())
    v0 = o.dim == 2 ? std::vector<double>{0.1, -0.2}
                    : std::vector<double>(o.dim, 0.0);
  if (static_cast<int>(x0.size()) != o.dim ||
      static_cast<int>(v0.size()) != o.dim)
    throw UsageError("--x0 and --v0 need " + std::to_string(o.dim) +
                     " numbers");
  s.x0 = Eigen::Map<Eigen::VectorXd>(x0.data(), o.dim);
  s.v0 = Eigen::Map<Eigen::VectorXd>(v0.data(), o.dim);
  s.t_end = o.t_end;
  s.difference_order = o.differences;
  if (!(o.t_end > 0))
    throw UsageError("--t-end: the end time must be positive, got " +
                     std::to_string(o.t_end));
  return s;
}

// The step sizes of --steps.
std::vector<double> VerifySteps(const BeaOptions& o) {
  const auto steps = ParseNumberList(o.steps, "--steps");
  for (double h : steps)
    if (!(h > 0) || o.t_end / h > 1e7 || o.t_end / h < 20) {
      // Between 20 steps (a slope needs a trajectory) and 1e7 (time).
      std::ostringstream m;
      m << "--steps: each h must lie in [t_end/1e7, t_end/20] = ["
        << o.t_end / 1e7 << ", " << o.t_end / 20 << "] for --t-end " << o.t_end
        << ", got h = " << h;
      throw UsageError(m.str());
    }
  return steps;
}

// The table: the largest deviation of each quantity per step size, and the
// fitted slopes.
void PrintSweep(std::ostream& human, const bea::Method& method,
                const BeaOptions& o, const bea::Sweep& sweep) {
  human << "# " << method.name << ", " << o.potential << ", d = " << o.dim
        << ", T = " << o.t_end << ", " << o.differences
        << "th-order differences; max |deviation|\n"
        << std::setw(8) << "h";
  for (const auto& n : sweep.names) human << std::setw(12) << n;
  human << "\n" << std::setprecision(3);
  for (const auto& row : sweep.rows) {
    human << std::setw(8) << row.h;
    for (double v : row.max_deviation) human << std::setw(12) << v;
    human << "\n";
  }
  if (!sweep.slopes.empty()) {
    human << std::setw(8) << "slope";
    for (double v : sweep.slopes) human << std::setw(12) << v;
    human << "\n";
  }
}

nlohmann::json SweepJson(const bea::Method& method, const BeaOptions& o,
                         bool stable, const bea::Sweep& sweep) {
  nlohmann::json j = {{"method", method.name},
                      {"potential", o.potential},
                      {"dim", o.dim},
                      {"t_end", o.t_end},
                      {"difference_order", o.differences},
                      {"stable", stable}};
  for (const auto& row : sweep.rows) {
    nlohmann::json jr = {{"h", row.h}, {"steps", row.steps}};
    for (std::size_t c = 0; c < sweep.names.size(); ++c)
      jr[sweep.names[c]] = JsonNumber(row.max_deviation[c]);
    j["rows"].push_back(jr);
  }
  j["slopes"] = nlohmann::json::object();
  for (std::size_t c = 0; c < sweep.slopes.size(); ++c)
    j["slopes"][sweep.names[c]] = JsonNumber(sweep.slopes[c]);
  return j;
}

}  // namespace

int RunBeaVerify(BeaOptions o) {
  if (!o.json.empty() && o.json != "-") CheckOutputFile(o.json, o.force);
  if (o.method == "midpoint")
    throw UsageError("verify runs multistep methods: --method sv or lmm4");
  GiNaC::symtab symbols;
  const bea::Method method = MakeBeaMethod(o, symbols);
  const bea::Stability stability = CheckVerifiable(method);
  if (o.potential.empty()) o.potential = o.dim == 1 ? "pendulum" : "gaussian";
  const bool radial =
      o.dim == 2 && o.matrix.empty() && o.potential == "gaussian";
  const auto r = bea::Derive(method, BeaDeriveOptions(o, radial));
  // The pendulum is one-dimensional (bea::MakePotential refuses others).
  if (o.potential == "pendulum" && o.dim != 1)
    throw UsageError("the pendulum potential needs --dim 1");
  const auto potential = bea::MakePotential(o.potential, o.dim, r.jet->model());
  const bea::ModifiedQuantities q(r, *potential);
  const bea::ConservationSetup s = VerifySetup(o);
  const auto steps = VerifySteps(o);
  const auto sweep = bea::ConservationSweep(r, q, *potential, s, steps);

  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  PrintSweep(human, method, o, sweep);
  if (!o.json.empty())
    WriteJson(o.json, SweepJson(method, o, stability.stable, sweep));
  return 0;
}

}  // namespace vivp::apps
