// The reduced critical-point equations of the doubled action of a field in
// 1+1 dimensions (docs/fields.md): the point-mechanics construction of
// reduced_system.h with one path per spatial point, coupled through the
// spatial derivative. On an Nt × Nx grid, with L(φ, φ_t, φ_x) the density,
//
//   S = Σ_ij Hᵗ_i Hˣ_j [L(φ1, D̄_t φ1, D_x φ1) − L(φ2, D̄_t φ2, D_x φ2)]
//       + Σ_j Hˣ_j [λ1·(φ1(0) − φ₀) + λ2·((D_t φ1)(0) − π₀)
//                   + λ3·(φ1(N) − φ2(N)) + λ4·((D_t φ1)(N) − (D_t φ2)(N))]_j
//
// where the regularized time operator D̄_t (affine coordinates, its shift
// φ₀(x_j)) acts per spatial point and D_x per time slice. In φ₊, φ₋ the
// solution has φ₋ = λ1 = λ2 = 0 and what remains, at φ₋ = 0, is
//
//   ∂S/∂φ₋(i, j) = Hᵗ_i Hˣ_j ∂L/∂φ + Hˣ_j (D̄ᵀ_t Hᵗ ∂L/∂φ_t)_i
//                 + Hᵗ_i (Dᵀ_x Hˣ ∂L/∂φ_x)_j + Hˣ_j (λ3 δ_{i,N} + λ4 D_{N,i})
//
// plus the initial-data rows. The multipliers carry Hˣ_j so that, as in
// point mechanics, λ3 = −∂L/∂φ_t at t = T (a momentum density).
//
// Unknowns, space-major: the block of spatial point j holds φ₊(i, j, a) at
// j·B + i·m + a (i < Nt, m components), then λ3(j, ·) and λ4(j, ·);
// B = (Nt + 2)·m. Rows use the same positions: the node rows, then the
// initial value and initial velocity rows of point j. A time window is then
// banded up to the periodic corners. On an interval, Dirichlet data imposed
// by multipliers append Nt·m unknowns per Dirichlet side after the blocks
// (field_boundary.h).
//
// In d spatial dimensions (a density with kSpaceDim = d on an
// sbp::SpaceGrid of d axes, space_grid.h) j is the grid's flat point index,
// Hˣ_j the product of the axes' weights, the density sees the gradient
// (D_0 φ, …, D_{d−1} φ) and the spatial term is Σ_b Hᵗ_i (D_bᵀ Hˣ
// ∂L/∂(∂_bφ))_j; everything else is as above (d = 1 is the formula above).
//
// The Jacobian is assembled pointwise: at each (i, j) the density sees φ,
// φ_t (row i of D̄_t along the column j) and φ_x (row j of D_x along the slice
// i); its 3m × 3m Hessian from automatic differentiation is chained through
// those rows. Time-neighbour × space-neighbour entries appear only when the
// density couples φ_t and φ_x (none of the shipped densities does).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/field_boundary.h"
#include "core/action/field_faces.h"
#include "core/action/field_point.h"
#include "core/autodiff/pointwise.h"
#include "core/sbp/regularized.h"
#include "core/sbp/space.h"

namespace vivp::action {

template <class Density, class Real = double>
class FieldSystem {
 public:
  static constexpr int m = Density::kDim;
  static constexpr int d = SpaceDimOf<Density>();
  // The density's arguments (φ, φ_t, ∂_0 φ, …, ∂_{d−1} φ).
  static constexpr int K = (2 + d) * m;
  using Scalar = Real;
  using Hessian = Eigen::Matrix<Real, K, K>;

