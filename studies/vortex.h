// The Abelian Higgs model at critical coupling in 2 + 1 D measured
// (docs/gauge.md §9): a Nielsen–Olesen vortex and antivortex far apart on a
// periodic square, relaxed to a static critical point of the slice's energy
// (solvers/spacetime/charged_static.h), its energy per unit winding against
// the Bogomolny bound 2π v² |n|, and the relaxed pair marched window by
// window with the space-time action (charged_march.h).
//
// Normalization (problems/fields/charged.h): D = ∂ − iA, the coupling in
// front of the field strength, V = (λ/2)(|φ|² − v²)². The static energy
//   E = ∫ |D_1φ|² + |D_2φ|² + B²/(2e²) + (λ/2)(|φ|² − v²)²
// is, with |D_1φ|² + |D_2φ|² = |(D_1 ± iD_2)φ|² ± B|φ|² + a divergence and
// λ = e² (critical coupling),
//   E = ∫ |(D_1 ± iD_2)φ|² + (1/(2e²))(B ∓ e²(v² − |φ|²))² ± v² ∫ B,
// so E ≥ v² |∫B| = 2π v² |n|: the flux quantum of a unit charge is 2π
// (Bogomolny 1976; Manton & Sutcliffe, Topological Solitons 2004, ch. 7).
#pragma once

#include <string>
#include <vector>

#include "core/linalg/fit.h"
#include "core/sbp/space_grid.h"
#include "problems/fields/charged.h"

namespace vivp::studies {

// The Bogomolny equations of a vortex of winding n > 0 in this
// normalization, φ = v f(r) e^{inθ}, A_θ = n a(r)/r:
//   f' = (n/r) f (1 − a),   a' = (e² v² r/n)(1 − f²),
// shot from f ≈ c rⁿ, a ≈ e²v² r²/(2n) at r → 0 (bisection on c until f
// neither turns down nor passes 1), and the continuum energy
// 2π ∫ r dr [v²f'² + v²n²f²(1 − a)²/r² + n²a'²/(2e²r²) + (λ/2)v⁴(1 − f²)²]
// along the shot (classical Runge–Kutta, Simpson), e = v = 1, λ = e²: the
// check of the bound's normalization apart from the lattice.
struct RadialVortex {
  double slope = 0;   // c, f ≈ c rⁿ at the centre
  double energy = 0;  // to the radius where the shot leaves
  double radius = 0;
};
RadialVortex ShootRadialVortex(int n);

// e = v = 1, λ = e² = 1, m² = 0: both the scalar's and the photon's mass is
// √2 e v.
fields::ScalarQed CriticalHiggs();

// n × n points on [−L/2, L/2)², shifted by h/2 so that the vortex centres
// (±L/4, 0) are plaquette centres (L/(4h) must be an integer).
sbp::SpaceGrid<double> VortexSquare(int n, double length);

// The ansatz of a vortex (n = 1) at (L/4, 0) and an antivortex (n = −1) at
// (−L/4, 0) (ChargedLayout<2>, χ = 0): φ = v f(r₁) f(r₂) e^{iΘ} with
// f = tanh r, and A = ∇Θ − (1 − a(r₁))∇θ₁ + (1 − a(r₂))∇θ₂ with
// a = tanh² r, each link the line integral of A along it over h. Θ is the
// phase of a function with a simple zero at the vortex and a simple pole at
// the antivortex that is periodic on the torus (Jacobi's ϑ₁, below), so
// that φ and A are exactly periodic.
std::vector<double> VortexPairAnsatz(const sbp::SpaceGrid<double>& grid,
                                     double length);

// The winding of each plaquette (at its lower-left point j), gauge
// invariant: (Σ_links arg(φ̄_j e^{−ihA} φ_k) + h²F)/(2π) around it, an
// integer; a vortex's plaquette has +1, an antivortex's −1.
std::vector<int> PlaquetteWindings(const sbp::SpaceGrid<double>& grid,
                                   const std::vector<double>& x);

// The relaxed pair on n × n points of [−L/2, L/2)².
struct VortexStatic {
  int n = 0;
  double length = 0, h = 0;
  double energy = 0;
  double deficit = 0;  // U/(2π v² Σ|n|) − 1, Σ|n| = 2
  // The static equations' residual max |∂U/∂x|/Hˣ at the ansatz, after
  // L-BFGS and after the Newton steps (charged_static.h).
  double start_residual = 0, lbfgs_residual = 0, residual = 0;
  int iterations = 0, newton = 0;
  double lbfgs_seconds = 0, seconds = 0;
  std::string message;
  std::vector<double> x;  // the relaxed slice
};
VortexStatic RelaxVortexPair(int n, double length, double residual = 1e-11);

// The order p and constant C of |deficit| ≈ C h^p (core/linalg/fit.h).
linalg::PowerLawFit FitPower(const std::vector<double>& h,
                             const std::vector<double>& y);

// The relaxed pair as data (π = 0, E = 0: ρ = 0, Gauss's law holds)
// marched `windows` windows of `window` nodes of `op` at step dt, Newton's
// normal equations factored by CHOLMOD's supernodal Cholesky or (cholmod =
// false) Eigen's simplicial LDLᵀ (normal_solver.h).
struct VortexMarchRun {
  bool ok = false;
  std::string reason;
  int windows = 0;
  double t_end = 0;
  double modulus = 0;         // max over nodes of | |φ|(t) − |φ|(0) |
  double energy_density = 0;  // max over nodes of its change
  double energy_scale = 0;    // max of the static energy density
  double gauss = 0;           // the action's law, max over nodes
  long long newton = 0;
  std::vector<double> window_seconds;
};
VortexMarchRun MarchVortexPair(const VortexStatic& pair, const std::string& op,
                               int window, double dt, int windows,
                               bool cholmod = true);

}  // namespace vivp::studies
