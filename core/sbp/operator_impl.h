// Template definitions of Operator (operator.h); not included directly.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace vivp::sbp {

template <class Real>
Operator<Real>::Operator(const Coefficients& table, int points, Real t_start,
                         Real t_end)
    : table_(&table),
      n_(points),
      t_start_(t_start),
      t_end_(t_end),
      dt_((t_end - t_start) / static_cast<Real>(points - 1)),
      inv_dt_(static_cast<Real>(points - 1) / (t_end - t_start)),
      half_width_(table.half_width()),
      bandwidth_(table.half_width()) {
  // Every array sized before it is filled: a march builds an operator per
  // window length, and growing them one push at a time took 77 allocations
  // per SBP84 operator (callgrind).
  weights_.reserve(table.norm_weights.size());
  interior_.reserve(table.interior_stencil.size());
  left_.reserve(std::size_t(table.boundary_rows()));
  right_.reserve(std::size_t(table.boundary_rows()));
  std::size_t closure_entries = 0;
  for (const auto& src : table.boundary_block) closure_entries += src.size();
  closure_start_.reserve(2 * std::size_t(table.boundary_rows()) + 1);
  closure_col_.reserve(2 * closure_entries);
  closure_coeff_.reserve(2 * closure_entries);
  for (const Rational& w : table.norm_weights) weights_.push_back(w.As<Real>());
  for (const Rational& o : table.node_offsets) offsets_.push_back(o.As<Real>());
  for (const Rational& c : table.interior_stencil)
    interior_.push_back(c.As<Real>());
  // Apply evaluates the interior as Σ_k c_k (u_{i+k} − u_{i−k}).
  const auto& st = table.interior_stencil;
  for (int k = 0; k <= half_width_; ++k) {
    const Rational& a = st[half_width_ + k];
    const Rational& b = st[half_width_ - k];
    if (a.num * b.den != -b.num * a.den)
      throw std::logic_error(std::string(table.name) +
                             ": interior stencil is not antisymmetric");
  }
  for (int i = 0; i < table.boundary_rows(); ++i) {
    const auto& src = table.boundary_block[i];
    std::vector<Real> l, r(src.size());
    l.reserve(src.size());
    const int len = static_cast<int>(src.size());
    for (int j = 0; j < len; ++j) {
      l.push_back(src[j].As<Real>());
      // Row N-1-i, column N-len+j holds -D[i][len-1-j].
      r[j] = -src[len - 1 - j].As<Real>();
      bandwidth_ = std::max(bandwidth_, std::abs(j - i));
    }
    left_.push_back(std::move(l));
    right_.push_back(std::move(r));
  }
  if (table.max_points > 0 && points != table.max_points)
    throw std::invalid_argument(
        std::string(table.name) + " is one spectral element of exactly " +
        std::to_string(table.max_points) + " points, got " +
        std::to_string(points) + "; build operators with MakeOperator");
  const int rows = table.boundary_rows();
  if (points < 2 * rows)
    throw std::invalid_argument(
        std::string(table.name) + " needs at least " +
        std::to_string(2 * rows) + " points for its two closures, got " +
        std::to_string(points) + "; build operators with MakeOperator");
  closure_start_.push_back(0);
  for (int k = 0; k < 2 * rows; ++k) {
    const int i = k < rows ? k : n_ - 2 * rows + k;
    const Row rw = row(i);
    for (std::size_t j = 0; j < rw.coeffs.size(); ++j)
      if (rw.coeffs[j] != Real(0)) {
        closure_col_.push_back(rw.first + static_cast<int>(j));
        closure_coeff_.push_back(rw.coeffs[j]);
      }
    closure_start_.push_back(static_cast<int>(closure_col_.size()));
  }
  for (int k = 0; k < rows; ++k) {
    left_width_ = std::max(left_width_, static_cast<int>(left_[k].size()));
    right_width_ = std::max(right_width_, static_cast<int>(right_[k].size()));
  }
  left_block_.assign(std::size_t(rows) * left_width_, Real(0));
  right_block_.assign(std::size_t(rows) * right_width_, Real(0));
  for (int k = 0; k < rows; ++k) {
    // Left row k: columns 0 … size − 1. Right block row k is row
    // n − rows + k, whose entries end at column n − 1.
    for (std::size_t j = 0; j < left_[k].size(); ++j)
      left_block_[j * rows + k] = left_[k][j];
    const auto& c = right_[rows - 1 - k];
    const int skip = right_width_ - static_cast<int>(c.size());
    for (std::size_t j = 0; j < c.size(); ++j)
      right_block_[(skip + j) * rows + k] = c[j];
  }
}