  // phi0, pi0: φ(0, x_j) and φ_t(0, x_j), value j·m + a, on the grid of
  // d axes (space_grid.h; its flat point index j); a density of one spatial
  // dimension may be given its axis alone.
  FieldSystem(const Density& density, const sbp::RegularizedOperator<Real>& dt,
              sbp::SpaceGrid<Real> grid, std::vector<Real> phi0,
              std::vector<Real> pi0)
      : density_(density),
        dt_(dt),
        grid_(std::move(grid)),
        nt_(dt.points()),
        nx_(grid_.points()) {
    if (grid_.dim() != d)
      throw std::invalid_argument("the density has " + std::to_string(d) +
                                  " spatial dimensions, the grid " +
                                  std::to_string(grid_.dim()) + " axes");
    SetInitial(std::move(phi0), std::move(pi0));
    // ∂²L/∂φ_t∂(∇φ)
    couples_t_x_ = !HessianBlockVanishes<m, d * m>(m, 2 * m);
    for (int a = 0; a < m; ++a)
      if (Constraint(a) &&
          !AtGenericPoints<Real, K>(Call(), [a](const auto& h) {
            return h.gradient[m + a] == Real(0) &&
                   h.hessian.row(m + a).cwiseAbs().maxCoeff() == Real(0);
          }))
        throw std::invalid_argument("the density depends on φ_t of component " +
                                    std::to_string(a) +
                                    ", declared in kWithoutTimeDerivative");
  }
  FieldSystem(const Density& density, const sbp::RegularizedOperator<Real>& dt,
              const sbp::SpaceDerivative<Real>& dx, std::vector<Real> phi0,
              std::vector<Real> pi0)
      : FieldSystem(density, dt, sbp::SpaceGrid<Real>(dx), std::move(phi0),
                    std::move(pi0)) {}

  // Component a is not differentiated in time (field_point.h): its λ3 and
  // λ4 rows read λ3 = λ4 = 0, no initial data (docs/gauge.md §2).
  static constexpr bool Constraint(int a) {
    return (ConstraintMaskOf<Density>() >> a) & 1u;
  }
  int time_points() const { return nt_; }
  int space_points() const { return nx_; }
  int block() const { return (nt_ + 2) * m; }
  // The blocks of the spatial points, then the boundary multipliers.
  int size() const { return nx_ * block() + constrained_ * nt_ * m; }
  int Phi(int i, int j, int a) const { return j * block() + i * m + a; }
  int Lambda3(int j, int a) const { return j * block() + nt_ * m + a; }
  int Lambda4(int j, int a) const { return j * block() + (nt_ + 1) * m + a; }
  // The initial-data rows of point j share the multipliers' positions.
  int InitialValueRow(int j, int a) const { return Lambda3(j, a); }
  int InitialVelocityRow(int j, int a) const { return Lambda4(j, a); }
  // Data at side 0 (x_0) or 1 (x_{Nx−1}) (field_boundary.h); values: g or h
  // at the window's nodes, i·m + a.
  void SetBoundary(int side, BoundaryKind kind, std::vector<Real> values) {
    CheckBoundary(*this, side, kind, values.size());
    boundary_[side] = {kind, std::move(values), {}};
    if (kind == BoundaryKind::kNeumann)
      boundary_[side].flux = detail::Flux(*this, boundary_[side].values);
    constrained_ = (boundary_[0].kind == BoundaryKind::kDirichlet) +
                   (boundary_[1].kind == BoundaryKind::kDirichlet);
  }
  const BoundarySide<Real>& boundary(int side) const { return boundary_[side]; }
  // Neumann slopes on a face of an interval axis in d > 1 (field_faces.h):
  // h at (node, face point, component); replaces that face's earlier data.
  void SetFace(int axis, int side, const std::vector<Real>& slopes) {
    std::erase_if(faces_, [&](const auto& f) {
      return f.axis == axis && f.side == side;
    });
    faces_.push_back(MakeFace(*this, axis, side, slopes));
  }
  const std::vector<FaceData<Real>>& faces() const { return faces_; }
  // The Dirichlet multiplier μ_i of a side (field_boundary.h).
  int Mu(int side, int i, int a) const {
    const int slot =
        side == 1 && boundary_[0].kind == BoundaryKind::kDirichlet ? 1 : 0;
    return nx_ * block() + (slot * nt_ + i) * m + a;
  }
  // Whether point j's column is Dirichlet data (field_boundary.h).
  bool Fixed(int j) const {
    return (j == 0 && boundary_[0].kind == BoundaryKind::kDirichlet) ||
           (j == nx_ - 1 && boundary_[1].kind == BoundaryKind::kDirichlet);
  }
  bool couples_time_and_space() const { return couples_t_x_; }
  const sbp::RegularizedOperator<Real>& time_operator() const { return dt_; }
  // The spatial axis of a one-dimensional field (the first axis otherwise),
  // and the grid.
  const sbp::SpaceDerivative<Real>& space_operator() const {
    return grid_.axis(0);
  }
  const sbp::SpaceGrid<Real>& space_grid() const { return grid_; }
  const Density& density() const { return density_; }
  const std::vector<Real>& phi0() const { return phi0_; }
  const std::vector<Real>& pi0() const { return pi0_; }

