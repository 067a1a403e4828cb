#include "solvers/bea/multistep.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace vivp::bea {

std::vector<Eigen::MatrixXd> NumericCoefficients(const Method& method) {
  const int d = method.dim;
  if (method.kind == MethodKind::kStormerVerlet)
    return {Eigen::MatrixXd::Identity(d, d)};
  if (method.kind != MethodKind::kMultistep)
    throw std::invalid_argument("method '" + method.name +
                                "' is not a multistep method");
  std::vector<Eigen::MatrixXd> out;
  for (const auto& a : method.A) {
    Eigen::MatrixXd m(d, d);
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < d; ++c) {
        const GiNaC::ex e = GiNaC::evalf(a(r, c));
        if (!GiNaC::is_a<GiNaC::numeric>(e))
          throw std::invalid_argument(
              "coefficient entries must be numbers to run the method");
        m(r, c) = GiNaC::ex_to<GiNaC::numeric>(e).to_double();
      }
    out.push_back(m);
  }
  return out;
}

Stability CheckStability(const std::vector<Eigen::MatrixXd>& A) {
  const int k = static_cast<int>(A.size());
  const int d = static_cast<int>(A[0].rows());
  // rho(zeta) = sum_{m=0}^{2k} C_m zeta^m with C_{k+j} = C_{k-j} = A_j,
  // C_k = -2 sum A_j. Block companion linearisation (C_{2k} = A_k invertible).
  std::vector<Eigen::MatrixXd> C(2 * k + 1, Eigen::MatrixXd::Zero(d, d));
  for (int j = 1; j <= k; ++j) {
    C[k + j] += A[j - 1];
    C[k - j] += A[j - 1];
    C[k] -= 2 * A[j - 1];
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lead(C[2 * k]);
  Stability s;
  if (!lead.isInvertible()) {
    s.stable = false;
    s.reason = "the leading coefficient A_k is singular";
    return s;
  }
  const int n = 2 * k * d;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  companion.topRightCorner(n - d, n - d).setIdentity();
  for (int m = 0; m < 2 * k; ++m)
    companion.block(n - d, m * d, d, d) = -lead.solve(C[m]);
  Eigen::EigenSolver<Eigen::MatrixXd> es(companion, false);
  // Drop the consistency root 1 (multiplicity 2 per component).
  std::vector<std::complex<double>> all(es.eigenvalues().data(),
                                        es.eigenvalues().data() + n);
  std::sort(all.begin(), all.end(), [](auto a, auto b) {
    return std::abs(a - 1.0) < std::abs(b - 1.0);
  });
  s.roots.assign(all.begin() + 2 * d, all.end());
  // Roots on the unit circle come out perturbed by ~sqrt(eps) when they are
  // (nearly) double: accept |zeta| <= 1 + 100 n sqrt(eps).
  const double tol =
      100 * n * std::sqrt(std::numeric_limits<double>::epsilon());
  for (const auto& z : s.roots) {
    s.max_root_modulus = std::max(s.max_root_modulus, std::abs(z));
  }
  if (s.max_root_modulus > 1 + tol) {
    s.stable = false;
    std::ostringstream msg;
    msg << "unstable: the characteristic polynomial has a root of modulus "
        << s.max_root_modulus
        << " > 1, so errors grow like that factor per step (for (4.1) with "
           "A = alpha I choose alpha <= 0)";
    s.reason = msg.str();
  }
  return s;
}

std::vector<double> CentralDifferenceWeights(int order) {
  if (order < 2 || order % 2)
    throw std::invalid_argument("difference order must be even and >= 2");
  const int m = order / 2;
  // Antisymmetric weights w_{-j} = -w_j; sum_j w_j 2 j^{2q+1} = delta_{q0}
  // for q = 0..m-1.
  Eigen::MatrixXd V(m, m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  rhs(0) = 1;
  for (int q = 0; q < m; ++q)
    for (int j = 1; j <= m; ++j) V(q, j - 1) = 2 * std::pow(j, 2 * q + 1);
  const Eigen::VectorXd w = V.fullPivLu().solve(rhs);
  std::vector<double> out(2 * m + 1, 0.0);
  for (int j = 1; j <= m; ++j) {
    out[m + j] = w(j - 1);
    out[m - j] = -w(j - 1);
  }
  return out;
}

MultistepRun RunMultistep(const std::vector<Eigen::MatrixXd>& A,
                          const NumericPotential& potential,
                          const ModifiedQuantities& start,
                          const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                          const MultistepOptions& o) {
  const int k = static_cast<int>(A.size());
  const int d = static_cast<int>(x0.size());
  const double h = o.h;
  if (o.steps < 2 * k) throw std::invalid_argument("need at least 2k steps");
  Eigen::FullPivLU<Eigen::MatrixXd> lead(A[k - 1]);
  if (!lead.isInvertible())
    throw std::invalid_argument(
        "A_k is singular: the multistep method cannot be solved for x_{n+k}");
  MultistepRun run;
  run.x.resize(o.steps + 1, d);
  run.x.row(0) = x0.transpose();
  // Start values: RK4 on the modified equation y = (x, x'), y' = (x', f).
  {
    Eigen::VectorXd x = x0, v = v0;
    const double dt = h / o.rk_substeps;
    auto acc = [&](const Eigen::VectorXd& xx, const Eigen::VectorXd& vv) {
      Eigen::VectorXd a(d);
      start.Acceleration(o.start_order, h, xx.data(), vv.data(), a.data());
      return a;
    };
    for (int n = 1; n < 2 * k; ++n) {
      for (int s = 0; s < o.rk_substeps; ++s) {
        const Eigen::VectorXd k1x = v, k1v = acc(x, v);
        const Eigen::VectorXd k2x = v + dt / 2 * k1v,
                              k2v = acc(x + dt / 2 * k1x, v + dt / 2 * k1v);
        const Eigen::VectorXd k3x = v + dt / 2 * k2v,
                              k3v = acc(x + dt / 2 * k2x, v + dt / 2 * k2v);
        const Eigen::VectorXd k4x = v + dt * k3v,
                              k4v = acc(x + dt * k3x, v + dt * k3v);
        x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      }
      run.x.row(n) = x.transpose();
    }
  }
  // March: A_k x_{n+k} = h^2 g(x_n) - sum_{j<k} A_j (x_{n+j} - 2x_n + x_{n-j})
  //                      - A_k (x_{n-k} - 2 x_n).
  Eigen::VectorXd g(d), rhs(d);
  for (int n = k; n + k <= o.steps; ++n) {
    const Eigen::VectorXd xn = run.x.row(n).transpose();
    potential.Gradient(xn.data(), g.data());
    rhs = h * h * g;
    for (int j = 1; j < k; ++j)
      rhs -= A[j - 1] * (run.x.row(n + j).transpose() - 2 * xn +
                         run.x.row(n - j).transpose());
    rhs -= A[k - 1] * (run.x.row(n - k).transpose() - 2 * xn);
    run.x.row(n + k) = lead.solve(rhs).transpose();
  }
  const auto w = CentralDifferenceWeights(o.difference_order);
  const int m = o.difference_order / 2;
  run.v = Eigen::MatrixXd::Constant(o.steps + 1, d,
                                    std::numeric_limits<double>::quiet_NaN());
  run.first_velocity = m;
  run.last_velocity = o.steps - m;
  for (int n = m; n <= o.steps - m; ++n) {
    Eigen::RowVectorXd s = Eigen::RowVectorXd::Zero(d);
    for (int j = -m; j <= m; ++j)
      if (w[m + j] != 0) s += w[m + j] * run.x.row(n + j);
    run.v.row(n) = s / h;
  }
  return run;
}

}  // namespace vivp::bea