namespace detail {

// out_k = s·Σ_j c_(j,k) (u_j − ui_k), k < R, for one closure block
// (column-major c, `width` columns) of R rows, R known at compile time: the
// rows' accumulators in registers, and the loop over them vectorizes.
template <int R, class Real>
void SweepClosureBlock(const Real* c, int width, const Real* uc, const Real* ui,
                       Real s, Real* out) {
  Real acc[R], at[R];
  for (int k = 0; k < R; ++k) {
    acc[k] = Real(0);
    at[k] = ui[k];
  }
  for (int j = 0; j < width; ++j) {
    const Real uj = uc[j];
    for (int k = 0; k < R; ++k) acc[k] += c[j * R + k] * (uj - at[k]);
  }
  for (int k = 0; k < R; ++k) out[k] = s * acc[k];
}

}  // namespace detail

template <class Real>
void Operator<Real>::ApplyClosureBlocks(const Real* u, Real* out) const {
  // A zero entry adds 0·(u_j − u_i) = ±0, which leaves every nonzero sum's
  // bits as ClosureRow's (which skips it). The closures have 4, 6 or 8 rows
  // (SBP42 … SBP84, lgl8 … lgl16), the counts Apply sends here (any other
  // is summed a row at a time, ClosureRow).
  const int r = boundary_rows();
  const auto sweep = [&](const Real* c, int width, const Real* uc,
                         const Real* ui, Real* o) {
    switch (r) {
      case 4:
        return detail::SweepClosureBlock<4>(c, width, uc, ui, inv_dt_, o);
      case 6:
        return detail::SweepClosureBlock<6>(c, width, uc, ui, inv_dt_, o);
      case 8:
        return detail::SweepClosureBlock<8>(c, width, uc, ui, inv_dt_, o);
    }
  };
  sweep(left_block_.data(), left_width_, u, u, out);
  sweep(right_block_.data(), right_width_, u + (n_ - right_width_),
        u + (n_ - r), out + (n_ - r));
}

template <class Real>
std::vector<Real> Operator<Real>::Grid() const {
  std::vector<Real> g(n_);
  for (int i = 0; i < n_; ++i) g[i] = t(i);
  return g;
}

template <class Real>
void Operator<Real>::CheckSize(std::size_t in, std::size_t out) const {
  if (in != static_cast<std::size_t>(n_) || out != in)
    throw std::invalid_argument(
        std::string(name()) + " operator on " + std::to_string(n_) +
        " points applied to vectors of length " + std::to_string(in) + " -> " +
        std::to_string(out) + "; both must have length " + std::to_string(n_));
}

