// Fig. 2 of Rothkopf & Nordström (2023): free fall with SBP21 at N_t = 32.
// Left: the boundary value problem of eq. (23), x(0) = 1, x(1) = 0.8, whose
// critical point is the exact parabola up to O(Δt²). Right: the naive initial
// value problem of eq. (24) with the unregularized D (sigma0 = 0): the
// pi-mode, the left null vector of D, throws every other node off the
// parabola. Usage: fig02_bvp_and_naive_ivp [OUTPUT_DIR]
#include <Eigen/Dense>
#include <iostream>

#include "core/sbp/builder.h"
#include "figures/solver_figures.h"
#include "problems/free_fall.h"

namespace {

// Critical point of eq. (23): ∂S/∂x = m DᵀHD x − mg H1 + λ1 e0 + λ2 e_N = 0
// with the two boundary rows; a small dense KKT solve (no library BVP exists).
Eigen::VectorXd SolveBvp(const vivp::sbp::Operator<double>& d, double m,
                         double g, double xi, double xf) {
  const int n = d.points();
  const Eigen::MatrixXd dd = d.DenseD();
  const Eigen::VectorXd h = d.NormDiagonal();
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + 2, n + 2);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 2);
  kkt.topLeftCorner(n, n) = m * dd.transpose() * h.asDiagonal() * dd;
  kkt(0, n) = kkt(n, 0) = 1;
  kkt(n - 1, n + 1) = kkt(n + 1, n - 1) = 1;
  rhs.head(n) = m * g * h;
  rhs[n] = xi;
  rhs[n + 1] = xf;
  return kkt.fullPivLu().solve(rhs).head(n);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vivp::figures;
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const vivp::studies::NamedProblem& ff =
      vivp::studies::FindProblem("freefall");
  const vivp::problems::FreeFall p;
  const auto d = vivp::sbp::MakeOperator<double>("sbp21", 32);
  const Eigen::VectorXd x = SolveBvp(d, p.m, p.g, p.x0, ff.exact(1.0).x[0]);

  Panel bvp{"BVP, eq. (23): SBP21, N_t = 32", "t", "x(t)", {}, ""};
  bvp.series.push_back(Curve(
      "exact", [&](double t) { return ff.exact(t).x[0]; }, 0, 1, kGrayLine));
  bvp.series.push_back({"x", {}, kRedCircles});
  for (int i = 0; i < d.points(); ++i)
    bvp.series.back().rows.push_back({d.t(i), x[i]});

  vivp::variational::SolveOptions options;
  options.path = vivp::variational::Path::kFullNewton;
  const auto naive =
      ff.solve({.op = "sbp21", .points = 32, .sigma0 = 0.0}, options);
  if (!naive.status.converged)
    std::cerr << "naive IVP: " << naive.status.reason << "\n";
  const Panel ivp = PathsPanel(
      ff, naive, "naive IVP, eq. (24): unregularized SBP21, N_t = 32");
  std::cout << PanelFigure(dir, "fig02_bvp_and_naive_ivp", {bvp, ivp}).string()
            << "\n";
}