  // New initial data on the same grid (marching reuses the system).
  void SetInitial(std::vector<Real> phi0, std::vector<Real> pi0) {
    const std::size_t n = static_cast<std::size_t>(nx_) * m;
    if (phi0.size() != n || pi0.size() != n)
      throw std::invalid_argument(
          "initial data: expected " + std::to_string(n) +
          " values of φ and of φ_t (one per spatial point and component), "
          "got " +
          std::to_string(phi0.size()) + " and " + std::to_string(pi0.size()));
    phi0_ = std::move(phi0);
    pi0_ = std::move(pi0);
  }

  // φ, D̄_t φ and ∇φ of the unknowns y on the grid.
  void Fields(const Real* y, FieldValues<Real>& out) const {
    const std::size_t n = static_cast<std::size_t>(nt_) * nx_ * m;
    out.phi.resize(n);
    out.phi_t.resize(n);
    out.phi_x.resize(n * d);
    auto& col = scratch_.col;
    auto& col_t = scratch_.col_t;
    col.resize(nt_);
    col_t.resize(nt_);
    for (int j = 0; j < nx_; ++j)
      for (int a = 0; a < m; ++a) {
        for (int i = 0; i < nt_; ++i) col[i] = y[Phi(i, j, a)];
        dt_.Apply(std::span<const Real>(col), phi0_[j * m + a],
                  std::span<Real>(col_t));
        for (int i = 0; i < nt_; ++i) {
          out.phi[At(i, j, a)] = col[i];
          out.phi_t[At(i, j, a)] = col_t[i];
        }
      }
    auto& row = scratch_.row;
    auto& row_x = scratch_.row_x;
    row.resize(nx_);
    row_x.resize(nx_);
    for (int i = 0; i < nt_; ++i)
      for (int a = 0; a < m; ++a) {
        for (int j = 0; j < nx_; ++j) row[j] = out.phi[At(i, j, a)];
        for (int b = 0; b < d; ++b) {
          grid_.Apply(b, std::span<const Real>(row), std::span<Real>(row_x),
                      scratch_.line);
          for (int j = 0; j < nx_; ++j) out.phi_x[Grad(i, j, b, a)] = row_x[j];
        }
      }
  }

  int At(int i, int j, int a) const { return (i * nx_ + j) * m + a; }
  // ∂_b φ_a at (i, j) in FieldValues::phi_x.
  int Grad(int i, int j, int b, int a) const {
    return ((i * nx_ + j) * d + b) * m + a;
  }

  // The density as a function of z = (φ, φ_t, φ_x).
  auto Call() const {
    return [this](const auto* z) { return density_(z, z + m, z + 2 * m); };
  }
  // Whether the R × C block of the density's Hessian at (row, col) of z is
  // zero (at AtGenericPoints').
  template <int R, int C>
  bool HessianBlockVanishes(int row, int col) const {
    return AtGenericPoints<Real, K>(Call(), [&](const auto& h) {
      return h.hessian.template block<R, C>(row, col).cwiseAbs().maxCoeff() ==
             Real(0);
    });
  }

