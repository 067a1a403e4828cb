#include "solvers/spacetime/fourier_solver.h"

#include <fftw3.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vivp::spacetime {

using Complex = std::complex<double>;

struct FourierWindowSolver::Impl {
  int nt = 0, n = 0, m = 0, block = 0, nullity = 0;
  int half = 0;  // wave vectors stored: axis 0 halved (real data)
  double dt = 0;
  std::vector<Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXcd>> cod;
  std::vector<Eigen::VectorXd> scale;  // row equilibration per wave vector
  double* real = nullptr;
  fftw_complex* hat = nullptr;
  fftw_plan forward = nullptr, backward = nullptr;
  ~Impl() {
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    if (real) fftw_free(real);
    if (hat) fftw_free(hat);
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

// The window's node rows for one wave vector (docs/gauge.md §4). With the
// density's arguments at node i written T_x φ̂ times a number c_x (T = I
// and c = 1 for φ, T = D̄ and c = 1 for φ_t, T = I and c = s_b for ∂_bφ),
//
//   w Pᴴ (Hᵗ ⊗ h) P = w Σ_{x,y} (T_xᵀ Hᵗ T_y) ⊗ conj(c_x) c_y h_xy,
//
// four time matrices (Hᵗ, Hᵗ D̄, D̄ᵀHᵗ, D̄ᵀHᵗD̄) built once for the window,
// each with an m × m coefficient per wave vector.
struct NodeRows {
  Eigen::MatrixXd h, hd, dhd;  // Hᵗ, Hᵗ D̄, D̄ᵀ Hᵗ D̄
  NodeRows(const Eigen::MatrixXd& dbar, const sbp::Operator<double>& D) {
    const int nt = int(dbar.rows());
    h = Eigen::MatrixXd::Zero(nt, nt);
    for (int i = 0; i < nt; ++i) h(i, i) = D.NormWeight(i);
    hd = h * dbar;
    dhd = dbar.transpose() * hd;
  }
  // J's node block += w Σ T ⊗ C for the wave vector with symbols s.
  void Add(const Eigen::MatrixXd& hess, int m, const std::vector<Complex>& s,
           double w, Eigen::MatrixXcd& J) const {
    const int nt = int(h.rows()), d = int(s.size());
    // The arguments without a time derivative: φ and each ∂_bφ.
    std::vector<std::pair<int, Complex>> plain{{0, 1.0}};
    for (int b = 0; b < d; ++b) plain.push_back({(2 + b) * m, s[b]});
    Eigen::MatrixXcd cpp = Eigen::MatrixXcd::Zero(m, m), cpt = cpp, ctp = cpp;
    const Eigen::MatrixXcd ctt = hess.block(m, m, m, m).cast<Complex>();
    for (const auto& [x, cx] : plain) {
      cpt += std::conj(cx) * hess.block(x, m, m, m).cast<Complex>();
      ctp += cx * hess.block(m, x, m, m).cast<Complex>();
      for (const auto& [y, cy] : plain)
        cpp += std::conj(cx) * cy * hess.block(x, y, m, m).cast<Complex>();
    }
    for (int i = 0; i < nt; ++i)
      for (int l = 0; l < nt; ++l)
        J.block(i * m, l * m, m, m) += w * (h(i, l) * cpp + hd(i, l) * cpt +
                                            hd(l, i) * ctp + dhd(i, l) * ctt);
  }
};

// The symbols of wave vector `index` of the half spectrum (axis 0 holds
// N_0/2 + 1 of them, the rest the complex conjugates of those).
std::vector<Complex> SymbolsOf(const std::vector<std::vector<Complex>>& all,
                               int index) {
  const int d = int(all.size()), h0 = int(all[0].size()) / 2 + 1;
  std::vector<Complex> s(d);
  s[0] = all[0][index % h0];
  int rest = index / h0;
  for (int b = 1; b < d; ++b) {
    const int nb = int(all[b].size());
    s[b] = all[b][rest % nb];
    rest /= nb;
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
  s.half = s.n / grid.points(0) * (grid.points(0) / 2 + 1);
  const int nt = s.nt, M = s.block;
  const double w = grid.NormWeight(0);
  const Eigen::MatrixXd Dm = D.DenseD();
  Eigen::MatrixXd Dbar = Dm;
  Dbar(0, 0) += dt.penalty();
  const NodeRows rows(Dbar, D);
  std::vector<std::vector<Complex>> symbols;
  for (int b = 0; b < d; ++b) symbols.push_back(Symbols(grid.axis(b)));
  auto constraint = [&](int a) { return (constraints >> a) & 1u; };
  s.cod.resize(s.half);
  s.scale.resize(s.half);
  Eigen::MatrixXcd J(M, M);
  for (int k = 0; k < s.half; ++k) {
    J.setZero();
    rows.Add(h, m, SymbolsOf(symbols, k), w, J);
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
    // The wave vectors not stored are the conjugates of stored ones, with
    // conjugate systems of the same rank.
    const int q0 = k % (grid.points(0) / 2 + 1);
    const bool self = q0 == 0 || 2 * q0 == grid.points(0);
    s.nullity += (self ? 1 : 2) * (M - int(s.cod[k].rank()));
  }
  // One real-to-complex transform per position of a point's block, over
  // the grid (FFTW's first dimension varies slowest: the grid's last axis,
  // and its last one, axis 0, is the one halved).
  std::vector<int> dims(d);
  for (int b = 0; b < d; ++b) dims[b] = grid.points(d - 1 - b);
  s.real = fftw_alloc_real(std::size_t(s.n) * M);
  s.hat = fftw_alloc_complex(std::size_t(s.half) * M);
  s.forward = fftw_plan_many_dft_r2c(d, dims.data(), M, s.real, nullptr, M, 1,
                                     s.hat, nullptr, M, 1, FFTW_ESTIMATE);
  s.backward = fftw_plan_many_dft_c2r(d, dims.data(), M, s.hat, nullptr, M, 1,
                                      s.real, nullptr, M, 1, FFTW_ESTIMATE);
}

FourierWindowSolver::~FourierWindowSolver() = default;

void FourierWindowSolver::Solve(double* b) const {
  const Impl& s = *impl_;
  const int M = s.block;
  const std::size_t total = std::size_t(s.n) * M;
  std::copy(b, b + total, s.real);
  fftw_execute(s.forward);
  Eigen::VectorXcd rhs(M);
  for (int k = 0; k < s.half; ++k) {
    fftw_complex* at = s.hat + std::size_t(k) * M;
    for (int r = 0; r < M; ++r)
      rhs[r] = s.scale[k][r] * Complex(at[r][0], at[r][1]);
    const Eigen::VectorXcd z = s.cod[k].solve(rhs);
    for (int r = 0; r < M; ++r) {
      at[r][0] = z[r].real();
      at[r][1] = z[r].imag();
    }
  }
  fftw_execute(s.backward);
  for (std::size_t k = 0; k < total; ++k) b[k] = s.real[k] / s.n;
}

int FourierWindowSolver::nullity() const { return impl_->nullity; }
int FourierWindowSolver::size() const { return impl_->n * impl_->block; }
int FourierWindowSolver::time_points() const { return impl_->nt; }
double FourierWindowSolver::dt() const { return impl_->dt; }

}  // namespace vivp::spacetime
