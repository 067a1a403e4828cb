// Running a scene: the effects become one Lagrangian (problems/composed.h)
// — or, for a stepper, the Hamiltonian ½pᵀM⁻¹p + V — and the method of the
// scene computes the trajectory. Nothing is evaluated that the scene did not
// ask for: diagnostics and the reference solution only when listed.
//
// Output goes to a RunSink node by node, in order, so a marched or stepped
// run holds O(window) memory whatever the number of points.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace vivp::scene {

// The per-node columns beyond t, x and v, in the order Node() passes them.
struct RunLayout {
  int dof = 1;
  std::vector<std::string> columns;
  // Index of the first reference position column, or −1 without reference.
  int reference_x = -1;
};

class RunSink {
 public:
  virtual ~RunSink() = default;
  virtual void Begin(const RunLayout& layout) = 0;
  // Every node once, in order; `columns` has layout.columns.size() values.
  virtual void Node(double t, const double* x, const double* v,
                    const double* columns) = 0;
  // The part of [start, end] done so far, in [0, 1]; called often.
  virtual void Progress(double /*fraction*/) {}
};

struct RunOutcome {
  bool converged = false;
  std::string status;  // "converged", or why not
  std::string method;  // human description, e.g. "variational, sbp42, ..."
  std::vector<double> end_x, end_v;  // best end state the method offers
  long long points = 0;              // nodes computed (under error control:
                                     // chosen by the march)
  double seconds = 0;                // the solve, without output
  nlohmann::json solver;  // method-specific figures (iterations, ‖∇S‖, …)
};

RunOutcome RunScene(const Scene& scene, RunSink& sink);

// The DOF counts the effect scenes are compiled for.
const std::vector<int>& SupportedDofs();

// Empty if the stepper scene.method.kind can run the scene, else why not
// ("needs a Hamiltonian: effect 'damping' is dissipative").
std::string StepperUnavailable(const Scene& scene);

}  // namespace vivp::scene
