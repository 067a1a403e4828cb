// The symmetric linear multistep method with matrix coefficients (2.2),
//   sum_{j=1}^k A_j (x_{n+j} - 2 x_n + x_{n-j}) = h^2 grad U(x_n),
// for any dimension: stability of the coefficients, start values from the
// modified equation, the explicit march, and velocities recovered from the
// discrete trajectory by central differences.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "solvers/bea/evaluator.h"
#include "solvers/bea/method.h"
#include "solvers/bea/potentials.h"

namespace vivp::bea {

// Numeric coefficients A_1..A_k of a method (Stormer-Verlet: A_1 = I).
// Throws std::invalid_argument if an entry is not a number.
std::vector<Eigen::MatrixXd> NumericCoefficients(const Method& method);

struct Stability {
  bool stable = true;
  double max_root_modulus = 0;
  // Roots of det rho(zeta), rho(zeta) = sum_j A_j (zeta^{k+j} - 2 zeta^k +
  // zeta^{k-j}), without the double root 1 that consistency puts there.
  std::vector<std::complex<double>> roots;
  std::string reason;  // why it is unstable (empty when stable)
};
// Stable iff every root lies in the closed unit disk (HLW XV.1.2); for
// (4.1) with A = alpha I that is alpha <= 0. Roots on the unit circle are
// accepted with a tolerance scaled by the number of roots.
Stability CheckStability(const std::vector<Eigen::MatrixXd>& A);

// Central-difference weights w_{-m..m} for x'(t_n) ~ sum w_j x_{n+j} / h,
// of order 2m (exact for polynomials of degree 2m).
std::vector<double> CentralDifferenceWeights(int order);

struct MultistepRun {
  Eigen::MatrixXd x;  // (steps + 1) x d, x.row(n) = x_n
  Eigen::MatrixXd v;  // velocities by central differences; NaN near the ends
  int first_velocity = 0, last_velocity = 0;  // rows where v is defined
};

struct MultistepOptions {
  double h = 0.1;
  int steps = 1000;
  int difference_order = 6;
  // Start values x_1..x_{2k-1} from the modified equation truncated at this
  // order (even), integrated with RK4 at substeps h / rk_substeps.
  int start_order = 4;
  int rk_substeps = 64;
};

// Marches (2.2) from x(0) = x0, x'(0) = v0 (initial data of the modified
// equation in `start`). Throws std::invalid_argument if A_k is singular.
MultistepRun RunMultistep(const std::vector<Eigen::MatrixXd>& A,
                          const NumericPotential& potential,
                          const ModifiedQuantities& start,
                          const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                          const MultistepOptions& options);

}  // namespace vivp::bea
