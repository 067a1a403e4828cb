// An independent integration of a field window's semi-discrete equations:
// the Newton start of the window and the reference its result is checked
// against, as in point mechanics (solvers/variational/predictor.h, whose
// Dormand–Prince integration and error bound it shares). The equations are
// those of the method of lines on the same spatial operator
// (method_of_lines.h: M φ̈_j = ∂ℒ/∂φ(j) + (D_xᵀ Hˣ ∂ℒ/∂φ_x)_j / Hˣ_j), so
// nothing is derived by hand here either, with the boundary data of the
// discrete action (core/action/field_boundary.h):
//
//   Dirichlet   the boundary point is the data: φ_b = g(t) wherever the
//               acceleration reads it, and its own components stand still
//               (the checks skip them);
//   Neumann     the flux term Hᵗ[q_L φ(x_0) − q_R φ(x_N)] of the action adds
//               ±M⁻¹ q(t)/Hˣ_b to the boundary point's acceleration, q the
//               flux ∂ℒ/∂φ_x at the prescribed slope.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <span>
#include <stdexcept>
#include <vector>

#include "core/action/field_boundary.h"
#include "core/action/field_faces.h"
#include "core/action/field_point.h"
#include "core/autodiff/pointwise.h"
#include "core/sbp/space_grid.h"
#include "solvers/spacetime/input.h"
#include "solvers/spacetime/method_of_lines.h"
#include "solvers/variational/predictor.h"

namespace vivp::spacetime {

template <class Density>
class FieldPredictor {
 public:
  static constexpr int m = Density::kDim;
  static constexpr int d = action::SpaceDimOf<Density>();
  using State = std::vector<double>;

  // The data of one end of an interval at time t: g or h of component a.
  using Data = std::function<double(double t, int a)>;
  struct End {
    action::BoundaryKind kind = action::BoundaryKind::kNatural;
    Data value;  // empty: 0
  };

  // phi0, pi0: a state at which the density's form is checked (the march's
  // initial data; method_of_lines.h). ends: the left and right ends' data
  // of a one-dimensional field.
  FieldPredictor(const Density& density, const sbp::SpaceGrid<double>& grid,
                 std::span<const double> phi0, std::span<const double> pi0,
                 const End ends[2] = nullptr)
      : density_(density),
        grid_(grid),
        n_(std::size_t(grid.points()) * m),
        acceleration_(density, grid, phi0, pi0),
        acc_(n_),
        work_(n_) {
    if (ends && d > 1 &&
        (ends[0].kind != action::BoundaryKind::kNatural ||
         ends[1].kind != action::BoundaryKind::kNatural))
      throw std::invalid_argument(
          "boundary data are built for one spatial dimension only");
    if (ends) {
      ends_[0] = ends[0];
      ends_[1] = ends[1];
    }
  }

  int dim() const { return int(n_); }
  // The first step of the next run (the last accepted one): part of a
  // checkpoint (solve.h).
  double first_step() const { return step_; }
  void set_first_step(double h) { step_ = h; }
  // Neumann faces of a grid of d > 1 axes (input.h): the flux term of
  // core/action/field_faces.h adds ±M⁻¹q_a/Hᵃ to a face point's
  // acceleration (H = H^{⊥a}Hᵃ), q_a the flux at the prescribed slope.
  void SetFaces(std::vector<FieldFace> faces) {
    faces_ = std::move(faces);
    face_points_.clear();
    for (const auto& f : faces_)
      face_points_.push_back(action::detail::FacePoints(grid_, f.axis, f.side));
  }

  // From (φ, φ_t) = (x0, v0) at τ = 0, time t0, to the nodes tau[0 …
  // count), writing φ and φ_t slice-major into x and v (count·n values
  // each).
  variational::PredictorReport Run(double t0, const double* x0,
                                   const double* v0, const double* tau,
                                   int count, double tol_abs, double tol_rel,
                                   double* x, double* v) {
    State s(2 * n_);
    std::copy(x0, x0 + n_, s.begin());
    std::copy(v0, v0 + n_, s.begin() + n_);
    auto rhs = [this, t0](const State& y, State& dy, double tau_now) {
      std::copy(y.begin() + n_, y.end(), dy.begin());
      std::copy(y.begin(), y.begin() + n_, work_.begin());
      Dirichlet(t0 + tau_now, work_.data());
      acceleration_(std::span<const double>(work_), std::span<double>(acc_));
      Neumann(t0 + tau_now, acc_.data());
      Faces(t0 + tau_now, acc_.data());
      std::copy(acc_.begin(), acc_.end(), dy.begin() + n_);
      for (int side = 0; side < 2; ++side)
        if (ends_[side].kind == action::BoundaryKind::kDirichlet)
          for (int a = 0; a < m; ++a) {
            dy[Point(side) * m + a] = 0;
            dy[n_ + Point(side) * m + a] = 0;
          }
    };
    double scale_x = 0, scale_v = 0;
    return variational::IntegrateToNodes(
        s, rhs, tau, count, tol_abs, tol_rel, step_,
        [&](const State& y, int i) {
          double* xi = x + std::size_t(i) * n_;
          double* vi = v + std::size_t(i) * n_;
          std::copy(y.begin(), y.begin() + n_, xi);
          std::copy(y.begin() + n_, y.end(), vi);
          Dirichlet(t0 + tau[i], xi);
          for (std::size_t k = 0; k < n_; ++k) {
            scale_x = std::max(scale_x, std::abs(xi[k]));
            scale_v = std::max(scale_v, std::abs(vi[k]));
          }
        },
        scale_x, scale_v);
  }