  // The density's derivatives ∂L/∂(φ, φ_t, φ_x) at grid point (i, j).
  Eigen::Matrix<Real, K, 1> PointGradient(const FieldValues<Real>& v, int i,
                                          int j) const {
    Real z[K];
    Point(v, i, j, z);
    return autodiff::Gradient<Real, K>(Call(), z).second;
  }
  Hessian PointHessian(const FieldValues<Real>& v, int i, int j) const {
    Real z[K];
    Point(v, i, j, z);
    return autodiff::Hessian<Real, K>(Call(), z).hessian;
  }

  void Residual(const Real* y, Real* f) const {
    auto& v = scratch_.values;
    Fields(y, v);
    const std::size_t n = static_cast<std::size_t>(nt_) * nx_ * m;
    auto& g = scratch_.g;  // ∂L/∂φ, ∂L/∂φ_t, ∂L/∂(∇φ), time-major
    g.resize((2 + d) * n);
    for (int i = 0; i < nt_; ++i)
      for (int j = 0; j < nx_; ++j) {
        const auto grad = PointGradient(v, i, j);
        for (int a = 0; a < m; ++a) {
          g[At(i, j, a)] = grad[a];
          g[n + At(i, j, a)] = grad[m + a];
          for (int b = 0; b < d; ++b)
            g[2 * n + Grad(i, j, b, a)] = grad[(2 + b) * m + a];
        }
      }
    const auto& D = dt_.base();
    auto& col = scratch_.col;
    auto& dw = scratch_.col_t;
    col.resize(nt_);
    for (int j = 0; j < nx_; ++j) {
      const Real hx = grid_.NormWeight(j);
      for (int a = 0; a < m; ++a) {
        for (int i = 0; i < nt_; ++i) {
          f[Phi(i, j, a)] = D.NormWeight(i) * hx * g[At(i, j, a)];
          col[i] = g[n + At(i, j, a)];
        }
        // Hˣ_j (D̄ᵀ Hᵗ ∂L/∂φ_t)_i, on unscaled values first so that the
        // time direction rounds as in point mechanics.
        auto& t = scratch_.t;
        t.assign(nt_, Real(0));
        sbp::AddDbarTransposeHw(dt_, col, dw,
                                [&](int i) -> Real& { return t[i]; });
        for (int i = 0; i < nt_; ++i) f[Phi(i, j, a)] += hx * t[i];
        f[Phi(nt_ - 1, j, a)] += hx * y[Lambda3(j, a)];
        const auto last = D.row(nt_ - 1);
        for (std::size_t k = 0; k < last.coeffs.size(); ++k)
          f[Phi(last.first + static_cast<int>(k), j, a)] +=
              hx * y[Lambda4(j, a)] * last.coeffs[k] * D.inv_dt();
        if (Constraint(a)) {
          f[InitialValueRow(j, a)] = y[Lambda3(j, a)];
          f[InitialVelocityRow(j, a)] = y[Lambda4(j, a)];
          continue;
        }
        f[InitialValueRow(j, a)] = y[Phi(0, j, a)] - phi0_[j * m + a];
        for (int i = 0; i < nt_; ++i) col[i] = y[Phi(i, j, a)];
        f[InitialVelocityRow(j, a)] =
            D.ApplyRow(0, col.data()) - pi0_[j * m + a];
      }
    }
    auto& row = scratch_.row;
    auto& drow = scratch_.row_x;
    auto& s = scratch_.s;
    row.resize(nx_);
    drow.resize(nx_);
    for (int i = 0; i < nt_; ++i) {
      const Real ht = D.NormWeight(i);
      for (int a = 0; a < m; ++a) {
        s.assign(nx_, Real(0));
        for (int b = 0; b < d; ++b) {
          for (int j = 0; j < nx_; ++j) row[j] = g[2 * n + Grad(i, j, b, a)];
          grid_.AddTransposeH(b, std::span<const Real>(row), std::span<Real>(s),
                              scratch_.line);
        }
        for (int j = 0; j < nx_; ++j) f[Phi(i, j, a)] += ht * s[j];
      }
    }
    AddBoundaryResidual(*this, y, f);
    AddFaceResidual(*this, faces_, f);
  }

