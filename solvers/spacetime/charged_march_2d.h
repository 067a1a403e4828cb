// The charged march (charged_march.h) of scalar electrodynamics or the
// Abelian Higgs model on a grid of two axes, compiled once, with Newton's
// normal equations factored by CHOLMOD's supernodal Cholesky: in 2 + 1 D a
// window's normal equations fill in like a three-dimensional grid's, and
// the supernodal factorization's dense blocks (BLAS) are where its time
// goes (32² points, windows of 8 SBP21 nodes: 6 s a window with OpenBLAS,
// 40 s with ATLAS; Eigen's simplicial LDLᵀ is slower still).
#pragma once

#include <functional>
#include <vector>

#include "core/action/charged_observables.h"
#include "problems/fields/charged.h"
#include "solvers/spacetime/charged_leapfrog.h"
#include "solvers/spacetime/charged_march.h"

namespace vivp::spacetime {

using ChargedSystem2 = action::ChargedFieldSystem<fields::ScalarQed, 2>;
using ChargedWindowObserver2 =
    std::function<void(const ChargedSystem2&, const std::vector<double>& y,
                       const action::ChargedNodes&, const ChargedSliceState&)>;

ChargedMarch MarchChargedSupernodal(const fields::ScalarQed& model,
                                    const sbp::SpaceGrid<double>& grid,
                                    std::vector<double> phi,
                                    std::vector<double> pi,
                                    const ChargedMarchOptions& options,
                                    const ChargedWindowObserver2& on_window);

}  // namespace vivp::spacetime