  // ∂ℒ/∂φ_t at each point of the slice (φ, φ_t): the momentum density, the
  // continuum value of −λ3 at a window's end (the Newton start of λ3).
  void Momentum(const double* phi, const double* phi_t, double* p) const {
    phi_x_.resize(n_ * d);
    grid_.Gradient<double>(m, std::span<const double>(phi, n_), phi_x_,
                           gradient_work_);
    auto call = [&](const auto* w) { return density_(w, w + m, w + 2 * m); };
    for (std::size_t j = 0; j < n_ / m; ++j) {
      double z[(2 + d) * m];
      for (int a = 0; a < m; ++a) {
        z[a] = phi[j * m + a];
        z[m + a] = phi_t[j * m + a];
      }
      for (int k = 0; k < d * m; ++k) z[2 * m + k] = phi_x_[j * d * m + k];
      const auto g = autodiff::Gradient<double, (2 + d) * m>(call, z).second;
      for (int a = 0; a < m; ++a) p[j * m + a] = g[m + a];
    }
  }

 private:
  int Point(int side) const { return side == 0 ? 0 : grid_.points() - 1; }

  // φ at the Dirichlet ends set to the data at time t.
  void Dirichlet(double t, double* phi) const {
    for (int side = 0; side < 2; ++side)
      if (ends_[side].kind == action::BoundaryKind::kDirichlet)
        for (int a = 0; a < m; ++a)
          phi[Point(side) * m + a] =
              ends_[side].value ? ends_[side].value(t, a) : 0.0;
  }

  // The Neumann ends' flux terms added to the acceleration at time t:
  // +M⁻¹q/Hˣ at x_0, −M⁻¹q/Hˣ at x_N (q = ∂ℒ/∂φ_x at φ_x = h(t)).
  void Neumann(double t, double* acc) const {
    auto call = [&](const auto* w) { return density_(w, w + m, w + 2 * m); };
    for (int side = 0; side < 2; ++side) {
      if (ends_[side].kind != action::BoundaryKind::kNeumann) continue;
      double z[(2 + d) * m] = {};
      for (int a = 0; a < m; ++a)
        z[2 * m + a] = ends_[side].value ? ends_[side].value(t, a) : 0.0;
      const auto g = autodiff::Gradient<double, (2 + d) * m>(call, z).second;
      Eigen::Matrix<double, m, 1> q;
      for (int a = 0; a < m; ++a) q[a] = g[2 * m + a];
      const int j = Point(side);
      const Eigen::Matrix<double, m, 1> f =
          acceleration_.inverse_mass() * q *
          ((side == 0 ? 1.0 : -1.0) / grid_.axis(0).NormWeight(j));
      for (int a = 0; a < m; ++a) acc[j * m + a] += f[a];
    }
  }

  void Faces(double t, double* acc) const {
    auto call = [&](const auto* w) { return density_(w, w + m, w + 2 * m); };
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      const FieldFace& face = faces_[f];
      const int col = (2 + face.axis) * m;
      const double sign = face.side == 0 ? 1.0 : -1.0;
      const auto& axis = grid_.axis(face.axis);
      double x[3] = {};
      for (int j : face_points_[f]) {
        for (int a = 0; a < grid_.dim(); ++a) x[a] = grid_.x(j, a);
        double z[(2 + d) * m] = {};
        for (int c = 0; c < m; ++c)
          z[col + c] = face.slope ? face.slope(t, x, c) : 0.0;
        const auto g = autodiff::Gradient<double, (2 + d) * m>(call, z).second;
        Eigen::Matrix<double, m, 1> q;
        for (int c = 0; c < m; ++c) q[c] = g[col + c];
        const Eigen::Matrix<double, m, 1> add =
            acceleration_.inverse_mass() * q *
            (sign / axis.NormWeight(grid_.Coordinate(j, face.axis)));
        for (int c = 0; c < m; ++c) acc[j * m + c] += add[c];
      }
    }
  }

  const Density& density_;
  const sbp::SpaceGrid<double>& grid_;
  std::size_t n_;
  FieldAcceleration<Density> acceleration_;
  mutable std::vector<double> acc_, work_;
  End ends_[2];
  std::vector<FieldFace> faces_;
  std::vector<std::vector<int>> face_points_;
  mutable std::vector<double> phi_x_;
  mutable sbp::SpaceGrid<double>::GradientWork<double> gradient_work_;
  double step_ = 0;  // last accepted step, the next run's first
};

}  // namespace vivp::spacetime
