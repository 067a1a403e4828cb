// The field problems `vivp converge --field NAME` knows by name, each with
// its density (a sum of terms, problems/fields/terms.h), domain (one axis,
// or a grid of 2 axes) and exact solution, and their convergence studies:
// the error of φ at t = T against the exact solution over a list of time
// grids (orders in Δt) or of spatial grids at one time grid (orders in Δx;
// on a grid, in the Δx of the first axis whose points vary, so that one axis
// can be refined while the others stay fine). The rows and orders are those of
// point mechanics (convergence.h): err_x of the last node φ_N, err_v of
// (D_t φ)_N, err_x_corrected of the multiplier-corrected φ_N + M⁻¹λ4 and
// err_p_corrected of the corrected momentum density −λ3 (= φ_t for these
// densities, where ∂L/∂φ_t = φ_t), each the maximum over x.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/sbp/space.h"
#include "core/sbp/space_grid.h"
#include "problems/fields/terms.h"
#include "studies/convergence.h"

namespace vivp::studies {

struct FieldProblem {
  std::string name;
  std::string description;
  std::vector<fields::FieldTerm> terms;  // one component
  bool periodic = true;                  // else natural boundaries
  double x0 = 0, x1 = 1;
  // The further axes of a problem on a grid (y, z), of the same kind.
  std::vector<std::array<double, 2>> cross_domains;
  int Dim() const { return 1 + int(cross_domains.size()); }
  // Defaults of the study: spatial points, order of the spatial operator
  // (periodic differences, or SBP(2p, p) on an interval) and end time.
  long long space_points = 64;
  int space_order = 8;
  double t_end = 1.0;
  // φ(t, x) and φ_t(t, x); x holds the point's Dim() coordinates.
  std::function<void(double t, const double* x, double* phi, double* phi_t)>
      exact;
};

const std::vector<FieldProblem>& FieldProblems();
std::string FieldProblemNameList();
// Throws std::invalid_argument naming the valid problems.
const FieldProblem& FindFieldProblem(const std::string& name);

// The spatial derivative of `problem` on nx points with an operator of
// order `order` (periodic differences, or sbp21 … sbp84 for 2, 4, 6, 8 on an
// interval). Throws std::invalid_argument for an order or nx it refuses.
sbp::SpaceDerivative<double> FieldSpace(const FieldProblem& problem, int order,
                                        long long nx);
// The grid of `problem` with points[a] on axis a (points.size() = Dim()).
sbp::SpaceGrid<double> FieldGridOf(const FieldProblem& problem, int order,
                                   const std::vector<long long>& points);

struct FieldConvergenceRow : ConvergenceRow {  // windows: the march's
  long long space_points = 0;                  // over all axes
  std::vector<long long> axis_points;          // per axis
  double dx = 0;  // of the axis the study refines (the first on one axis)
};

struct FieldStudyOptions {
  std::string op = "sbp42";
  std::vector<long long> points;  // time points, one per row, or one
  // Spatial points per axis (Dim() values), one entry per row, or one.
  std::vector<std::vector<long long>> space_points;
  int space_order = 8;
  double t_end = 1.0;
  long long window_points = 0;  // 0: global solves
};

struct FieldConvergenceStudy {
  bool in_space = false;  // rows differ in Nx (else in Nt)
  int refined_axis = 0;   // in space: the first axis whose points vary
  std::vector<FieldConvergenceRow> rows;
  // In time: against Δt = T/Nt and T/(Nt − 1) (convergence.h); in space:
  // both against Δx.
  ConvergenceOrders orders, orders_true_dt;
  // Error control (RunFieldTolerance): how the corrected end error and the
  // largest errors of φ and φ_t over the kept slices follow the tolerance.
  ToleranceTracking tracking, tracking_max, tracking_max_v;
};

// The study over o.points (o.space_points one value) or over
// o.space_points (o.points one value). A solve that fails is its row's
// reason; a bad argument throws std::invalid_argument before any work.
FieldConvergenceStudy RunFieldConvergence(const FieldProblem& problem,
                                          const FieldStudyOptions& o,
                                          double round_off_floor = 1e-13);

// Error control (docs/error_control.md): one march per tolerance (absolute =
// relative) on o.space_points[0] points, in windows of o.window_points (0:
// 16); each row has the corrected end errors, the largest errors of φ and
// φ_t over every kept slice (max_error, max_error_v), the time nodes
// (points), windows and rejected windows. o.points is not used.
FieldConvergenceStudy RunFieldTolerance(const FieldProblem& problem,
                                        const FieldStudyOptions& o,
                                        const std::vector<double>& tolerances,
                                        double round_off_floor = 1e-13);

}  // namespace vivp::studies
