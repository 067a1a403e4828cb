#include "solvers/spacetime/fourier_solver.h"

#include <fftw3.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace vivp::spacetime {

using Complex = std::complex<double>;

struct FourierWindowSolver::Impl {
  int nt = 0, n = 0, m = 0, block = 0, nullity = 0;
  double dt = 0;
  std::vector<Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXcd>> cod;
  std::vector<Eigen::VectorXd> scale;  // row equilibration per wave vector
  fftw_complex* data = nullptr;
  fftw_plan forward = nullptr, backward = nullptr;
  ~Impl() {
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    if (data) fftw_free(data);
  }
};

namespace {

// s_b(q) for q = 0 … N_b − 1: the axis's derivative of exp(2πi q j / N_b)
// at j = 0, where that function is 1.
std::vector<Complex> Symbols(const sbp::SpaceDerivative<double>& axis) {
  const int n = axis.points();
  std::vector<Complex> s(n);
  std::vector<double> c(n), sn(n), dc(n), ds(n);
  for (int q = 0; q < n; ++q) {
    for (int j = 0; j < n; ++j) {
      const double theta = 2 * std::numbers::pi * double(q) * j / n;
      c[j] = std::cos(theta);
      sn[j] = std::sin(theta);
    }
    axis.Apply<double>(c, dc);
    axis.Apply<double>(sn, ds);
    s[q] = Complex(dc[0], ds[0]);
  }
  // The round-off of cos and sin at the grid's points leaves ~ε/Δx where
  // the symbol is zero (the constants, the checkerboard): exactly zero, so
  // that those modes' null spaces are exact.
  double largest = 0;
  for (const Complex& z : s) largest = std::max(largest, std::abs(z));
  for (Complex& z : s) {
    if (std::abs(z.real()) <= 1e-13 * largest) z.real(0);
    if (std::abs(z.imag()) <= 1e-13 * largest) z.imag(0);
  }
  return s;
}

}  // namespace

FourierWindowSolver::FourierWindowSolver(
    const sbp::RegularizedOperator<double>& dt,
    const sbp::SpaceGrid<double>& grid, int m, const Eigen::MatrixXd& h,
    unsigned constraints, double rank_threshold)
    : impl_(std::make_unique<Impl>()) {
  const int d = grid.dim(), K = (2 + d) * m;
  for (int b = 0; b < d; ++b)
    if (!grid.axis(b).periodic())
      throw std::invalid_argument(
          "the Fourier window solve needs periodic axes; axis " +
          std::to_string(b) + " is an interval");
  if (h.rows() != K || h.cols() != K)
    throw std::invalid_argument("the Fourier window solve: a Hessian of " +
                                std::to_string(K) + " × " + std::to_string(K) +
                                " expected");
  Impl& s = *impl_;
  const auto& D = dt.base();
  s.nt = dt.points();
  s.n = grid.points();
  s.m = m;
  s.block = (s.nt + 2) * m;
  s.dt = D.dt();
  const int nt = s.nt, M = s.block;
  const double w = grid.NormWeight(0);
  const Eigen::MatrixXd Dm = D.DenseD();
  Eigen::MatrixXd Dbar = Dm;
  Dbar(0, 0) += dt.penalty();
  std::vector<std::vector<Complex>> symbols;
  for (int b = 0; b < d; ++b) symbols.push_back(Symbols(grid.axis(b)));
  auto constraint = [&](int a) { return (constraints >> a) & 1u; };
  s.cod.resize(s.n);
  s.scale.resize(s.n);
  Eigen::MatrixXcd P(nt * K, nt * m), J(M, M);
  for (int k = 0; k < s.n; ++k) {
    // P: the density's arguments at each node from the mode's φ̂.
    P.setZero();
    for (int i = 0; i < nt; ++i)
      for (int a = 0; a < m; ++a) {
        P(i * K + a, i * m + a) = 1;
        for (int l = 0; l < nt; ++l) P(i * K + m + a, l * m + a) = Dbar(i, l);
        for (int b = 0; b < d; ++b)
          P(i * K + (2 + b) * m + a, i * m + a) =
              symbols[b][grid.Coordinate(k, b)];
      }
    Eigen::MatrixXcd WH = Eigen::MatrixXcd::Zero(nt * K, nt * K);
    for (int i = 0; i < nt; ++i)
      WH.block(i * K, i * K, K, K) = (w * D.NormWeight(i)) * h;
    J.setZero();
    J.topLeftCorner(nt * m, nt * m) = P.adjoint() * WH * P;
    for (int a = 0; a < m; ++a) {
      const int l3 = nt * m + a, l4 = (nt + 1) * m + a;
      J((nt - 1) * m + a, l3) += w;
      for (int l = 0; l < nt; ++l) J(l * m + a, l4) += w * Dm(nt - 1, l);
      if (constraint(a)) {
        J(l3, l3) = 1;
        J(l4, l4) = 1;
        continue;
      }
      J(l3, a) = 1;
      for (int l = 0; l < nt; ++l) J(l4, l * m + a) = Dm(0, l);
    }
    Eigen::VectorXd r(M);
    for (int row = 0; row < M; ++row) {
      const double big = J.row(row).cwiseAbs().maxCoeff();
      r[row] = big > 0 ? 1 / big : 1;
    }
    s.scale[k] = r;
    s.cod[k].setThreshold(rank_threshold);
    s.cod[k].compute(r.asDiagonal() * J);
    s.nullity += M - int(s.cod[k].rank());
  }
  // One transform per position of a point's block, over the grid (FFTW's
  // first dimension varies slowest: the grid's last axis).
  std::vector<int> dims(d);
  for (int b = 0; b < d; ++b) dims[b] = grid.points(d - 1 - b);
  s.data = fftw_alloc_complex(std::size_t(s.n) * M);
  s.forward =
      fftw_plan_many_dft(d, dims.data(), M, s.data, nullptr, M, 1, s.data,
                         nullptr, M, 1, FFTW_FORWARD, FFTW_ESTIMATE);
  s.backward =
      fftw_plan_many_dft(d, dims.data(), M, s.data, nullptr, M, 1, s.data,
                         nullptr, M, 1, FFTW_BACKWARD, FFTW_ESTIMATE);
}

FourierWindowSolver::~FourierWindowSolver() = default;

void FourierWindowSolver::Solve(double* b) const {
  const Impl& s = *impl_;
  const int M = s.block;
  const std::size_t total = std::size_t(s.n) * M;
  for (std::size_t k = 0; k < total; ++k) {
    s.data[k][0] = b[k];
    s.data[k][1] = 0;
  }
  fftw_execute(s.forward);
  Eigen::VectorXcd rhs(M);
  for (int k = 0; k < s.n; ++k) {
    fftw_complex* at = s.data + std::size_t(k) * M;
    for (int r = 0; r < M; ++r)
      rhs[r] = s.scale[k][r] * Complex(at[r][0], at[r][1]);
    const Eigen::VectorXcd z = s.cod[k].solve(rhs);
    for (int r = 0; r < M; ++r) {
      at[r][0] = z[r].real();
      at[r][1] = z[r].imag();
    }
  }
  fftw_execute(s.backward);
  for (std::size_t k = 0; k < total; ++k) b[k] = s.data[k][0] / s.n;
}

int FourierWindowSolver::nullity() const { return impl_->nullity; }
int FourierWindowSolver::size() const { return impl_->n * impl_->block; }
int FourierWindowSolver::time_points() const { return impl_->nt; }
double FourierWindowSolver::dt() const { return impl_->dt; }

}  // namespace vivp::spacetime
