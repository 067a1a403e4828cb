// Neumann data on the faces of a grid of d > 1 axes (space_grid.h): the
// flux form of field_boundary.h's Neumann ends, face by face. On the face
// x_a = x_{a,0} (side 0) or x_{a,N} (side 1) of an interval axis a, the
// action gains
//
//   Σ_i Hᵗ_i Σ_{j ∈ face} H^{⊥a}_j (±) q_a(t_i, x_j)·φ(t_i, x_j),
//
// + on side 0 and − on side 1, with q_a = ∂L/∂(∂_aφ) at the prescribed
// normal slope ∂_aφ = h(t_i, x_j) (the other arguments 0). The boundary
// term of axis a in D_aᵀ H q (space_grid.h) is ∓H^{⊥a} q_a on the face, so
// the weak condition becomes q_a = q_a(h), i.e. ∂_aφ = h: the data enter
// the residual only, and the Jacobian — and with it the space-diagonalized
// solve of the natural condition — is unchanged. A point on two faces (an
// edge or a corner) carries both terms. The flux must depend on ∂_aφ
// alone (checked).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/autodiff/pointwise.h"

namespace vivp::action {

template <class Real>
struct FaceData {
  int axis = 0, side = 0;
  std::vector<int> points;  // the face's flat indices
  std::vector<Real> flux;   // q_a at (node i, face point k, component c):
                            // (i·points + k)·m + c
};

namespace detail {

// The face's points, axis 0 fastest, as the grid orders them.
template <class Grid>
std::vector<int> FacePoints(const Grid& g, int axis, int side) {
  std::vector<int> out;
  const int at = side == 0 ? 0 : g.points(axis) - 1;
  for (int j = 0; j < g.points(); ++j)
    if (g.Coordinate(j, axis) == at) out.push_back(j);
  return out;
}

}  // namespace detail

// Face data for `system` from the slopes h at (node i, face point k,
// component c), in FaceData::flux's layout.
template <class System, class Real>
FaceData<Real> MakeFace(const System& s, int axis, int side,
                        const std::vector<Real>& slopes) {
  constexpr int m = System::m, d = System::d, K = System::K;
  const auto& g = s.space_grid();
  if (axis < 0 || axis >= d || (side != 0 && side != 1))
    throw std::invalid_argument("a face is an axis below " + std::to_string(d) +
                                " and a side 0 or 1");
  if (g.axis(axis).periodic())
    throw std::invalid_argument("axis " + std::to_string(axis) +
                                " is periodic: it has no faces for data");
  if (!s.template HessianBlockVanishes<m, 2 * m>((2 + axis) * m, 0))
    throw std::invalid_argument(
        "Neumann data need a density whose flux depends on the slope alone; "
        "this one couples the gradient to φ or φ_t");
  FaceData<Real> f{axis, side, detail::FacePoints(g, axis, side), {}};
  const std::size_t want = std::size_t(s.time_points()) * f.points.size() * m;
  if (slopes.size() != want)
    throw std::invalid_argument(
        "face data: expected " + std::to_string(want) +
        " slopes (node × face point × component), got " +
        std::to_string(slopes.size()));
  f.flux.resize(want);
  for (std::size_t r = 0; r < want; r += m) {
    Real z[K] = {};
    for (int c = 0; c < m; ++c) z[(2 + axis) * m + c] = slopes[r + c];
    const auto q = autodiff::Gradient<Real, K>(s.Call(), z).second;
    for (int c = 0; c < m; ++c) f.flux[r + c] = q[(2 + axis) * m + c];
  }
  return f;
}

// Adds the faces' terms to the residual f of the field system.
template <class System, class Real>
void AddFaceResidual(const System& s, const std::vector<FaceData<Real>>& faces,
                     Real* f) {
  constexpr int m = System::m;
  const auto& D = s.time_operator().base();
  const auto& g = s.space_grid();
  for (const auto& face : faces) {
    const Real sign = face.side == 0 ? Real(1) : Real(-1);
    const std::size_t np = face.points.size();
    for (int i = 0; i < s.time_points(); ++i)
      for (std::size_t k = 0; k < np; ++k) {
        const int j = face.points[k];
        const Real w =
            sign * D.NormWeight(i) * g.NormWeightAcross(j, face.axis);
        for (int c = 0; c < m; ++c)
          f[s.Phi(i, j, c)] += w * face.flux[(i * np + k) * m + c];
      }
  }
}

}  // namespace vivp::action
