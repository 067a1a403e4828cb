// Legendre–Gauss–Lobatto collocation as an SBP operator: one spectral
// element of n nodes per window.
//
//   auto D = vivp::sbp::MakeOperator<double>("lgl8", 8, 0.0, 0.7);
//
// The nodes are the n Gauss–Lobatto points of [t_start, t_end] (the ends
// and the roots of P'_{n−1}, P the Legendre polynomial), H their quadrature
// weights and D the derivative of the interpolating polynomial at the nodes.
// The quadrature is exact to degree 2n − 3 and (Du)·u of a polynomial of
// degree n − 1 has degree 2n − 3, so H D + Dᵀ H = diag(−1, 0, …, 0, 1)
// holds exactly: D is a diagonal-norm SBP operator (Gassner, "A
// skew-symmetric discontinuous Galerkin spectral element discretization and
// its relation to SBP-SAT finite difference methods", SIAM J. Sci. Comput.
// 35 (2013) A1233). D is centro-antisymmetric, D[n−1−i][n−1−j] = −D[i][j],
// so a table of its first n/2 rows describes it (n even: no middle row),
// with the node positions as offsets.
//
// As the time derivative of the discrete action an element's window is the
// Galerkin variational integrator with Lobatto quadrature (Marsden & West,
// "Discrete mechanics and variational integrators", Acta Numerica 10
// (2001)), whose end state, corrected by the multipliers as every window's
// is (solvers/variational/end_state.h), converges with order 2n − 2 in the
// window's length: lgl8 of order 14 with 7 steps per window (measured 14.4;
// docs/method.md §13).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/sbp/coefficients.h"

namespace vivp::sbp {

// The element operators lgl8, lgl12, lgl16, in the order of their accuracy.
const std::vector<const Coefficients*>& ElementOperators();

// "lgl8, lgl12, lgl16".
std::string ElementOperatorNameList();

// The element's interpolating polynomial through its n nodes at the times
// `at` (per unit step from the element's start, as its node offsets): an
// at.size() × n row-major matrix whose row k holds ℓ_i(at[k]), the Lagrange
// polynomials of the Gauss–Lobatto nodes. Error control starts the two
// halves of an element from the whole one's polynomial
// (solvers/variational/march_adaptive.h). std::invalid_argument for a name
// that is not an element.
std::vector<double> ElementInterpolation(std::string_view name,
                                         const std::vector<double>& at);

}  // namespace vivp::sbp
