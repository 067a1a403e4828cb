#include "studies/field_work_precision.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "core/sbp/builder.h"
#include "core/sbp/space.h"
#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "solvers/spacetime/method_of_lines.h"
#include "solvers/spacetime/solve.h"
#include "solvers/variational/resolution.h"

namespace vivp::studies {

namespace {

using Space = sbp::SpaceDerivative<double>;

// The largest |φ − u| over the grid at the kept slices t_end·k/8.
template <class Solution>
double SampledError(const Solution& s, const Space& dx, double t_end,
                    double omega) {
  const fields::SineGordonBreather u{omega};
  double e = 0;
  const int n = dx.points();
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    const double slot = s.t[k] / t_end * 8;
    if (std::abs(slot - std::round(slot)) > 1e-9 || s.t[k] == 0) continue;
    for (int j = 0; j < n; ++j)
      e = std::max(e, std::abs(s.phi[k * n + j] - u(s.t[k], dx.x(j))));
  }
  return e;
}

struct Problem {
  Space dx;
  std::vector<double> phi0, pi0;
  double omega_max = 0;
};

Problem MakeProblem(const FieldWorkOptions& o, int nx) {
  Problem p{
      Space::Periodic(8, nx, -o.half_length, 2 * o.half_length), {}, {}, 0};
  std::tie(p.phi0, p.pi0) =
      fields::InitialData(fields::SineGordonBreather{o.omega}, p.dx);
  p.omega_max = spacetime::FastestFieldFrequency(
      fields::SineGordon{}, p.dx, spacetime::SpectralRadius(p.dx), p.phi0,
      p.pi0);
  return p;
}

long long RoundUp8(double n) {
  return 8 * static_cast<long long>(std::ceil(n / 8 - 1e-9));
}

using Knob = std::function<FieldWorkRun(long long steps)>;

// Raises the step count until the target is met (see the header).
FieldWorkBest SearchSteps(const Knob& run, long long n, double target,
                          double budget, std::vector<FieldWorkRun>& runs,
                          void (*progress)(const std::string&)) {
  FieldWorkBest best;
  auto record = [&](long long steps) -> const FieldWorkRun& {
    runs.push_back(run(steps));
    const FieldWorkRun& r = runs.back();
    if (progress) {
      std::ostringstream line;
      line << r.family << " " << r.config << " Nx " << r.space_points
           << " steps " << r.steps << ": error " << r.error << ", " << r.seconds
           << " s" << (r.converged ? "" : " — " + r.message);
      progress(line.str());
    }
    return r;
  };
  const FieldWorkRun* prev = nullptr;
  FieldWorkRun last;
  for (int attempt = 0; attempt < 14; ++attempt) {
    const FieldWorkRun& r = record(n);
    long long next = 2 * n;
    if (r.converged && r.error <= target) {
      best.found = true;
      best.run = r;
      // One step back towards the failing count, to where the observed
      // order says the target is just met.
      if (prev && prev->converged) {
        const double p = std::log(prev->error / r.error) /
                         std::log(double(r.steps) / double(prev->steps));
        const long long fit =
            RoundUp8(1.02 * double(n) * std::pow(r.error / target, 1 / p));
        if (p > 0.5 && double(fit) < 0.9 * double(n) && fit > prev->steps) {
          const FieldWorkRun& closer = record(fit);
          if (closer.converged && closer.error <= target) best.run = closer;
        }
      }
      return best;
    }
    if (r.converged && prev && prev->converged) {
      const double p = std::log(prev->error / r.error) /
                       std::log(double(r.steps) / double(prev->steps));
      if (!(p > 0.5)) {
        std::ostringstream why;
        why << "error stops falling at " << r.error << " (observed order " << p
            << ")";
        best.why = why.str();
        return best;
      }
      const double want = double(n) * std::pow(r.error / target, 1 / p) * 1.05;
      next = std::clamp<long long>(RoundUp8(want), RoundUp8(1.2 * double(n)),
                                   4 * n);
    }
    const double predicted = r.seconds * double(next) / double(n);
    if (r.converged && predicted > budget) {
      std::ostringstream why;
      why << "needs about " << next << " steps, predicted " << predicted
          << " s > budget " << budget << " s (error " << r.error << " at " << n
          << ")";
      best.why = why.str();
      return best;
    }
    last = r;
    prev = &last;
    n = next;
  }
  best.why = "no step count met the target";
  return best;
}

}  // namespace

const std::vector<std::string>& FieldWorkFamilies() {
  static const std::vector<std::string> f{"variational", "leapfrog", "gauss4",
                                          "gauss6", "dopri5"};
  return f;
}

