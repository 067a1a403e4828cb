// The variational solver as an external method of the work–precision harness
// (bench_problems.h): the same problems and measurements as the steppers,
// under error control (variational_sbpXY, a tolerance like odeint_dopri5's)
// or on a uniform grid (variational_sbpXY_uniform, a step count); the
// spectral elements likewise (variational_lgl8, variational_lgl8_uniform …).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/sbp/builder.h"
#include "problems/damped_oscillator.h"
#include "solvers/variational/solver_choice.h"
#include "studies/bench_problems.h"
#include "studies/registry.h"

namespace vivp::studies {

namespace {

// A method name: variational_sbpXY (its knob a tolerance, like dopri5's) or
// variational_sbpXY_uniform (its knob a step count); a spectral element also
// variational_lglN_embedded and variational_lglN_halves, under error
// control by its own end-node estimates or by its halves at every
// tolerance (variational_lglN: the march's default, the first down to
// 10⁻⁸; MarchOptions::element_estimate).
constexpr std::string_view kUniform = "_uniform";
constexpr std::string_view kEmbedded = "_embedded";
constexpr std::string_view kHalves = "_halves";
std::string Operator(const std::string& method) {
  std::string op = method.substr(std::string("variational_").size());
  for (std::string_view kind : {kUniform, kEmbedded, kHalves})
    if (op.ends_with(kind)) op.resize(op.size() - kind.size());
  return op;
}
bool Adaptive(const std::string& method) { return !method.ends_with(kUniform); }

// The window SetVariationalWindowPoints chose; 0: the solver's default.
long long& WindowOverride() {
  static long long points = 0;
  return points;
}

// The window of a configuration's march: the one chosen, or the default of
// Newton's march on a uniform grid or under error control. March sets it,
// and the evaluation counts below use it.
long long MethodWindow(const std::string& method) {
  // A spectral element's window is the element, whatever was chosen for
  // the finite-difference operators.
  if (WindowOverride() > 0 && !sbp::IsElement(Operator(method)))
    return WindowOverride();
  return variational::DefaultWindowPoints(variational::Path::kReducedNewton,
                                          Operator(method), Adaptive(method));
}

// The march of one configuration: a tolerance (absolute = relative) or a
// uniform grid of `knob` steps, in the default windows.
variational::MarchResult March(const NamedProblem& p, const std::string& method,
                               double t_end, double knob,
                               bool trajectory = true) {
  variational::Grid g{.op = Operator(method), .t_start = 0.0, .t_end = t_end};
  variational::MarchOptions o;
  o.keep_trajectory = trajectory;
  o.window_points = MethodWindow(method);
  if (Adaptive(method)) {
    o.tolerance = {knob, knob};
    if (method.ends_with(kEmbedded))
      o.element_estimate = variational::ElementEstimate::kEmbedded;
    if (method.ends_with(kHalves))
      o.element_estimate = variational::ElementEstimate::kHalves;
  } else {
    g.points = static_cast<long long>(knob) + 1;
    // A spectral element marches whole elements of n − 1 steps: the count
    // rounded up to the next multiple (the row reports the steps taken).
    if (const int n = sbp::Table(g.op).max_points; n > 0)
      g.points = (static_cast<long long>(knob) + n - 2) / (n - 1) * (n - 1) + 1;
    o.stabilize = false;  // a step count means that step: no hidden refinement
  }
  return p.march(g, o, {});
}

// Pointwise evaluations of a march: a window evaluates the density's
// derivatives at every node once per Newton or chord correction — at its
// start (with the Jacobian when it factors afresh) and after every correction
// but the converging one — and the predictor's Dormand–Prince steps six
// equations of motion each.
long long Evaluations(const variational::MarchResult& m,
                      const std::string& method) {
  return m.corrections * MethodWindow(method) + 6 * m.predictor_steps;
}

ExternalRun RunVariational(const std::string& method,
                           const std::string& problem,
                           const std::vector<double>& y0, double t_end,
                           double knob, bool trajectory) {
  ExternalRun run;
  if (!HasProblem(problem)) {
    run.status = "n/a (" + problem + " has no variational registry entry)";
    return run;
  }
  const NamedProblem& p = FindProblem(problem);
  const std::size_t d = p.initial.x.size();
  // Equal to a few ulps: the bench's Kepler e = 0.9 starts at 1 − e, the
  // registry's at 0.1.
  auto same = [](double a, double b) {
    return std::abs(a - b) <= 4e-16 * std::max(std::abs(a), std::abs(b));
  };
  // The bench's state is (q, p): the registry's (x, ẋ) with p = ∂L/∂ẋ.
  const std::vector<double> p0 =
      p.momentum(p.initial.x.data(), p.initial.v.data());
  for (std::size_t c = 0; c < d; ++c)
    if (!same(y0[c], p.initial.x[c]) || !same(y0[d + c], p0[c])) {
      run.status = "n/a (initial state differs from the registry's)";
      return run;
    }
  const variational::MarchResult m = March(p, method, t_end, knob, trajectory);
  if (!m.status.converged) {
    run.status = "not converged: " + m.status.reason;
    return run;
  }
  run.states.reserve(trajectory ? m.t.size() : 1);
  auto state = [&](const double* x, const double* v) {
    std::vector<double> s(x, x + d);
    const std::vector<double> momentum = p.momentum(x, v);
    s.insert(s.end(), momentum.begin(), momentum.end());
    return s;
  };
  std::vector<double> x(d), v(d);
  for (Eigen::Index i = 0; i < Eigen::Index(m.t.size()); ++i) {
    for (std::size_t c = 0; c < d; ++c) {
      x[c] = m.x(i, c);
      v[c] = m.v(i, c);
    }
    run.states.push_back(state(x.data(), v.data()));
  }
  // The last node carries the multiplier-corrected state, the one the march
  // hands on (of higher order than x_N).
  if (run.states.empty()) run.states.emplace_back();
  run.states.back() = state(m.end_position.data(), m.end_velocity.data());
  run.steps = long(m.points - 1);
  run.evaluations = Evaluations(m, method);
  run.iterations = m.corrections;
  return run;
}

// The damped oscillator is not Hamiltonian: no stepper of the family
// applies, so its row of the comparison is the variational solver alone,
// measured like the steppers (error of (x, p = μẋ) at t_end, maximum energy
// error against the exact decaying energy relative to E(0), median time).
WorkPoint MeasureDamped(const std::string& method, double t_end, double knob,
                        int repeats) {
  const problems::DampedOscillator exact;
  const NamedProblem& p = FindProblem("damped");
  WorkPoint w;
  w.method = method;
  if (Adaptive(method)) {
    w.tolerance = knob;
  } else {
    w.steps = static_cast<long>(knob);
    w.h = t_end / knob;
  }
  // Timed without the trajectory, as the steppers are timed without an
  // observer; the energy error from one more run that keeps it.
  std::vector<double> t;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    const auto begin = std::chrono::steady_clock::now();
    (void)March(p, method, t_end, knob, false);
    t.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin)
            .count());
  }
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  w.seconds = t[t.size() / 2];
  const variational::MarchResult m = March(p, method, t_end, knob);
  if (!m.status.converged) {
    w.status = "not converged: " + m.status.reason;
    return w;
  }
  w.steps = long(m.points - 1);
  const auto end = exact.Exact(t_end);
  w.error = std::max(std::abs(m.end_position[0] - end.x),
                     exact.mu * std::abs(m.end_velocity[0] - end.v));
  const double e0 = exact.Energy(exact.x0, exact.v0);
  double de = 0;
  for (Eigen::Index i = 0; i < Eigen::Index(m.t.size()); ++i) {
    const auto e = exact.Exact(m.t[i]);
    de = std::max(de, std::abs(exact.Energy(m.x(i, 0), m.v(i, 0)) -
                               exact.Energy(e.x, e.v)));
  }
  w.energy_error = de / e0;
  w.evaluations = Evaluations(m, method);
  w.iterations = m.corrections;
  return w;
}

}  // namespace

