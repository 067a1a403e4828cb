// Boundary data of a field on an interval (docs/fields.md §2). Without them
// the discrete action has the natural boundary condition ∂L/∂φ_x = 0 at
// both ends, weakly: the variation of Σ_j Hˣ_j L(…, (D_x φ)_j) carries the
// boundary term (B q)_j, q = ∂L/∂φ_x (core/sbp/space.h). A side may instead
// carry data at every time node t_i of the window:
//
// Dirichlet, φ(t_i, x_b) = g(t_i), by multipliers: the doubled action gains
// Σ_i Hᵗ_i [μ1_i (φ1(t_i, x_b) − g_i) − μ2_i (φ2(t_i, x_b) − g_i)]. At φ₋ = 0
// its variation adds Hᵗ_i μ_i to the φ₋ row of (i, b) and the row
// φ₊(t_i, x_b) = g_i for μ_i. μ_i balances the boundary term: the φ₋ row
// reads Hᵗ_i [μ_i ∓ q_b + O(Δx)], so μ_i → q at x_0 and −q at x_N.
// The multipliers follow the blocks of the spatial points, Nt·m per
// Dirichlet side, left side first. The boundary point's column is then the
// data: its own initial value, initial velocity and end connection are
// implied or contradicted by them and are dropped (their multipliers λ3, λ4
// get the rows λ3 = λ4 = 0; its end state is its last node, end_state.h).
// They cannot be kept: at t_N the φ₋ rows of the slice determine λ3, and
// μ_N's column would be a multiple of λ3's.
//
// Neumann, φ_x(t_i, x_b) = h(t_i), as the natural condition with data: the
// action gains Σ_i Hᵗ_i [q_L(t_i) φ(t_i, x_0) − q_R(t_i) φ(t_i, x_N)] with
// q = ∂L/∂φ_x at φ_x = h, so that its boundary term reads B(q − q_data). A
// multiplier cannot impose it: φ(x_b) stays free, so the natural condition
// q = 0 still holds and a constraint on φ_x contradicts it unless h = 0
// (measured with one on the moving sine-Gordon kink of docs/fields.md §2:
// order 0.5 in Δx, error 0.17 on 61 points). The data enter through q, so the
// density's flux must depend on φ_x alone (true of every shipped density;
// checked).
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/autodiff/pointwise.h"

