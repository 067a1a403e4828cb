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
  return [u](double t, const double* x, double* phi, double* phi_t) {
    using J = ceres::Jet<double, 1>;
    const J v = u(J(t, 0), J(x[0]));
    phi[0] = v.a;
    phi_t[0] = v.v[0];
  };
}

// Klein–Gordon (m = 1) on the periodic square [0, 2π)²: the plane wave
// cos(x + 2y − √6 t), along (1, 2), a Jet in t for φ_t.
FieldProblem PlaneWave2d() {
  const double two_pi = 2 * std::numbers::pi;
  FieldProblem p{
      "klein_gordon_2d",
      "Klein–Gordon plane wave cos(x + 2y − √6 t), m = 1 on [0, 2π)², "
      "periodic",
      {ft::Kinetic{}, ft::Gradient{}, ft::Mass{}},
      true,
      0.0,
      two_pi,
      {{0.0, two_pi}},
      32,
      8,
      1.0,
      [](double t, const double* x, double* phi, double* phi_t) {
        const double omega = std::sqrt(6.0),
                     theta = x[0] + 2 * x[1] - omega * t;
        phi[0] = std::cos(theta);
        phi_t[0] = omega * std::sin(theta);
      }};
  return p;
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
       {},
       64,
       8,
       1.0,
       ExactOf(fields::KleinGordonPlaneWave{})},
      {"sine_gordon_breather",
       "sine-Gordon breather ω = 0.5 on [−20, 20), periodic",
       sine_gordon,
       true,
       -20.0,
       20.0,
       {},
       200,
       8,
       1.0,
       ExactOf(fields::SineGordonBreather{0.5})},
      {"sine_gordon_kink",
       "sine-Gordon kink moving at v = 0.5 on [−20, 20], natural boundaries",
       sine_gordon,
       false,
       -20.0,
       20.0,
       {},
       301,
       6,
       1.0,
       ExactOf(fields::SineGordonKink{0.5, 0.0})},
      {"wave_gaussian",
       "wave equation c = 1, Gaussian σ = 1 at rest on [−10, 10), periodic",
       {ft::Kinetic{}, ft::Gradient{}},
       true,
       -10.0,
       10.0,
       {},
       256,
       8,
       1.0,
       [pulse](double t, const double* x, double* phi, double* phi_t) {
         std::tie(phi[0], phi_t[0]) = pulse(t, x[0]);
       }},
      PlaneWave2d(),
  };
}

template <class T>
std::string List(const std::vector<T>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
  return s;
}

// The problem's density on a grid of d axes; one axis solves with the
// solver compiled for the derivative (composed.h).
template <int d>
spacetime::FieldSolution SolveOn(const FieldProblem& p,
                                 const sbp::SpaceGrid<double>& g,
                                 const spacetime::FieldGrid& grid,
                                 const spacetime::FieldSolveOptions& options,
                                 std::vector<double> phi,
                                 std::vector<double> pi) {
  const fields::ComposedDensity<1, d> density{p.terms};
  if constexpr (d == 1)
    return spacetime::SolveField(density, g.axis(0), grid, std::move(phi),
                                 std::move(pi), options);
  else
    return spacetime::SolveField(density, g, grid, std::move(phi),
                                 std::move(pi), options);
}

// The coordinates of point j of g.
struct PointOf {
  const sbp::SpaceGrid<double>& g;
  double x[3] = {};
  const double* operator()(int j) {
    for (int a = 0; a < g.dim(); ++a) x[a] = g.x(j, a);
    return x;
  }
};

