// An SBP first-derivative operator on a uniform time grid, stored as stencils
// (or one spectral element, lobatto.h, on its Gauss–Lobatto nodes).
//
//   auto D = vivp::sbp::MakeOperator<double>("sbp42", 64, 0.0, 1.0);
//   D.Apply(x, dx);          // dx = D x, O(N), any scalar (double, Jets, ...)
//   D.ApplyTranspose(y, z);  // z = D^T y, O(N)
//   D.Integrate(f);          // 1^T H f, the SBP quadrature
//
// D = H^{-1} Q with H diagonal positive and Q + Q^T = B = diag(-1, 0, ..., 1),
// so H D + D^T H = B (the discrete integration by parts).
//
// The operator never holds a matrix: a row is a first column plus a span of
// coefficients per unit dt (left closure, interior stencil, or the mirrored
// right closure). SparseD()/DenseD() export matrices for analysis only.
//
// Warnings:
//  1. Coefficients are per unit dt; every apply multiplies by 1/dt once per
//     row, after summing, so a constant is annihilated to round-off.
//  2. The Real parameter is the floating-point type at the bottom of every
//     scalar the operator is applied to: Operator<double> applies to double and
//     ceres::Jet<double, N> (nested too), Operator<long double> to long double.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/autodiff/scalar.h"
#include "core/sbp/coefficients.h"

namespace vivp::sbp {

// Throws std::invalid_argument unless t_end > t_start, both finite: the
// interval of an operator (MakeOperator, Operator::Retime).
template <class Real>
void CheckInterval(Real t_start, Real t_end) {
  if (!std::isfinite(static_cast<long double>(t_start)) ||
      !std::isfinite(static_cast<long double>(t_end)) || !(t_end > t_start)) {
    std::ostringstream msg;
    msg << "time interval [" << t_start << ", " << t_end
        << "] is invalid; need finite values with t_end > t_start";
    throw std::invalid_argument(msg.str());
  }
}

template <class Real>
class Operator {
 public:
  // Row i of D (per unit dt): D[i][first + j] = coeffs[j].
  struct Row {
    int first;
    std::span<const Real> coeffs;
  };

  // Use MakeOperator (builder.h), which validates its arguments.
  Operator(const Coefficients& table, int points, Real t_start, Real t_end);

  std::string_view name() const { return table_->name; }
  std::string_view citation() const { return table_->citation; }
  int interior_order() const { return table_->interior_order; }
  int boundary_order() const { return table_->boundary_order; }
  int min_points() const { return table_->min_points; }
  int boundary_rows() const { return table_->boundary_rows(); }
  const Coefficients& table() const { return *table_; }

  int points() const { return n_; }
  Real t_start() const { return t_start_; }
  Real t_end() const { return t_end_; }
  Real dt() const { return dt_; }
  Real inv_dt() const { return inv_dt_; }
  // D[i][j] including 1/dt (zero outside row i's stencil).
  Real Entry(int i, int j) const {
    const Row rw = row(i);
    const int k = j - rw.first;
    if (k < 0 || k >= static_cast<int>(rw.coeffs.size())) return Real(0);
    return rw.coeffs[k] * inv_dt_;
  }
  // Node i's time: uniform, or at a spectral element's node offsets.
  Real t(int i) const {
    return t_start_ +
           dt_ * (offsets_.empty() ? static_cast<Real>(i) : offsets_[i]);
  }
  // The same operator on [t_start, t_end]: the coefficients are per unit
  // step, so only the times change, computed as the constructor computes
  // them (the same bits as an operator built anew). A march under error
  // control moves its window's operator to every new step; building it
  // from the table each time was 4 % of a march (Kepler e = 0.9, SBP84,
  // callgrind). Throws std::invalid_argument unless t_end > t_start, both
  // finite.
  void Retime(Real t_start, Real t_end) {
    CheckInterval(t_start, t_end);
    t_start_ = t_start;
    t_end_ = t_end;
    dt_ = (t_end - t_start) / static_cast<Real>(n_ - 1);
    inv_dt_ = static_cast<Real>(n_ - 1) / (t_end - t_start);
  }
  std::vector<Real> Grid() const;

  // Largest |j - i| over the nonzero entries D[i][j].
  int Bandwidth() const { return bandwidth_; }

  Row row(int i) const {
    const int r = boundary_rows();
    if (i < r) return {0, left_[i]};
    if (i >= n_ - r) {
      const auto& c = right_[n_ - 1 - i];
      return {n_ - static_cast<int>(c.size()), c};
    }
    return {i - half_width_, interior_};
  }

  // H_ii, including dt.
  Real NormWeight(int i) const {
    const int r = static_cast<int>(weights_.size());
    if (i < r) return dt_ * weights_[i];
    if (i >= n_ - r) return dt_ * weights_[n_ - 1 - i];
    return dt_;
  }