namespace vivp::action {

enum class BoundaryKind { kNatural, kDirichlet, kNeumann };

inline const char* BoundaryName(BoundaryKind k) {
  switch (k) {
    case BoundaryKind::kDirichlet:
      return "dirichlet";
    case BoundaryKind::kNeumann:
      return "neumann";
    default:
      return "natural";
  }
}

template <class Real>
struct BoundarySide {
  BoundaryKind kind = BoundaryKind::kNatural;
  std::vector<Real> values;  // g or h at the window's nodes, i·m + a
  std::vector<Real> flux;    // Neumann: q at φ_x = h, the same layout
};

namespace detail {

// q = ∂L/∂φ_x at φ_x = h for every node's h (φ = φ_t = 0; see
// FluxDependsOnSlopeOnly): computed once per window, when the data are set.
template <class System, class Real>
std::vector<Real> Flux(const System& s, const std::vector<Real>& h) {
  constexpr int m = System::m;
  std::vector<Real> q(h.size());
  for (std::size_t i = 0; i < h.size(); i += m) {
    Real z[3 * m] = {};
    for (int a = 0; a < m; ++a) z[2 * m + a] = h[i + a];
    const auto g = autodiff::Gradient<Real, 3 * m>(s.Call(), z).second;
    for (int a = 0; a < m; ++a) q[i + a] = g[2 * m + a];
  }
  return q;
}

}  // namespace detail

// Whether ∂²L/∂φ_x∂(φ, φ_t) vanishes (sampled, FieldSystem).
template <class System>
bool FluxDependsOnSlopeOnly(const System& s) {
  constexpr int m = System::m;
  return s.template HessianBlockVanishes<m, 2 * m>(2 * m, 0);
}

// Why data of `kind` at `side` with `count` values cannot be set on s (a
// one-dimensional interval takes Nt·m values per side), as an exception.
template <class System>
void CheckBoundary(const System& s, int side, BoundaryKind kind,
                   std::size_t count) {
  constexpr int m = System::m, d = System::d;
  if (side != 0 && side != 1)
    throw std::invalid_argument("boundary side must be 0 (left) or 1");
  if (kind == BoundaryKind::kNatural) return;
  if (d > 1)
    throw std::invalid_argument(
        std::string("a ") + BoundaryName(kind) +
        " boundary is built for one spatial dimension only; in " +
        std::to_string(d) +
        " a face takes Neumann data (FieldSystem::SetFace)");
  if (s.space_grid().axis(0).periodic())
    throw std::invalid_argument(
        std::string("a ") + BoundaryName(kind) +
        " boundary needs an interval; the periodic circle has none");
  if (count != static_cast<std::size_t>(s.time_points()) * m)
    throw std::invalid_argument(
        "boundary data: expected " + std::to_string(s.time_points() * m) +
        " values (one per time node and component), got " +
        std::to_string(count));
  if (kind == BoundaryKind::kNeumann && !FluxDependsOnSlopeOnly(s))
    throw std::invalid_argument(
        "Neumann data need a density whose flux ∂L/∂φ_x depends on φ_x "
        "alone (they enter as the flux at the prescribed slope); this one "
        "couples φ_x to φ or φ_t");
}

// Adds the boundary data's terms to the residual f of the field system at y.
template <class System, class Real>
void AddBoundaryResidual(const System& s, const Real* y, Real* f) {
  constexpr int m = System::m;
  const auto& D = s.time_operator().base();
  for (int side = 0; side < 2; ++side) {
    const auto& b = s.boundary(side);
    const int jb = side == 0 ? 0 : s.space_points() - 1;
    if (b.kind == BoundaryKind::kNeumann) {
      const Real sign = side == 0 ? Real(1) : Real(-1);
      for (int i = 0; i < s.time_points(); ++i)
        for (int a = 0; a < m; ++a)
          f[s.Phi(i, jb, a)] += sign * D.NormWeight(i) * b.flux[i * m + a];
    }
    if (b.kind != BoundaryKind::kDirichlet) continue;
    for (int i = 0; i < s.time_points(); ++i)
      for (int a = 0; a < m; ++a) {
        const int row = s.Mu(side, i, a);
        f[s.Phi(i, jb, a)] += D.NormWeight(i) * y[row];
        f[row] = y[s.Phi(i, jb, a)] - b.values[i * m + a];
      }
    for (int a = 0; a < m; ++a) {
      f[s.InitialValueRow(jb, a)] = y[s.Lambda3(jb, a)];
      f[s.InitialVelocityRow(jb, a)] = y[s.Lambda4(jb, a)];
    }
  }
}

// Feeds the Dirichlet multipliers' Jacobian entries to sink.Add(row, col,
// value) (Neumann data add none: their flux is constant in φ).
template <class System, class Sink>
void AddBoundaryJacobian(const System& s, Sink& sink) {
  using Real = typename System::Scalar;
  constexpr int m = System::m;
  const auto& D = s.time_operator().base();
  for (int side = 0; side < 2; ++side) {
    if (s.boundary(side).kind != BoundaryKind::kDirichlet) continue;
    const int jb = side == 0 ? 0 : s.space_points() - 1;
    for (int i = 0; i < s.time_points(); ++i)
      for (int a = 0; a < m; ++a) {
        const int mu = s.Mu(side, i, a);
        sink.Add(mu, s.Phi(i, jb, a), Real(1));
        sink.Add(s.Phi(i, jb, a), mu, D.NormWeight(i));
      }
    for (int a = 0; a < m; ++a) {
      sink.Add(s.InitialValueRow(jb, a), s.Lambda3(jb, a), Real(1));
      sink.Add(s.InitialVelocityRow(jb, a), s.Lambda4(jb, a), Real(1));
    }
  }
}

}  // namespace vivp::action
