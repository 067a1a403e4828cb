// What the steppers and their harness ask of a Hamiltonian problem beyond
// H(q, p), with defaults so that a problem states only what differs: its
// initial state (q, p) — the problem's Initial() where it computes one
// (Kepler from e, the NLDNLS profile), otherwise its members q0 and p0 —
// and the invariants tracked besides the energy (Kepler: ℓ and the
// Runge–Lenz vector; the NLDNLS: its charge), none unless declared by
// InvariantNames() and Invariants(q, p).
#pragma once

#include <string>
#include <vector>

namespace vivp::problems {

template <class P>
std::vector<double> InitialState(const P& problem) {
  if constexpr (requires { problem.Initial(); }) {
    return problem.Initial();
  } else {
    std::vector<double> y(problem.q0.begin(), problem.q0.end());
    y.insert(y.end(), problem.p0.begin(), problem.p0.end());
    return y;
  }
}

template <class P>
std::vector<std::string> InvariantNames() {
  if constexpr (requires { P::InvariantNames(); })
    return P::InvariantNames();
  else
    return {};
}

template <class P>
std::vector<double> InvariantValues(const P& problem, const double* q,
                                    const double* p) {
  if constexpr (requires { problem.Invariants(q, p); })
    return problem.Invariants(q, p);
  else
    return {};
}

}  // namespace vivp::problems
