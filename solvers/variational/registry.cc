#include "solvers/variational/registry.h"

#include "problems/anharmonic.h"
#include "problems/coupled_oscillators.h"
#include "problems/damped_oscillator.h"
#include "problems/exponential.h"
#include "problems/free_fall.h"
#include "problems/kepler.h"
#include "problems/pendulum.h"
#include "solvers/variational/registry_entry.h"

namespace vivp {

const std::vector<NamedProblem>& Registry() {
  static const std::vector<NamedProblem> problems = [] {
    using namespace problems;
    std::vector<NamedProblem> r;
    r.push_back(detail::Entry("freefall", "free fall, L = ½ẋ² − x (eq. 24)",
                              FreeFall{}, {{1.0}, {0.3}},
                              detail::Scalar<FreeFall>));
    r.push_back(detail::Entry(
        "anharmonic", "anharmonic oscillator, L = ½ẋ² − 5x⁴ (eq. 33)",
        Anharmonic{}, {{1.0}, {0.3}}, detail::Scalar<Anharmonic>));
    r.push_back(detail::Entry(
        "exponential", "first order ẋ = 5x/2, L = −5x²/4, Λ = ẋ₊x₋ (eq. 39)",
        Exponential{}, {{1.0}, {}}, [](const Exponential& p, double t) {
          const auto e = p.Exact(t);
          return ExactState{{e.x}, {e.v}, {}};
        }));
    r.push_back(detail::Entry(
        "damped", "damped oscillator μ = 0.5, κ = 1, ξ = 0.00071 (eq. 43)",
        DampedOscillator{}, {{1.0}, {0.0}}, detail::Scalar<DampedOscillator>));
    r.push_back(detail::Entry(
        "coupled", "two coupled oscillators (d = 2, normal modes exact)",
        CoupledOscillators{}, {{1.0, 0.0}, {0.0, 0.3}},
        [](const CoupledOscillators& p, double t) {
          const auto s = p.Exact(t);
          return ExactState{{s.x[0], s.x[1]}, {s.v[0], s.v[1]}, {}};
        }));
    // Canonical systems with L = ½|ẋ|² − V: the momentum is the velocity.
    auto canonical = [](const auto& p, double t) {
      const std::vector<double> y = p.Exact(t);
      const std::size_t d = y.size() / 2;
      return ExactState{
          {y.begin(), y.begin() + d}, {y.begin() + d, y.end()}, {}};
    };
    auto initial = [](const auto& p) {
      const std::vector<double> y = p.Initial();
      const std::size_t d = y.size() / 2;
      return InitialData{{y.begin(), y.begin() + d}, {y.begin() + d, y.end()}};
    };
    r.push_back(detail::Entry("pendulum",
                              "pendulum, L = ½ẋ² + cos x, x(0) = 0, ẋ(0) = 1",
                              Pendulum{}, initial(Pendulum{}), canonical));
    r.push_back(detail::Entry(
        "kepler", "planar Kepler e = 0.6 from pericentre (d = 2, period 2π)",
        Kepler{}, initial(Kepler{}), canonical));
    return r;
  }();
  return problems;
}

std::string ProblemNameList() {
  std::string out;
  for (const auto& p : Registry()) out += (out.empty() ? "" : ", ") + p.name;
  return out;
}

const NamedProblem& FindProblem(const std::string& name) {
  for (const auto& p : Registry())
    if (p.name == name) return p;
  throw std::invalid_argument("unknown problem '" + name +
                              "'; valid problems: " + ProblemNameList());
}

ConvergenceRow MarchRow(const NamedProblem& problem, const Grid& grid,
                        const SolveOptions& options, long long slab_points,
                        const ExactState& exact) {
  MarchOptions mo;
  mo.window_points = slab_points;
  mo.solve = options;
  // A convergence study measures the grids it names: an under-resolved one
  // is reported, not silently refined.
  mo.stabilize = false;
  const MarchResult m = problem.march(grid, mo, {});
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
  r.error_estimate = m.error_estimate;
  r.iterations = m.iterations;
  r.fallbacks = m.fallbacks;
  r.seconds = m.seconds;
  r.converged = m.status.converged;
  r.reason = m.status.reason;
  return r;
}

ConvergenceStudy RunConvergence(const NamedProblem& problem, Grid grid,
                                const std::vector<long long>& points,
                                const SolveOptions& options,
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
    const IvpSolution<double> s = problem.solve(grid, options);
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

}  // namespace vivp