// Solves the problem on g and grid into row r: its status, counts and the
// errors at t = T, max over the grid. A bad argument throws; any other
// failure is the row's reason. Returns the solution.
spacetime::FieldSolution SolveRow(const FieldProblem& p,
                                  const sbp::SpaceGrid<double>& g,
                                  const spacetime::FieldGrid& grid,
                                  const spacetime::FieldSolveOptions& options,
                                  FieldConvergenceRow& r) {
  const int n = g.points();
  std::vector<double> phi(std::size_t(n), 0.0), pi(std::size_t(n), 0.0);
  PointOf at{g};
  for (int j = 0; j < n; ++j) p.exact(0.0, at(j), &phi[j], &pi[j]);
  r.space_points = n;
  r.axis_points.clear();
  for (int a = 0; a < g.dim(); ++a) r.axis_points.push_back(g.points(a));
  r.dx = g.axis(0).dx();
  spacetime::FieldSolution s;
  try {
    s = g.dim() == 2 ? SolveOn<2>(p, g, grid, options, phi, pi)
                     : SolveOn<1>(p, g, grid, options, phi, pi);
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
  const std::size_t last = s.t.size() - 1;
  r.err_x = r.err_v = r.err_x_corrected = r.err_p_corrected = 0;
  for (int j = 0; j < n; ++j) {
    double u = 0, u_t = 0;
    p.exact(grid.t_end, at(j), &u, &u_t);
    r.err_x = std::max(r.err_x, std::abs(s.end_phi_node[j] - u));
    r.err_v = std::max(r.err_v, std::abs(s.phi_t[last * n + j] - u_t));
    r.err_x_corrected = std::max(r.err_x_corrected, std::abs(s.end.phi[j] - u));
    r.err_p_corrected =
        std::max(r.err_p_corrected, std::abs(s.end.phi_t[j] - u_t));
  }
  r.error_estimate = s.end.phi_estimate;
  return s;
}

// One solve and its errors at t = T, max over the grid.
FieldConvergenceRow Row(const FieldProblem& p, const FieldStudyOptions& o,
                        long long nt, const std::vector<long long>& points) {
  const auto g = FieldGridOf(p, o.space_order, points);
  const spacetime::FieldGrid grid{.op = o.op,
                                  .points = nt,
                                  .t_end = o.t_end,
                                  .window_points = o.window_points};
  FieldConvergenceRow r;
  r.points = nt;
  r.dt = o.t_end / double(nt);
  r.dt_true = o.t_end / double(nt - 1);
  SolveRow(p, g, grid, {}, r);
  return r;
}

long long Product(const std::vector<long long>& v) {
  long long n = 1;
  for (long long x : v) n *= x;
  return n;
}

std::string Points(const std::vector<long long>& v) {
  std::string s;
  for (long long x : v) s += (s.empty() ? "" : "x") + std::to_string(x);
  return s;
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

sbp::SpaceGrid<double> FieldGridOf(const FieldProblem& p, int order,
                                   const std::vector<long long>& points) {
  if (int(points.size()) != p.Dim())
    throw std::invalid_argument("'" + p.name + "' has " +
                                std::to_string(p.Dim()) + " axes; got " +
                                std::to_string(points.size()) +
                                " numbers of points (" + Points(points) + ")");
  std::vector<sbp::SpaceDerivative<double>> axes{
      FieldSpace(p, order, points[0])};
  for (int a = 1; a < p.Dim(); ++a) {
    FieldProblem along = p;  // the same kind of axis on its own interval
    along.x0 = p.cross_domains[std::size_t(a) - 1][0];
    along.x1 = p.cross_domains[std::size_t(a) - 1][1];
    axes.push_back(FieldSpace(along, order, points[std::size_t(a)]));
  }
  return sbp::SpaceGrid<double>(std::move(axes));
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
  for (const auto& nx : o.space_points)
    for (long long nt : o.points) {
      (void)FieldGridOf(p, o.space_order, nx);  // refused before any work
      (void)sbp::MakeOperator<double>(o.op, nt, 0.0, o.t_end);
      const long long at_once =
          (o.window_points > 0 ? std::min(o.window_points, nt) : nt) *
          Product(nx);
      if (at_once > spacetime::MaxSolvedAtOnce(o.op))
        throw std::invalid_argument(
            std::to_string(at_once) + " values solved at once (" +
            std::to_string(nt) + " × " + Points(nx) + ") exceed the " +
            std::to_string(spacetime::MaxSolvedAtOnce(o.op)) + " of " + o.op +
            "; march in windows (window_points = 16)");
    }
  // In space: fitted against the Δx of the first axis whose points vary.
  for (int a = p.Dim() - 1; a >= 0; --a)
    for (const auto& nx : o.space_points)
      if (nx[std::size_t(a)] != o.space_points[0][std::size_t(a)])
        study.refined_axis = a;
  for (const auto& nx : o.space_points)
    for (long long nt : o.points) {
      study.rows.push_back(Row(p, o, nt, nx));
      study.rows.back().dx =
          FieldGridOf(p, o.space_order, nx).axis(study.refined_axis).dx();
    }
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
        "an error-control study takes one spatial grid, got " +
        std::to_string(o.space_points.size()));
  const auto g = FieldGridOf(p, o.space_order, o.space_points[0]);
  const long long window = o.window_points > 0 ? o.window_points : 16;
  if (window * g.points() > spacetime::MaxSolvedAtOnce(o.op))
    throw std::invalid_argument(
        "windows of " + std::to_string(window) + " × " +
        std::to_string(g.points()) + " values exceed the " +
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
    const auto s = SolveRow(p, g, grid, options, r);
    r.rejected = s.rejected;
    r.points = s.points;
    if (s.status.converged) {
      const std::size_t n = std::size_t(g.points());
      r.max_error = r.max_error_v = 0;
      PointOf at{g};
      for (std::size_t k = 0; k < s.t.size(); ++k)
        for (int j = 0; j < g.points(); ++j) {
          double u = 0, u_t = 0;
          p.exact(s.t[k], at(j), &u, &u_t);
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
