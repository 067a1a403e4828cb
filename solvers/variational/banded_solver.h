// The linear solver of Newton's method (newton.h) for point mechanics: the
// banded Jacobian of a window's time nodes and its LU factorization.
#pragma once

#include <string>

#include "core/linalg/banded.h"
#include "solvers/variational/banded_lu.h"

namespace vivp::variational {

// The banded Jacobian of the time nodes (point mechanics): LAPACK's banded
// LU (banded_lu.h), the band probed from the system's pattern. The System
// (newton.h) also provides
//   int points() const;                               // time nodes
//   template <class Sink> void Jacobian(const Real* y, Sink& sink) const;
//   template <class Sink> void Jacobian(const Real* y, Sink& sink,
//                                       int node_begin, int node_end) const;
template <class Real>
struct BandedSolver {
  bool valid = false;
  linalg::BandedMatrix<Real> jac;
  BandedLu<Real> lu;  // refers to jac
  int kl = 0, ku = 0;
  long long factorizations = 0;  // over the solver's lifetime

  void Invalidate() { valid = false; }
  bool exact() const { return true; }
  std::string message() const { return ""; }
  // The band is the pattern's, which depends on the operator and the
  // number of nodes only, not on y or the step: it is probed once per size
  // (the probe walks an assembly's pattern; under error control, where
  // every window has a new step and a new factorization, probing each time
  // was a seventh of the march's time, perf).
  template <class System>
  void Prepare(const System& system, const Real* y) {
    const int n = system.size();
    if (jac.size() == n && probed_points == system.points()) return;
    valid = false;
    // Closure rows reach at most twice the widest boundary row into the grid.
    const linalg::BandwidthProbe probe =
        linalg::ProbeBand(system, y, system.points(), 32);
    kl = probe.kl;
    ku = probe.ku;
    probed_points = system.points();
    jac = linalg::BandedMatrix<Real>(n, probe.kl, probe.ku);
  }
  int probed_points = -1;  // the nodes of the probed band
  // A System that writes its Jacobian over the band (reduced_system.h,
  // OverwriteJacobian) spares the zeroing.
  template <class System>
  void Assemble(const System& system, const Real* y) {
    if constexpr (requires { system.OverwriteJacobian(y, jac); }) {
      system.OverwriteJacobian(y, jac);
    } else {
      jac.SetZero();
      system.Jacobian(y, jac);
    }
  }
  // The Jacobian and, into f, the residual at the same y, for a System that
  // evaluates both in one pass (reduced_system.h).
  template <class System>
  void AssembleWithResidual(const System& system, const Real* y,
                            Real* f) requires requires {
    system.ResidualAndJacobian(y, f, jac);
  }
  {
    if constexpr (requires { system.OverwriteJacobian(y, jac, f); }) {
      system.OverwriteJacobian(y, jac, f);
    } else {
      jac.SetZero();
      system.ResidualAndJacobian(y, f, jac);
    }
  }
  bool Factorize() {
    ++factorizations;
    return lu.Factor(jac);
  }
  void Solve(Real* b) const { lu.Solve(b); }
};

}  // namespace vivp::variational
