// The rows of the work–precision comparison and the hook for methods from
// outside the stepper family, without the stepper templates: what the
// users of bench_problems.h need (work_precision.h measures).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vivp::studies {

struct WorkPoint {
  std::string method;
  long steps = 0;          // fixed-step methods: steps to t_end
  double tolerance = NAN;  // adaptive methods
  double h = NAN;
  double error = NAN;  // max-norm of (q, p) − reference at t_end
  double energy_error = NAN;  // max |H − H₀| / |H₀| over the run (|H₀| if ≠ 0)
  double invariant_error = NAN;  // max over invariants of max |I − I₀|
  double seconds = NAN;          // median wall time of one run
  long evaluations = 0;
  long iterations = 0;
  double iterations_per_step = 0;
  std::string status = "ok";
};

// A method from outside the stepper family (the variational solver).
struct ExternalRun {
  std::vector<std::vector<double>> states;  // (q, p) at the method's nodes
  long steps = 0;                           // intervals between the nodes
  long evaluations = 0, iterations = 0;
  std::string status = "ok";
};
// `knob`: the step count, or the tolerance for an adaptive method.
// `trajectory`: the states at every node (the observed run); otherwise the end
// state alone (the timed runs, which charge a stepper no observer either).
using ExternalMethod = std::function<ExternalRun(
    const std::string& problem, const std::vector<double>& y0, double t_end,
    double knob, bool trajectory)>;

inline std::map<std::string, ExternalMethod>& ExternalMethods() {
  static std::map<std::string, ExternalMethod> methods;
  return methods;
}
// Which problems (by bench name) an external method can run; empty: all.
using ExternalApplicability = std::function<bool(const std::string& problem)>;
inline std::map<std::string, ExternalApplicability>& ExternalApplies() {
  static std::map<std::string, ExternalApplicability> applies;
  return applies;
}
// The external methods whose knob is a tolerance.
inline std::vector<std::string>& AdaptiveExternalMethods() {
  static std::vector<std::string> names;
  return names;
}
inline void RegisterExternalMethod(const std::string& name, ExternalMethod m,
                                   ExternalApplicability applies = {},
                                   bool adaptive = false) {
  ExternalMethods()[name] = std::move(m);
  ExternalApplies()[name] = std::move(applies);
  if (adaptive) AdaptiveExternalMethods().push_back(name);
}
// True for every non-external method.
inline bool ExternalMethodApplies(const std::string& method,
                                  const std::string& problem) {
  const auto it = ExternalApplies().find(method);
  return it == ExternalApplies().end() || !it->second || it->second(problem);
}

inline const std::vector<std::string>& PeerNames() {
  static const std::vector<std::string> names = {
      "odeint_rk4", "odeint_velocity_verlet", "odeint_mclachlan",
      "odeint_dopri5"};
  return names;
}

// True when the method's knob is a tolerance, not a step count.
inline bool IsAdaptive(const std::string& method) {
  const auto& a = AdaptiveExternalMethods();
  return method == "odeint_dopri5" ||
         std::find(a.begin(), a.end(), method) != a.end();
}

}  // namespace vivp::studies