FieldWorkReport BreatherWorkPrecision(const FieldWorkOptions& o,
                                      void (*progress)(const std::string&)) {
  FieldWorkReport report;
  report.options = o;
  const fields::SineGordon density;
  std::map<int, double> floors;
  std::map<int, Problem> problems;
  auto problem = [&](int nx) -> const Problem& {
    if (!problems.count(nx)) problems.emplace(nx, MakeProblem(o, nx));
    return problems.at(nx);
  };
  // The semi-discrete flow: gauss6 at h·ω_max = ¼, far below any target.
  auto floor_of = [&](int nx) {
    if (floors.count(nx)) return floors[nx];
    const auto& p = problem(nx);
    spacetime::MolOptions m{.method = "gauss6",
                            .steps = RoundUp8(o.t_end * p.omega_max * 4)};
    m.output_every = m.steps / 8;
    const auto s =
        spacetime::SolveFieldMol(density, p.dx, o.t_end, p.phi0, p.pi0, m);
    return floors[nx] = s.status.converged
                            ? SampledError(s, p.dx, o.t_end, o.omega)
                            : INFINITY;
  };
  auto mol = [&](const Problem& p, const std::string& method, long long steps,
                 double tol) {
    spacetime::MolOptions m{.method = method,
                            .steps = steps,
                            .tolerance = tol,
                            .output_every = steps / 8};
    const auto s =
        spacetime::SolveFieldMol(density, p.dx, o.t_end, p.phi0, p.pi0, m);
    FieldWorkRun r{method,
                   method == "dopri5" ? "tolerance" : "fixed step",
                   p.dx.points(),
                   s.steps,
                   tol,
                   0,
                   s.seconds,
                   s.status.converged,
                   s.status.reason};
    r.error =
        s.status.converged ? SampledError(s, p.dx, o.t_end, o.omega) : INFINITY;
    return r;
  };
  struct Variational {
    std::string op;
    long long window;
  };
  // Every time operator, in windows of its minimum but at least 8 points.
  std::vector<Variational> variational;
  for (const sbp::Coefficients* c : sbp::Operators())
    variational.push_back(
        {std::string(c->name), std::max<long long>(8, c->min_points)});
  auto var = [&](const Problem& p, const Variational& v, long long steps) {
    spacetime::FieldGrid g{.op = v.op,
                           .points = steps + 1,
                           .t_end = o.t_end,
                           .window_points = v.window};
    const auto s = spacetime::SolveField(density, p.dx, g, p.phi0, p.pi0);
    FieldWorkRun r{"variational",
                   v.op + ", windows of " + std::to_string(v.window),
                   p.dx.points(),
                   steps,
                   0,
                   0,
                   s.seconds_total,
                   s.status.converged,
                   s.status.reason};
    r.error =
        s.status.converged ? SampledError(s, p.dx, o.t_end, o.omega) : INFINITY;
    return r;
  };
  // Re-times a found run as the median of o.repeats runs when it is short.
  auto retime = [&](FieldWorkRun& r, const std::function<FieldWorkRun()>& f) {
    if (r.seconds > 5 || o.repeats < 2) return;
    std::vector<double> t{r.seconds};
    for (int k = 1; k < o.repeats; ++k) t.push_back(f().seconds);
    std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
    r.seconds = t[t.size() / 2];
  };
  for (const double target : o.targets) {
    int nx = o.space_points.back();
    for (const int n : o.space_points)
      if (floor_of(n) <= target / 4) {
        nx = n;
        break;
      }
    const auto& p = problem(nx);
    // The first step counts: each time operator's resolution limit
    // (docs/fields.md §5), h·ω_max = 1.5 for the Gauss stage iteration and
    // 2 for leapfrog's stability.
    auto start = [&](double limit) {
      return std::max<long long>(16, RoundUp8(o.t_end * p.omega_max / limit));
    };
    for (const auto& family : FieldWorkFamilies()) {
      FieldWorkBest best;
      if (family == "variational") {
        for (const auto& v : variational) {
          auto b = SearchSteps([&](long long n) { return var(p, v, n); },
                               start(variational::StabilityLimit(v.op)), target,
                               o.budget_seconds, report.runs, progress);
          if (b.found) retime(b.run, [&] { return var(p, v, b.run.steps); });
          if (b.found && (!best.found || b.run.seconds < best.run.seconds))
            best = b;
          else if (!best.found && best.why.empty())
            best.why = v.op + ": " + b.why;
        }
      } else if (family == "dopri5") {
        double tol = target;
        for (int k = 0; k < 12 && !best.found; ++k) {
          report.runs.push_back(mol(p, family, 8, tol));
          const auto r = report.runs.back();
          if (progress)
            progress("dopri5 tolerance " + std::to_string(tol) + ": error " +
                     std::to_string(r.error));
          if (r.converged && r.error <= target) {
            best.found = true;
            best.run = r;
            retime(best.run, [&] { return mol(p, family, 8, tol); });
          }
          tol *= std::clamp(0.7 * target / r.error, 1e-2, 0.5);
        }
        if (!best.found) best.why = "no tolerance met the target";
      } else {
        best = SearchSteps([&](long long n) { return mol(p, family, n, 0); },
                           start(family == "leapfrog" ? 1.99 : 1.5), target,
                           o.budget_seconds, report.runs, progress);
        if (best.found)
          retime(best.run, [&] { return mol(p, family, best.run.steps, 0); });
      }
      best.family = family;
      best.target = target;
      best.space_points = nx;
      best.floor = floor_of(nx);
      report.cheapest.push_back(best);
    }
    // A window's cost per time step against one Gauss4 step at the same Δt
    // on the same grid: Gauss4 run with the variational step count.
    const FieldWorkBest& v =
        report.cheapest[report.cheapest.size() - FieldWorkFamilies().size()];
    if (v.found) {
      FieldStepCost c{target, nx, v.run.config, v.run.steps,
                      v.run.seconds / double(v.run.steps)};
      FieldWorkRun g = mol(p, "gauss4", v.run.steps, 0);
      retime(g, [&] { return mol(p, "gauss4", v.run.steps, 0); });
      c.gauss4_seconds_per_step = g.seconds / double(g.steps);
      c.gauss4_converged = g.converged;
      report.step_costs.push_back(c);
    }
  }
  return report;
}

}  // namespace vivp::studies
