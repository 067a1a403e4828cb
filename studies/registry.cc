#include "studies/registry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vivp::studies {

namespace {

// Function-local, so that registrations in any translation unit find it
// constructed whatever the order of static initialization.
std::vector<NamedProblem>& Problems() {
  static std::vector<NamedProblem> problems;
  return problems;
}

}  // namespace

void AddProblem(NamedProblem problem) {
  auto& all = Problems();
  const auto at = std::lower_bound(
      all.begin(), all.end(), problem.name,
      [](const NamedProblem& p, const std::string& n) { return p.name < n; });
  if (at != all.end() && at->name == problem.name)
    throw std::logic_error("two problems registered as '" + problem.name + "'");
  all.insert(at, std::move(problem));
}

const std::vector<NamedProblem>& Registry() { return Problems(); }

std::string ProblemNameList() {
  std::string out;
  for (const auto& p : Registry()) out += (out.empty() ? "" : ", ") + p.name;
  return out;
}

bool HasProblem(const std::string& name) {
  for (const auto& p : Registry())
    if (p.name == name) return true;
  return false;
}

const NamedProblem& FindProblem(const std::string& name) {
  for (const auto& p : Registry())
    if (p.name == name) return p;
  throw std::invalid_argument("unknown problem '" + name +
                              "'; valid problems: " + ProblemNameList());
}

namespace {

// One row of a study: a failure inside the solver (not a bad argument, which
// is the caller's to report before any work) becomes that row's reason
// instead of ending the whole study.
template <class F, class OnFailure>
auto Guarded(F&& run, OnFailure&& on_failure) -> decltype(run()) {
  try {
    return run();
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    decltype(run()) failed{};
    on_failure(failed, std::string("failed: ") + e.what());
    return failed;
  }
}

// The counts and status of a march, into its row.
void FromMarch(const variational::MarchResult& m, ConvergenceRow& r) {
  r.error_estimate = m.error_estimate;
  r.iterations = m.iterations;
  r.fallbacks = m.fallbacks;
  r.windows = m.window_count;
  r.rejected = m.rejected;
  r.seconds = m.seconds;
  r.converged = m.status.converged;
  r.reason = m.status.reason;
}

}  // namespace

ConvergenceRow MarchRow(const NamedProblem& problem,
                        const variational::Grid& grid,
                        const variational::SolveOptions& options,
                        long long slab_points, const ExactState& exact) {
  variational::MarchOptions mo;
  mo.window_points = slab_points;
  mo.solve = options;
  // A convergence study measures the grids it names: an under-resolved one
  // is reported, not silently refined.
  mo.stabilize = false;
  const variational::MarchResult m =
      Guarded([&] { return problem.march(grid, mo, {}); },
              [](variational::MarchResult& f, const std::string& why) {
                f.status = {false, why};
              });
  ConvergenceRow r;
  r.points = grid.points;
  const std::size_t last = m.t.size() - 1;
  auto maxdiff = [](auto&& a, const std::vector<double>& b) {
    double v = 0;
    for (std::size_t c = 0; c < b.size(); ++c)
      v = std::max(v, std::abs(a(c) - b[c]));
    return v;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!m.t.empty()) {
    r.err_x = maxdiff([&](std::size_t c) { return m.x(last, c); }, exact.x);
    r.err_v =
        exact.v.empty()
            ? nan
            : maxdiff([&](std::size_t c) { return m.v(last, c); }, exact.v);
  }
  r.err_x_corrected =
      maxdiff([&](std::size_t c) { return m.end_position[c]; }, exact.x);
  // For L = ½ẋᵀMẋ − V the handed-off velocity is M⁻¹p; compare velocities.
  r.err_p_corrected =
      m.end_velocity.empty() || exact.v.empty()
          ? nan
          : maxdiff([&](std::size_t c) { return m.end_velocity[c]; }, exact.v);
  FromMarch(m, r);
  return r;
}