template <class Real>
template <class T>
void Operator<Real>::Apply(std::span<const T> u, std::span<T> out) const {
  CheckSize(u.size(), out.size());
  const int r = boundary_rows();
  // Closures on plain numbers as blocks (ApplyClosureBlocks) where they
  // have 4, 6 or 8 rows, else a row at a time.
  bool blocks = false;
  if constexpr (std::is_same_v<T, Real>) blocks = r == 4 || r == 6 || r == 8;
  if (!blocks)
    for (int i = 0; i < r; ++i) out[i] = ClosureRow(i, i, u.data());
  // Interior: the central stencil is antisymmetric (checked in the
  // constructor), Σ_k c_k (u_{i+k} − u_{i−k}), the difference form of
  // ApplyRow without the reference subtraction.
  // The sums run over k for all rows at once (k outer), each row's terms
  // added in the order of k as before, so the bits are those of a row at a
  // time; the rows are independent, and the loop over them vectorizes.
  const T* uu = u.data();
  T* o = out.data();
  for (int i = r; i < n_ - r; ++i) o[i] = autodiff::Lift<T>(Real(0));
  for (int k = 1; k <= half_width_; ++k) {
    const Real c = interior_[half_width_ + k];
    for (int i = r; i < n_ - r; ++i)
      autodiff::AddScaled(o[i], c, T(uu[i + k] - uu[i - k]));
  }
  for (int i = r; i < n_ - r; ++i) o[i] = autodiff::Scaled(inv_dt_, o[i]);
  if (blocks) {
    if constexpr (std::is_same_v<T, Real>) ApplyClosureBlocks(uu, o);
  } else {
    for (int i = n_ - r; i < n_; ++i)
      out[i] = ClosureRow(i - (n_ - 2 * r), i, u.data());
  }
}

template <class Real>
template <class T>
void Operator<Real>::ApplyTranspose(std::span<const T> u,
                                    std::span<T> out) const {
  CheckSize(u.size(), out.size());
  // Through the SBP property H D + Dᵀ H = B: Dᵀ u = B H⁻¹u − H D H⁻¹u.
  // A scatter of the columns of D would sum terms of size |u|/dt that cancel
  // to the result; this form reuses the difference evaluation of D (ApplyRow)
  // and so inherits its exact annihilation of constants: DᵀHD·1 = 0 exactly,
  // which an assembled DᵀHD does not give (docs/method.md §6).
  std::vector<T> g(u.size());
  for (int i = 0; i < n_; ++i)
    g[i] = autodiff::Scaled(Real(1) / NormWeight(i), u[i]);
  Apply(std::span<const T>(g), out);
  for (int i = 0; i < n_; ++i)
    out[i] = autodiff::Scaled(-NormWeight(i), out[i]);
  out[0] = out[0] - g[0];
  out[n_ - 1] = out[n_ - 1] + g[n_ - 1];
}

template <class Real>
template <class T>
T Operator<Real>::Integrate(std::span<const T> u) const {
  CheckSize(u.size(), u.size());
  T acc = autodiff::Lift<T>(Real(0));
  for (int i = 0; i < n_; ++i) autodiff::AddScaled(acc, NormWeight(i), u[i]);
  return acc;
}

template <class Real>
Eigen::SparseMatrix<Real> Operator<Real>::SparseD() const {
  std::vector<Eigen::Triplet<Real>> entries;
  entries.reserve(static_cast<std::size_t>(n_) * interior_.size());
  for (int i = 0; i < n_; ++i) {
    const Row rw = row(i);
    for (std::size_t j = 0; j < rw.coeffs.size(); ++j)
      if (rw.coeffs[j] != Real(0))
        entries.emplace_back(i, rw.first + static_cast<int>(j),
                             rw.coeffs[j] * inv_dt_);
  }
  Eigen::SparseMatrix<Real> d(n_, n_);
  d.setFromTriplets(entries.begin(), entries.end());
  return d;
}

template <class Real>
Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic> Operator<Real>::DenseD()
    const {
  return Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>(SparseD());
}

template <class Real>
Eigen::Matrix<Real, Eigen::Dynamic, 1> Operator<Real>::NormDiagonal() const {
  Eigen::Matrix<Real, Eigen::Dynamic, 1> h(n_);
  for (int i = 0; i < n_; ++i) h[i] = NormWeight(i);
  return h;
}

}  // namespace vivp::sbp