  // (D u)_i; u points at all N values.
  //
  // Every row annihilates constants (its exact coefficients sum to zero), so
  // it is evaluated on differences, Σ_j c_j (u_j − u_i): neighbouring values
  // of a smooth u subtract exactly (Sterbenz), the round-off scales with the
  // variation of u instead of |u|/dt, and D·1 = 0 holds exactly in floating
  // point although the rounded coefficients need not sum to zero. At
  // Nt = 65536 this is what keeps free fall at |x_N − 0.8| ~ 1e-15
  // (docs/method.md §6: the spurious constant force).
  template <class T>
  T ApplyRow(int i, const T* u) const {
    const int r = boundary_rows();
    if (i < r) return ClosureRow(i, i, u);
    if (i >= n_ - r) return ClosureRow(i - (n_ - 2 * r), i, u);
    const Row rw = row(i);
    const T& ref = u[i];
    T acc = autodiff::Lift<T>(Real(0));
    for (std::size_t j = 0; j < rw.coeffs.size(); ++j)
      if (rw.coeffs[j] != Real(0))
        autodiff::AddScaled(acc, rw.coeffs[j], T(u[rw.first + j] - ref));
    return autodiff::Scaled(inv_dt_, acc);
  }

  template <class T>
  void Apply(std::span<const T> u, std::span<T> out) const;
  template <class T>
  void ApplyTranspose(std::span<const T> u, std::span<T> out) const;
  template <class T>
  std::vector<T> Apply(const std::vector<T>& u) const {
    std::vector<T> out(u.size());
    Apply(std::span<const T>(u), std::span<T>(out));
    return out;
  }
  template <class T>
  std::vector<T> ApplyTranspose(const std::vector<T>& u) const {
    std::vector<T> out(u.size());
    ApplyTranspose(std::span<const T>(u), std::span<T>(out));
    return out;
  }

  // 1^T H u.
  template <class T>
  T Integrate(std::span<const T> u) const;

  Eigen::SparseMatrix<Real> SparseD() const;
  Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic> DenseD() const;
  Eigen::Matrix<Real, Eigen::Dynamic, 1> NormDiagonal() const;

 private:
  void CheckSize(std::size_t in, std::size_t out) const;

  // Row i of a closure, the k-th of the 2r closure rows (left rows first,
  // then the right ones top to bottom): ApplyRow's sum over the row's
  // nonzero entries in the same order, read from the flat lists below.
  template <class T>
  T ClosureRow(int k, int i, const T* u) const {
    const T& ref = u[i];
    T acc = autodiff::Lift<T>(Real(0));
    for (int e = closure_start_[k]; e < closure_start_[k + 1]; ++e)
      autodiff::AddScaled(acc, closure_coeff_[e], T(u[closure_col_[e]] - ref));
    return autodiff::Scaled(inv_dt_, acc);
  }

  const Coefficients* table_;
  int n_;
  Real t_start_, t_end_, dt_, inv_dt_;
  int half_width_;
  int bandwidth_;
  std::vector<Real> weights_;
  std::vector<Real> offsets_;  // node positions per unit dt (elements only)
  std::vector<std::vector<Real>> left_;   // rows 0..r-1
  std::vector<std::vector<Real>> right_;  // right_[i] is row N-1-i
  std::vector<Real> interior_;
  // The closures' nonzero entries with their columns, row k's at
  // [closure_start_[k], closure_start_[k + 1]). A window of 48 points under
  // SBP84 has 16 closure rows of up to 12 entries, more work than its 32
  // interior rows: kept flat, without the zeros of the published blocks, a
  // row is read without a test per coefficient (with the interior's sums
  // vectorized, Apply takes 31 % fewer instructions; docs/performance.md §3).
  std::vector<int> closure_start_, closure_col_;
  std::vector<Real> closure_coeff_;
  // The same closures as dense blocks, column-major (column j of the left
  // block at [j·r, (j + 1)·r), zeros where a row has no entry), for Apply on
  // plain numbers: the sums then run column by column for all r rows at
  // once, each row's terms still added in the order of its columns, so the
  // bits are ClosureRow's, and the loop over the rows vectorizes. A spectral
  // element is nothing but closure rows (lgl8: 4 + 4 dense rows of 8): its
  // Apply took 650 instructions a row at a time, 440 as blocks, and a
  // residual applies D about five times (v = D̄x̄ and D̄ᵀHw per coordinate;
  // docs/performance.md §9).
  int left_width_ = 0, right_width_ = 0;
  std::vector<Real> left_block_, right_block_;
  void ApplyClosureBlocks(const Real* u, Real* out) const;
};

}  // namespace vivp::sbp

#include "core/sbp/operator_impl.h"
