// Vortices of a charged field on a square torus (core/action/
// charged_terms.h's layout): the ansatz of any windings, moving data from a
// static slice, and the data of the vortex scenes and studies.
//
// Moving data: each region of a static slice set in motion with its own
// velocity u(x), to first order in u.
// A static solution translated with velocity u, φ(x − ut) and A(x − ut), is
// with A₀ = −u·A (the boost's first order) a solution whose data are
//
//   D_0φ = −(u·D)φ,   E_b = −u_c F_cb,
//
// and Gauss's law holds: ∂_bE_b/e² = −u_c ∂_bF_cb/e² = −u_c j_c = ρ by the
// static Ampère law ∂_bF_bc/e² = −j_c, with j_c = 2 Im(φ̄ D_cφ) and ρ =
// 2 Im(φ̄ D_0φ). Both data are gauge covariant (D_0φ) or invariant (E), so
// they are the data of the gauge A₀ = 0 at t = 0 as well. On the lattice
// D_cφ at a node is the mean of the covariant forward and backward
// differences, and F on a link the mean of its two plaquettes: the data
// then hold Gauss's law to O(h²), and A₀, an unknown of every window, takes
// up the rest. Where u varies, the law is off by u's gradient times the
// fields, which is small where the regions of different u are far apart.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "core/sbp/space_grid.h"
#include "problems/fields/charged.h"
#include "solvers/spacetime/charged_static.h"

namespace vivp::spacetime {

// A vortex of the ansatz: its centre and winding.
struct VortexSeed {
  double x = 0, y = 0;
  int winding = 1;
};

// The ansatz of vortices on the periodic square [x0, x0 + L)² (windings
// summing to zero, as the torus demands), in charged_terms.h's layout with
// χ = 0: φ = v Π_k f(r_k)^{|n_k|} e^{iΘ}, f = tanh, and
//
//   A = ∇Θ − Σ_k n_k (1 − a(r_k)) ∇θ_k,   a = tanh²,
//
// each link the line integral of A along it over h (8-point Gauss–Legendre
// for the cores, arg of the ratio for ∇Θ): far from the cores D_bφ → 0.
// Θ is the phase of F(z) = Π_k ϑ₁(π(z − z_k)/L)^{n_k} e^{icy}: a zero or
// pole of order |n_k| at each centre, periodic in x, and in y once c
// cancels the phase e^{2πi Re Σ n_k z_k / L} that a period iL adds. So φ
// and A are exactly periodic, and the winding around each centre is n_k.
std::vector<double> VortexAnsatz(const sbp::SpaceGrid<double>& grid, double v,
                                 const std::vector<VortexSeed>& seeds);

// π (Re, Im of D_0φ; ∂_tA_b = E_b; 0 for χ) of the static slice x moving
// with velocity u(x, y) (two components).
std::vector<double> MovingSliceVelocities(
    const sbp::SpaceGrid<double>& grid, const std::vector<double>& x,
    const std::function<std::array<double, 2>(double, double)>& u);

// The vortex data of the scenes and studies on a square torus of side L,
// about the plaquette centre c = (x0 + (⌊N/2⌋ + ½)h) on both axes (a torus
// has no middle; this one makes the lattice mirror symmetric about c), each
// vortex moved to the plaquette centre nearest its place (a zero of φ at a
// node has no phase), relaxed towards a static critical point of the
// slice's energy (charged_static.h) from VortexAnsatz.
struct VortexData {
  std::vector<double> x, pi;  // charged_terms.h's layout, χ = 0
  StaticReport relax;
  std::vector<VortexSeed> seeds;  // where they were placed
  // How far the relaxation moved the vortices: the largest distance from a
  // seed to the nearest zero of φ of its winding after it
  // (core/action/vortex_tracks.h), infinite when one is gone (a vortex
  // and an antivortex annihilated), and the zeros found.
  double moved = 0;
  int found = 0;
};

// A vortex at c + (s/2, 0) and an antivortex at c − (s/2, 0), at rest,
// relaxed to `residual`.
VortexData VortexPairData(const fields::ScalarQed& model,
                          const sbp::SpaceGrid<double>& grid, double separation,
                          double residual = 1e-11);

// Two vortices at c ± (a, 0) moving towards c at speed u, the velocity
// −u tanh((x − c_x)/w) along x switched off beyond 5.5 from c, and two
// antivortices at c + (L/2, ±3L/8), where a vortex's pull is ∝ exp(−√2 e v
// r) small. The relaxation stops after 30 L-BFGS iterations: the profiles
// have relaxed (on 32² the residual falls from 0.9 to 1e-3), and further
// iterations move the vortices along their flat directions (at critical
// coupling like vortices exert no force) until, after some 150, they meet
// the antivortices.
VortexData VortexCollisionData(const fields::ScalarQed& model,
                               const sbp::SpaceGrid<double>& grid,
                               double offset, double speed, double transition);

}  // namespace vivp::spacetime