ConvergenceStudy RunToleranceStudy(const NamedProblem& problem,
                                   variational::Grid grid,
                                   const std::vector<double>& tolerances,
                                   const variational::SolveOptions& options,
                                   long long window_points,
                                   double round_off_floor) {
  ConvergenceStudy study;
  const double span = grid.t_end - grid.t_start;
  const ExactState exact = problem.exact(grid.t_end);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double tol : tolerances) {
    variational::MarchOptions mo;
    mo.window_points = window_points;
    mo.solve = options;
    mo.tolerance = {tol, tol};
    mo.keep_trajectory = false;
    double max_error = 0, max_error_v = 0;
    const variational::MarchResult m = Guarded(
        [&] {
          return problem.march(
              grid, mo, [&](double t, const double* x, const double* v) {
                const ExactState e = problem.exact(t);
                for (std::size_t c = 0; c < e.x.size(); ++c)
                  max_error = std::max(max_error, std::abs(x[c] - e.x[c]));
                for (std::size_t c = 0; c < e.v.size(); ++c)
                  max_error_v = std::max(max_error_v, std::abs(v[c] - e.v[c]));
              });
        },
        [](variational::MarchResult& f, const std::string& why) {
          f.status = {false, why};
        });
    ConvergenceRow r;
    r.tolerance = tol;
    r.points = m.points;
    r.dt = r.dt_true = m.points > 1 ? span / double(m.points - 1) : nan;
    r.err_x = r.err_v = nan;
    auto maxdiff = [](const std::vector<double>& a,
                      const std::vector<double>& b) {
      double v = 0;
      for (std::size_t c = 0; c < b.size() && c < a.size(); ++c)
        v = std::max(v, std::abs(a[c] - b[c]));
      return v;
    };
    r.err_x_corrected = maxdiff(m.end_position, exact.x);
    r.err_p_corrected = m.end_velocity.empty() || exact.v.empty()
                            ? nan
                            : maxdiff(m.end_velocity, exact.v);
    r.max_error = max_error;
    r.max_error_v = exact.v.empty() ? nan : max_error_v;
    FromMarch(m, r);
    study.rows.push_back(r);
  }
  FitTracking(study, round_off_floor);
  return study;
}

ConvergenceStudy RunConvergence(const NamedProblem& problem,
                                variational::Grid grid,
                                const std::vector<long long>& points,
                                const variational::SolveOptions& options,
                                double round_off_floor, long long slab_points) {
  ConvergenceStudy study;
  const double span = grid.t_end - grid.t_start;
  const ExactState exact = problem.exact(grid.t_end);
  for (long long n : points) {
    grid.points = n;
    if (slab_points > 0) {
      ConvergenceRow r = MarchRow(problem, grid, options, slab_points, exact);
      r.dt = span / static_cast<double>(n);
      r.dt_true = span / static_cast<double>(n - 1);
      study.rows.push_back(r);
      continue;
    }
    const variational::IvpSolution<double> s = Guarded(
        [&] { return problem.solve(grid, options); },
        [&](variational::IvpSolution<double>& f, const std::string& why) {
          f.status = {false, why};
          f.x1 = f.velocity = Eigen::MatrixXd::Constant(
              1, long(exact.x.size()),
              std::numeric_limits<double>::quiet_NaN());
          f.t = {grid.t_end};
          f.corrected.position.assign(exact.x.size(),
                                      std::numeric_limits<double>::quiet_NaN());
        });
    ConvergenceRow r;
    r.points = n;
    r.dt = span / static_cast<double>(n);
    r.dt_true = span / static_cast<double>(n - 1);
    const int last = s.points() - 1;
    auto maxdiff = [](auto&& a, const std::vector<double>& b) {
      double m = 0;
      for (std::size_t c = 0; c < b.size(); ++c)
        m = std::max(m, std::abs(a(c) - b[c]));
      return m;
    };
    r.err_x = maxdiff([&](std::size_t c) { return s.x1(last, c); }, exact.x);
    r.err_v = exact.v.empty()
                  ? std::numeric_limits<double>::quiet_NaN()
                  : maxdiff([&](std::size_t c) { return s.velocity(last, c); },
                            exact.v);
    r.err_x_corrected = maxdiff(
        [&](std::size_t c) { return s.corrected.position[c]; }, exact.x);
    r.err_p_corrected =
        s.corrected.momentum.empty() || exact.p.empty()
            ? std::numeric_limits<double>::quiet_NaN()
            : maxdiff([&](std::size_t c) { return s.corrected.momentum[c]; },
                      exact.p);
    r.error_estimate = s.corrected.position_error_estimate;
    r.iterations = s.iterations;
    r.seconds = s.seconds.total;
    r.converged = s.status.converged;
    r.reason = s.status.reason;
    study.rows.push_back(r);
  }
  FitOrders(study, round_off_floor);
  return study;
}

}  // namespace vivp::studies