  // Feeds every Jacobian entry to sink.Add(row, col, value); entries at the
  // same position are summed by the sink. The entries fed depend on the
  // grid and the density only, never on y (a sink may fix its pattern on
  // the first call).
  template <class Sink>
  void Jacobian(const Real* y, Sink& sink) const {
    auto& v = scratch_.values;
    Fields(y, v);
    const auto& D = dt_.base();
    FieldLocal<Real, d> local[FieldLocal<Real, d>::kMax];
    for (int i = 0; i < nt_; ++i)
      for (int j = 0; j < nx_; ++j) {
        const Hessian h =
            D.NormWeight(i) * grid_.NormWeight(j) * PointHessian(v, i, j);
        const int count = FieldLocalEntries(dt_, grid_, i, j, local);
        for (int r = 0; r < count; ++r) {
          const auto& lr = local[r];
          // Row entry r's weights applied once: (wφ, wt, w∇)·H, m × K.
          const Eigen::Matrix<Real, m, K> row = lr.template Rows<m>(h);
          for (int c = 0; c < count; ++c) {
            const auto& lc = local[c];
            // A time neighbour and a space neighbour meet only through
            // ∂²L/∂φ_t∂(∇φ).
            if (!couples_t_x_ && lr.kind + lc.kind == 3) continue;
            const Eigen::Matrix<Real, m, m> b = lc.template Cols<m>(row);
            for (int a = 0; a < m; ++a)
              for (int e = 0; e < m; ++e)
                sink.Add(Phi(lr.i, lr.j, a), Phi(lc.i, lc.j, e), b(a, e));
          }
        }
      }
    const auto last = D.row(nt_ - 1);
    const auto first = D.row(0);
    for (int j = 0; j < nx_; ++j) {
      const Real hx = grid_.NormWeight(j);
      for (int a = 0; a < m; ++a) {
        sink.Add(Phi(nt_ - 1, j, a), Lambda3(j, a), hx);
        for (std::size_t k = 0; k < last.coeffs.size(); ++k)
          if (last.coeffs[k] != Real(0))
            sink.Add(Phi(last.first + static_cast<int>(k), j, a), Lambda4(j, a),
                     hx * (last.coeffs[k] * D.inv_dt()));
        if (Fixed(j)) continue;  // rows replaced by the boundary's
        if (Constraint(a)) {
          sink.Add(InitialValueRow(j, a), Lambda3(j, a), Real(1));
          sink.Add(InitialVelocityRow(j, a), Lambda4(j, a), Real(1));
          continue;
        }
        sink.Add(InitialValueRow(j, a), Phi(0, j, a), Real(1));
        for (std::size_t k = 0; k < first.coeffs.size(); ++k)
          if (first.coeffs[k] != Real(0))
            sink.Add(InitialVelocityRow(j, a),
                     Phi(first.first + static_cast<int>(k), j, a),
                     first.coeffs[k] * D.inv_dt());
      }
    }
    AddBoundaryJacobian(*this, sink);
  }

 private:
  void Point(const FieldValues<Real>& v, int i, int j, Real* z) const {
    for (int a = 0; a < m; ++a) {
      z[a] = v.phi[At(i, j, a)];
      z[m + a] = v.phi_t[At(i, j, a)];
      for (int b = 0; b < d; ++b)
        z[(2 + b) * m + a] = v.phi_x[Grad(i, j, b, a)];
    }
  }

  const Density& density_;
  const sbp::RegularizedOperator<Real>& dt_;
  sbp::SpaceGrid<Real> grid_;
  int nt_, nx_;
  std::vector<Real> phi0_, pi0_;
  bool couples_t_x_ = false;
  BoundarySide<Real> boundary_[2];
  std::vector<FaceData<Real>> faces_;
  int constrained_ = 0;

  // Work arrays reused across evaluations (not thread-safe).
  struct Scratch {
    FieldValues<Real> values;
    std::vector<Real> g, col, col_t, row, row_x, t, s, line;
  };
  mutable Scratch scratch_;
};

}  // namespace vivp::action
