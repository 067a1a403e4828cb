// Expansions in h of a method's discrete Lagrangian and of its scheme, on the
// jet space, as truncated coefficient lists (no GiNaC series()).
//
// x(t + s h) = sum_m (s h)^m / m! x^(m) is inserted term by term, so the
// order-p coefficient of the Lagrangian depends on x, ..., x^(p+1).
#pragma once

#include <vector>

#include "solvers/bea/jet_space.h"
#include "solvers/bea/method.h"
#include "solvers/bea/series.h"

namespace vivp::bea {

// L_0, ..., L_order (coefficients of h^p) of the method's Lagrangian.
std::vector<GiNaC::ex> ExpandLagrangian(JetSpace& jet, const Method& method,
                                        int order);

// The scheme itself, Taylor expanded: the residual of the discrete equation
// (e.g. sum_j A_j (x(t+jh) - 2x + x(t-jh))/h^2 - grad U(x)) per component, to
// order `order`, on the full jet. Vanishes along the modified equation.
std::vector<Series> ExpandScheme(JetSpace& jet, const Method& method,
                                 int order);

// g(x + delta) = sum_n ((delta . grad)^n g)(x) / n!, truncated at
// delta's order, for delta = O(h) built from x', x'', ... (never x itself).
Series ShiftedPotential(JetSpace& jet, const GiNaC::ex& g,
                        const std::vector<Series>& delta);

}  // namespace vivp::bea
