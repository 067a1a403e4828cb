// Private to solvers/bea (derivation.cc): the self-checks Derive runs on its
// result. The checks one by one are public in derivation.h.
#pragma once

#include <vector>

#include "solvers/bea/derivation.h"
#include "solvers/bea/jet_space.h"
#include "solvers/bea/series.h"

namespace vivp::bea {

// Runs every self-check that applies to r, in order, into r.checks and times
// them into r.check_seconds: 1. odd orders vanish; 2. Hamiltonian structure;
// 3. the Taylor-expanded scheme (from ExpandScheme, reduced with red)
// vanishes along the modified equation; 4. the charge is conserved (if r has
// one); 5. the modified Lagrangian generates the modified equation (if r has
// one). With throw_on_failure, throws std::runtime_error naming the method,
// the order and the first failed check.
void RunSelfChecks(BeaResult& r, const std::vector<Series>& scheme,
                   Reduction& red, bool throw_on_failure);

}  // namespace vivp::bea
