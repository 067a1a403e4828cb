// Where the vortices of a charged slice are, found gauge invariantly on a
// periodic grid of two axes (charged_terms.h's layout; a slice is values
// j·m + a).
//
// The winding of the plaquette with corners j, j + x̂, j + x̂ + ŷ, j + ŷ,
// counterclockwise, is
//
//   n_p = (1/2π) (Σ_links θ_ab + h_x h_y F_xy),
//   θ_ab = arg(φ̄_a e^{−ih A_ab} φ_b) ∈ (−π, π],
//
// since Σ h A around the plaquette is h_x h_y F_xy. Each θ and F are gauge
// invariant, so n_p is; it is an integer wherever no link's phase jump
// reaches π, and vanishes unless φ has a zero inside (a vortex of winding
// n_p). Inside a winding plaquette the zero is located to below the
// spacing: the corners' φ, transported to corner j along the links, are
// interpolated bilinearly (gauge covariantly: every value takes the factor
// of corner j), and Newton finds the zero of the interpolant.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "core/action/charged_terms.h"

namespace vivp::action {

struct Vortex {
  double x = 0, y = 0;  // the zero of φ
  int winding = 0;      // of its plaquette
};

// The plaquette's winding n_p, rounded, and its corners' φ transported to
// corner j (a, b, c, d: j, j + x̂, j + x̂ + ŷ, j + ŷ).
inline int PlaquetteWinding(const sbp::SpaceGrid<double>& grid, const double* x,
                            int j, Complex corners[4]) {
  using L = ChargedLayout<2>;
  constexpr int m = L::m;
  const int jx = NextOn(grid, j, 0), jy = NextOn(grid, j, 1),
            jxy = NextOn(grid, jx, 1);
  const double hx = grid.axis(0).dx(), hy = grid.axis(1).dx();
  auto phi = [&](int k) {
    return Complex(x[k * m + L::kRe], x[k * m + L::kIm]);
  };
  // The link variables e^{−ih A} of the four edges, counterclockwise.
  const Complex u1 = std::polar(1.0, -hx * x[j * m + L::A(0)]);
  const Complex u2 = std::polar(1.0, -hy * x[jx * m + L::A(1)]);
  const Complex u3 = std::polar(1.0, hx * x[jy * m + L::A(0)]);
  const Complex u4 = std::polar(1.0, hy * x[j * m + L::A(1)]);
  const Complex a = phi(j), b = phi(jx), c = phi(jxy), d = phi(jy);
  const double theta =
      std::arg(std::conj(a) * u1 * b) + std::arg(std::conj(b) * u2 * c) +
      std::arg(std::conj(c) * u3 * d) + std::arg(std::conj(d) * u4 * a);
  LocalReal f;
  MagneticAt<2>(
      grid, x, j, 0, 1, [&](int k, int comp) { return k * m + comp; }, f);
  const double flux = hx * hy * f.value;
  corners[0] = a;
  corners[1] = u1 * b;
  corners[2] = u1 * u2 * c;
  corners[3] = std::conj(u4) * d;  // along the link (j, j + ŷ)
  return int(std::lround((theta + flux) / (2 * std::numbers::pi)));
}

// The zero (s, t) ∈ [0, 1]² of the bilinear interpolant of the corners
// a, b, c, d at (0,0), (1,0), (1,1), (0,1), by Newton from the centre;
// clamped to the plaquette.
inline Eigen::Vector2d BilinearZero(const Complex corners[4]) {
  Eigen::Vector2d st(0.5, 0.5);
  for (int it = 0; it < 30; ++it) {
    const double s = st[0], t = st[1];
    const Complex v = (1 - s) * (1 - t) * corners[0] +
                      s * (1 - t) * corners[1] + s * t * corners[2] +
                      (1 - s) * t * corners[3];
    const Complex ds =
        (1 - t) * (corners[1] - corners[0]) + t * (corners[2] - corners[3]);
    const Complex dt =
        (1 - s) * (corners[3] - corners[0]) + s * (corners[2] - corners[1]);
    Eigen::Matrix2d J;
    J << ds.real(), dt.real(), ds.imag(), dt.imag();
    const Eigen::Vector2d step =
        J.fullPivLu().solve(Eigen::Vector2d(v.real(), v.imag()));
    st -= step;
    st = st.cwiseMax(0.0).cwiseMin(1.0);
    if (step.norm() < 1e-13) break;
  }
  return st;
}

// Every plaquette of nonzero winding, with the zero of φ inside it.
inline std::vector<Vortex> FindVortices(const sbp::SpaceGrid<double>& grid,
                                        const double* x) {
  std::vector<Vortex> out;
  Complex corners[4];
  for (int j = 0; j < grid.points(); ++j) {
    const int n = PlaquetteWinding(grid, x, j, corners);
    if (n == 0) continue;
    const Eigen::Vector2d st = BilinearZero(corners);
    out.push_back({grid.x(j, 0) + st[0] * grid.axis(0).dx(),
                   grid.x(j, 1) + st[1] * grid.axis(1).dx(), n});
  }
  return out;
}

// The vortices of node i of a window of a charged field's system
// (charged_field.h): its slice of the unknowns y, then FindVortices.
template <class System>
std::vector<Vortex> FindVorticesAtNode(const System& sys, const double* y,
                                       int i) {
  const int nx = sys.space_points();
  std::vector<double> slice(std::size_t(nx) * System::m);
  for (int j = 0; j < nx; ++j)
    for (int a = 0; a < System::m; ++a)
      slice[std::size_t(j) * System::m + a] = y[sys.Phi(i, j, a)];
  return FindVortices(sys.space_grid(), slice.data());
}

}  // namespace vivp::action
