// Template definitions of Operator (operator.h); not included directly.
#pragma once

#include <stdexcept>
#include <string>

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
  for (const Rational& w : table.norm_weights) weights_.push_back(w.As<Real>());
  for (const Rational& c : table.interior_stencil)
    interior_.push_back(c.As<Real>());
  for (int i = 0; i < table.boundary_rows(); ++i) {
    const auto& src = table.boundary_block[i];
    std::vector<Real> l, r(src.size());
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
  for (int i = 0; i < r; ++i) out[i] = ApplyRow(i, u.data());
  const int w = static_cast<int>(interior_.size());
  for (int i = r; i < n_ - r; ++i) {
    const T* ui = u.data() + (i - half_width_);
    T acc = Lift<T>(Real(0));
    for (int j = 0; j < w; ++j)
      if (interior_[j] != Real(0)) AddScaled(acc, interior_[j], ui[j]);
    out[i] = Scaled(inv_dt_, acc);
  }
  for (int i = n_ - r; i < n_; ++i) out[i] = ApplyRow(i, u.data());
}

template <class Real>
template <class T>
void Operator<Real>::ApplyTranspose(std::span<const T> u,
                                    std::span<T> out) const {
  CheckSize(u.size(), out.size());
  // Scatter each row i of D into the columns it touches: out += u_i * D[i][:].
  for (int j = 0; j < n_; ++j) out[j] = Lift<T>(Real(0));
  for (int i = 0; i < n_; ++i) {
    const Row rw = row(i);
    const T ui = Scaled(inv_dt_, u[i]);
    for (std::size_t j = 0; j < rw.coeffs.size(); ++j)
      if (rw.coeffs[j] != Real(0)) AddScaled(out[rw.first + j], rw.coeffs[j], ui);
  }
}

template <class Real>
template <class T>
T Operator<Real>::Integrate(std::span<const T> u) const {
  CheckSize(u.size(), u.size());
  T acc = Lift<T>(Real(0));
  for (int i = 0; i < n_; ++i) AddScaled(acc, NormWeight(i), u[i]);
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
