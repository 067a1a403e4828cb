#include "studies/field_problems.h"

#include <ceres/jet.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "problems/fields/exact.h"
#include "problems/fields/profiles.h"
#include "solvers/spacetime/composed.h"

namespace vivp::studies {

namespace {

namespace ft = fields::terms;

// φ and φ_t of an exact solution of exact.h, φ_t by a Jet in t.
template <class U>
auto ExactOf(U u) {
  return [u](double t, double x, double* phi, double* phi_t) {
    using J = ceres::Jet<double, 1>;
    const J v = u(J(t, 0), J(x));
    phi[0] = v.a;
    phi_t[0] = v.v[0];
  };
}

std::vector<FieldProblem> MakeFieldProblems() {
  const double two_pi = 2 * std::numbers::pi;
  const std::vector<fields::FieldTerm> sine_gordon = {
      ft::Kinetic{}, ft::Gradient{}, ft::SineGordon{}};
  fields::MovingGaussian pulse{.width = 1.0};
  pulse.images = fields::MovingGaussian::Images::kPeriodic;
  pulse.x0 = -10;
  pulse.length = 20;
  return {
      {"klein_gordon",
       "Klein–Gordon plane wave cos(x − √2 t), m = k = 1 on [0, 2π), periodic",
       {ft::Kinetic{}, ft::Gradient{}, ft::Mass{}},
       true,
       0.0,
       two_pi,
       64,
       8,
       1.0,
       ExactOf(fields::KleinGordonPlaneWave{})},
      {"sine_gordon_breather",
       "sine-Gordon breather ω = 0.5 on [−20, 20), periodic", sine_gordon, true,
       -20.0, 20.0, 200, 8, 1.0, ExactOf(fields::SineGordonBreather{0.5})},
      {"sine_gordon_kink",
       "sine-Gordon kink moving at v = 0.5 on [−20, 20], natural boundaries",
       sine_gordon, false, -20.0, 20.0, 301, 6, 1.0,
       ExactOf(fields::SineGordonKink{0.5, 0.0})},
      {"wave_gaussian",
       "wave equation c = 1, Gaussian σ = 1 at rest on [−10, 10), periodic",
       {ft::Kinetic{}, ft::Gradient{}},
       true,
       -10.0,
       10.0,
       256,
       8,
       1.0,
       [pulse](double t, double x, double* phi, double* phi_t) {
         std::tie(phi[0], phi_t[0]) = pulse(t, x);
       }},
  };
}

template <class T>
std::string List(const std::vector<T>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
  return s;
}

// Solves the problem on dx and grid into row r: its status, counts and
// the errors at t = T, max over x. A bad argument throws; any other failure
// is the row's reason. Returns the solution.
spacetime::FieldSolution SolveRow(const FieldProblem& p,
                                  const sbp::SpaceDerivative<double>& dx,
                                  const spacetime::FieldGrid& grid,
                                  const spacetime::FieldSolveOptions& options,
                                  FieldConvergenceRow& r) {
  std::vector<double> phi(dx.points()), pi(dx.points());
  for (int j = 0; j < dx.points(); ++j) p.exact(0.0, dx.x(j), &phi[j], &pi[j]);
  const fields::ComposedDensity<1> density{p.terms};
  r.space_points = dx.points();
  r.dx = dx.dx();
  spacetime::FieldSolution s;
  try {
    s = spacetime::SolveField(density, dx, grid, phi, pi, options);
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    s.status.reason = std::string("failed: ") + e.what();
  }
  r.converged = s.status.converged;
  r.reason = s.status.reason;
  r.iterations = int(s.factorizations);
  r.windows = s.windows;
  r.seconds = s.seconds_total;
  if (!s.status.converged) return s;
  const std::size_t last = s.t.size() - 1, n = std::size_t(dx.points());
  r.err_x = r.err_v = r.err_x_corrected = r.err_p_corrected = 0;
  for (int j = 0; j < dx.points(); ++j) {
    double u = 0, u_t = 0;
    p.exact(grid.t_end, dx.x(j), &u, &u_t);
    r.err_x = std::max(r.err_x, std::abs(s.end_phi_node[j] - u));
    r.err_v = std::max(r.err_v, std::abs(s.phi_t[last * n + j] - u_t));
    r.err_x_corrected = std::max(r.err_x_corrected, std::abs(s.end.phi[j] - u));
    r.err_p_corrected =
        std::max(r.err_p_corrected, std::abs(s.end.phi_t[j] - u_t));
  }
  r.error_estimate = s.end.phi_estimate;
  return s;
}

// One solve and its errors at t = T, max over x.
FieldConvergenceRow Row(const FieldProblem& p, const FieldStudyOptions& o,
                        long long nt, long long nx) {
  const auto dx = FieldSpace(p, o.space_order, nx);
  const spacetime::FieldGrid grid{.op = o.op,
                                  .points = nt,
                                  .t_end = o.t_end,
                                  .window_points = o.window_points};
  FieldConvergenceRow r;
  r.points = nt;
  r.dt = o.t_end / double(nt);
  r.dt_true = o.t_end / double(nt - 1);
  SolveRow(p, dx, grid, {}, r);
  return r;
}

}  // namespace

const std::vector<FieldProblem>& FieldProblems() {
  static const std::vector<FieldProblem> problems = MakeFieldProblems();
  return problems;
}

std::string FieldProblemNameList() {
  std::string out;
  for (const auto& p : FieldProblems())
    out += (out.empty() ? "" : ", ") + p.name;
  return out;
}

const FieldProblem& FindFieldProblem(const std::string& name) {
  for (const auto& p : FieldProblems())
    if (p.name == name) return p;
  throw std::invalid_argument(
      "unknown field problem '" + name +
      "'; valid field problems: " + FieldProblemNameList());
}

sbp::SpaceDerivative<double> FieldSpace(const FieldProblem& p, int order,
                                        long long nx) {
  if (order != 2 && order != 4 && order != 6 && order != 8)
    throw std::invalid_argument("a spatial order of " + std::to_string(order) +
                                " is not offered; use 2, 4, 6 or 8");
  if (nx > (1 << 16))
    throw std::invalid_argument(std::to_string(nx) +
                                " spatial points are too many; use at most " +
                                std::to_string(1 << 16));
  if (p.periodic)
    return sbp::SpaceDerivative<double>::Periodic(order, int(nx), p.x0,
                                                  p.x1 - p.x0);
  const std::string op =
      "sbp" + std::to_string(order) + std::to_string(order / 2);
  return sbp::SpaceDerivative<double>::Bounded(op, int(nx), p.x0, p.x1);
}

FieldConvergenceStudy RunFieldConvergence(const FieldProblem& p,
                                          const FieldStudyOptions& o,
                                          double round_off_floor) {
  FieldConvergenceStudy study;
  study.in_space = o.space_points.size() > 1;
  if (study.in_space && o.points.size() != 1)
    throw std::invalid_argument(
        "a study in space takes one number of time points, got " +
        List(o.points));
  if (o.points.empty() || o.space_points.empty())
    throw std::invalid_argument("a study needs time and spatial points");
  for (long long nx : o.space_points)
    for (long long nt : o.points) {
      (void)FieldSpace(p, o.space_order, nx);  // refused before any work
      (void)sbp::MakeOperator<double>(o.op, nt, 0.0, o.t_end);
      const long long at_once =
          (o.window_points > 0 ? std::min(o.window_points, nt) : nt) * nx;
      if (at_once > spacetime::MaxSolvedAtOnce(o.op))
        throw std::invalid_argument(
            std::to_string(at_once) + " values solved at once (" +
            std::to_string(nt) + " × " + std::to_string(nx) + ") exceed the " +
            std::to_string(spacetime::MaxSolvedAtOnce(o.op)) + " of " + o.op +
            "; march in windows (window_points = 16)");
    }
  for (long long nx : o.space_points)
    for (long long nt : o.points) study.rows.push_back(Row(p, o, nt, nx));
  ConvergenceStudy fit;
  for (const auto& r : study.rows) {
    fit.rows.push_back(r);
    if (study.in_space) fit.rows.back().dt = fit.rows.back().dt_true = r.dx;
  }
  FitOrders(fit, round_off_floor);
  study.orders = fit.orders;
  study.orders_true_dt = fit.orders_true_dt;
  return study;
}

FieldConvergenceStudy RunFieldTolerance(const FieldProblem& p,
                                        const FieldStudyOptions& o,
                                        const std::vector<double>& tolerances,
                                        double round_off_floor) {
  if (o.space_points.size() != 1)
    throw std::invalid_argument(
        "an error-control study takes one number of spatial points, got " +
        List(o.space_points));
  const auto dx = FieldSpace(p, o.space_order, o.space_points[0]);
  const long long window = o.window_points > 0 ? o.window_points : 16;
  if (window * dx.points() > spacetime::MaxSolvedAtOnce(o.op))
    throw std::invalid_argument(
        "windows of " + std::to_string(window) + " × " +
        std::to_string(dx.points()) + " values exceed the " +
        std::to_string(spacetime::MaxSolvedAtOnce(o.op)) + " solved at once");
  for (double tol : tolerances)
    if (!(tol > 0 && tol < 1))
      throw std::invalid_argument("a tolerance must lie in (0, 1), got " +
                                  std::to_string(tol));
  FieldConvergenceStudy study;
  for (double tol : tolerances) {
    spacetime::FieldSolveOptions options;
    options.tolerance = {tol, tol};
    const spacetime::FieldGrid grid{
        .op = o.op, .points = 0, .t_end = o.t_end, .window_points = window};
    FieldConvergenceRow r;
    r.tolerance = tol;
    const auto s = SolveRow(p, dx, grid, options, r);
    r.rejected = s.rejected;
    r.points = s.points;
    if (s.status.converged) {
      const std::size_t n = std::size_t(dx.points());
      r.max_error = r.max_error_v = 0;
      for (std::size_t k = 0; k < s.t.size(); ++k)
        for (int j = 0; j < dx.points(); ++j) {
          double u = 0, u_t = 0;
          p.exact(s.t[k], dx.x(j), &u, &u_t);
          r.max_error = std::max(r.max_error, std::abs(s.phi[k * n + j] - u));
          r.max_error_v =
              std::max(r.max_error_v, std::abs(s.phi_t[k * n + j] - u_t));
        }
    }
    study.rows.push_back(r);
  }
  ConvergenceStudy fit;
  for (const auto& r : study.rows) fit.rows.push_back(r);
  FitTracking(fit, round_off_floor);
  study.tracking = fit.tracking;
  study.tracking_max = fit.tracking_max;
  study.tracking_max_v = fit.tracking_max_v;
  return study;
}

}  // namespace vivp::studies
