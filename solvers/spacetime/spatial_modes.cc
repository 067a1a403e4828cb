#include "solvers/spacetime/spatial_modes.h"

#include <fftw3.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace vivp::spacetime {

// FFTW's plans for one (stride, rows): a forward and a backward batch of
// `rows` real transforms of length n, element stride `stride`, one row after
// the other (distance 1), in place. Planned with FFTW_ESTIMATE: the plan, and
// so the rounding of every transform, does not depend on timings (a measured
// plan may differ from run to run, and a march must be reproducible to the
// bit). A plan made on an aligned buffer is used for data of the same
// alignment, an unaligned one otherwise.
struct SpatialModes::Fft {
  int n = 0, stride = -1, rows = -1;
  fftw_plan forward[2] = {nullptr, nullptr}, backward[2] = {nullptr, nullptr};
  int alignment = 0;  // fftw_alignment_of of the aligned plans' buffer

  ~Fft() { Clear(); }
  void Clear() {
    for (auto* p : {&forward[0], &forward[1], &backward[0], &backward[1]})
      if (*p) {
        fftw_destroy_plan(*p);
        *p = nullptr;
      }
  }
  // The plans for data; `kind` 0 forward, 1 backward.
  fftw_plan Plan(double* data, int s, int r, int kind) {
    if (s != stride || r != rows) {
      Clear();
      stride = s;
      rows = r;
    }
    const bool aligned = fftw_alignment_of(data) == 0;
    fftw_plan& p = kind == 0 ? forward[aligned] : backward[aligned];
    if (!p) {
      // Planning may overwrite its array: plan on scratch of the same shape
      // and alignment class.
      const std::size_t size = std::size_t(n) * s + 1;
      double* scratch = fftw_alloc_real(size);
      double* at = aligned ? scratch : scratch + 1;
      const fftw_r2r_kind k = kind == 0 ? FFTW_R2HC : FFTW_HC2R;
      p = fftw_plan_many_r2r(1, &n, r, at, nullptr, s, 1, at, nullptr, s, 1, &k,
                             FFTW_ESTIMATE | (aligned ? 0 : FFTW_UNALIGNED));
      fftw_free(scratch);
      if (!p) throw std::runtime_error("FFTW could not plan the transform");
    }
    return p;
  }
};

SpatialModes::SpatialModes(const sbp::SpaceDerivative<double>& dx, int first,
                           int count)
    : first_(first), count_(count) {
  const int n = dx.points();
  if (dx.periodic()) {
    if (first != 0 || count != n)
      throw std::invalid_argument(
          "spatial modes: the periodic circle keeps every point");
    const auto& p = *dx.periodic_operator();
    fft_ = std::make_unique<Fft>();
    fft_->n = n;
    eigenvalues_.resize(n);
    system_of_.resize(n);
    forward_scale_.resize(n);
    inverse_scale_.resize(n);
    // Halfcomplex slot q holds Re of mode q (q ≤ n/2) or Im of mode n − q.
    for (int q = 0; q < n; ++q) {
      const int k = q <= n / 2 ? q : n - q;
      const double theta = 2 * std::numbers::pi * k / n;
      double sigma = 0;
      for (int l = 1; l <= p.half_width(); ++l)
        sigma += 2 * p.coefficient(l) * std::sin(l * theta);
      eigenvalues_[q] = sigma * sigma * p.inv_dx() * p.inv_dx();
      system_of_[q] = k;
      // ‖column‖² of the unnormalized real Fourier matrix, and the weight of
      // the column in FFTW's inverse: their product is n for every q.
      const bool single = k == 0 || 2 * k == n;
      const double norm2 = single ? n : 0.5 * n;
      forward_scale_[q] = 1 / std::sqrt(p.dx() * norm2);
      inverse_scale_[q] = forward_scale_[q] / (single ? 1.0 : 2.0);
    }
    distinct_ = n / 2 + 1;
    return;
  }
  if (first < 0 || count < 1 || first + count > n)
    throw std::invalid_argument("spatial modes: points [" +
                                std::to_string(first) + ", " +
                                std::to_string(first + count) +
                                ") outside the grid of " + std::to_string(n));
  // S = D_xᵀ H_x D_x column by column, through the SBP property
  // (core/sbp/space.h): S e_l = D_xᵀ H (D_x e_l).
  stiffness_.setZero(n, n);
  std::vector<double> e(n, 0.0), de(n), scratch(n), col(n);
  for (int l = 0; l < n; ++l) {
    e[l] = 1;
    dx.Apply<double>(e, de);
    std::fill(col.begin(), col.end(), 0.0);
    dx.AddTransposeH<double>(de, scratch, col);
    for (int j = 0; j < n; ++j) stiffness_(j, l) = col[j];
    e[l] = 0;
  }
  // Symmetric in exact arithmetic; its rounding is not.
  stiffness_ = (0.5 * (stiffness_ + stiffness_.transpose())).eval();
  Eigen::VectorXd h_half(count);
  for (int q = 0; q < count; ++q)
    h_half[q] = 1 / std::sqrt(dx.NormWeight(first + q));
  const Eigen::MatrixXd a = h_half.asDiagonal() *
                            stiffness_.block(first, first, count, count) *
                            h_half.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(a);
  if (eig.info() != Eigen::Success)
    throw std::runtime_error("spatial modes: the eigensolver did not converge");
  basis_ = h_half.asDiagonal() * eig.eigenvectors();
  eigenvalues_.resize(count);
  system_of_.resize(count);
  for (int q = 0; q < count; ++q) {
    // S is positive semidefinite: a slightly negative eigenvalue (the
    // constant mode of the natural condition) is its round-off.
    eigenvalues_[q] = std::max(eig.eigenvalues()[q], 0.0);
    system_of_[q] = q;
  }
  distinct_ = count;
}

SpatialModes::~SpatialModes() = default;
SpatialModes::SpatialModes(SpatialModes&&) noexcept = default;
SpatialModes& SpatialModes::operator=(SpatialModes&&) noexcept = default;

void SpatialModes::Forward(double* data, int stride, int rows) const {
  if (fft_) {
    fftw_execute_r2r(fft_->Plan(data, stride, rows, 0), data, data);
    for (int q = 0; q < count_; ++q) {
      double* b = data + std::size_t(q) * stride;
      for (int r = 0; r < rows; ++r) b[r] *= forward_scale_[q];
    }
    return;
  }
  // The kept points' rows as a rows × count matrix with leading dimension
  // stride.
  Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>> x(
      data + std::size_t(first_) * stride, rows, count_,
      Eigen::OuterStride<>(stride));
  work_.noalias() = x * basis_;
  x = work_;
}

void SpatialModes::Inverse(double* data, int stride, int rows) const {
  if (fft_) {
    for (int q = 0; q < count_; ++q) {
      double* b = data + std::size_t(q) * stride;
      for (int r = 0; r < rows; ++r) b[r] *= inverse_scale_[q];
    }
    fftw_execute_r2r(fft_->Plan(data, stride, rows, 1), data, data);
    return;
  }
  Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>> x(
      data + std::size_t(first_) * stride, rows, count_,
      Eigen::OuterStride<>(stride));
  work_.noalias() = x * basis_.transpose();
  x = work_;
}

}  // namespace vivp::spacetime