void SetVariationalWindowPoints(long long points) {
  if (points < 0)
    throw std::invalid_argument(
        "window points must be 0 (the default) or positive, got " +
        std::to_string(points));
  WindowOverride() = points;
}

bool IsVariationalMethod(const std::string& method) {
  return method.starts_with("variational_");
}

std::string VariationalOperator(const std::string& method) {
  return Operator(method);
}

BenchProblem DampedBenchProblem() {
  BenchProblem b;
  b.name = "damped";
  b.description =
      "damped oscillator μẍ + ξẋ + κx = 0 (Rothkopf & Nordström 2023, "
      "eq. 43), t = 204.8";
  b.reference = "exact";
  b.t_end = 204.8;
  b.first_steps = 256;
  for (const std::string& op : sbp::OperatorNames())
    for (const char* kind : {"", "_uniform"})
      b.methods.push_back("variational_" + op + kind);
  b.measure = [t_end = b.t_end](const std::string& method, double knob,
                                int repeats) {
    return MeasureDamped(method, t_end, knob, repeats);
  };
  return b;
}

void RegisterVariationalMethods() {
  static const bool registered = [] {
    // Every operator under error control and uniform: the finite-difference
    // operators and the spectral elements, these also under error control
    // by their embedded estimates or their halves at every tolerance.
    std::vector<std::string> names;
    std::vector<std::string> ops = sbp::OperatorNames();
    for (const std::string& op : ops)
      for (const std::string kind : {"", "_uniform"})
        names.push_back("variational_" + op + kind);
    for (const sbp::Coefficients* e : sbp::ElementOperators())
      for (const std::string kind : {"", "_uniform", "_embedded", "_halves"})
        names.push_back("variational_" + std::string(e->name) + kind);
    for (const std::string& name : names)
      RegisterExternalMethod(
          name,
          [name](const std::string& problem, const std::vector<double>& y0,
                 double t_end, double knob, bool trajectory) {
            return RunVariational(name, problem, y0, t_end, knob, trajectory);
          },
          HasProblem, Adaptive(name));
    return true;
  }();
  (void)registered;
}

}  // namespace vivp::studies
