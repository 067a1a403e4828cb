// A window's banded LU kept across a change of step (error control), with
// the step's scaling of the reduced equations undone (reduced_system.h).
//
// For a second-order density the node rows are ∂S/∂x₋ = E_vv + E_xv + E_xx,
// the parts through two, one and no velocities: they scale like 1/Δt, 1 and
// Δt (H ∝ Δt, D̄ ∝ 1/Δt). The initial-velocity rows and the λ4 column scale
// like 1/Δt, the initial-position rows and the λ3 column do not. With
// s = Δt/Δt_f, the step now over the step factored at,
//
//   R J(Δt) Q = E_vv + s E_xv + s² E_xx (+ constraints as at Δt_f),
//   R = diag(1 on the initial-position rows, s elsewhere),
//   Q = diag(1/s on the λ3 column, 1 elsewhere),
//
// so J(Δt)⁻¹ ≈ Q J(Δt_f)⁻¹ R leaves the chord steps only the mismatch of the
// position terms, (s − 1) E_xv + (s² − 1) E_xx, where the factorization used
// as it stands leaves all of J's (1 − 1/s) E_vv as well. The BandedSolver
// of variational::Newton (newton.h) with its factorization and substitution
// scaled so.
#pragma once

#include "solvers/variational/newton.h"

namespace vivp::variational::detail {

class StepScaledLu : public BandedSolver<double> {
 public:
  // The unknowns' layout: d components, the first λ3 unknown; `scaled`
  // false (a first-order density, whose node rows scale otherwise): the
  // factorization is used as it stands.
  StepScaledLu(int d, int lambda3, bool scaled)
      : d_(d), lambda3_(lambda3), scaled_(scaled) {}

  // The step of the equations solved from now on; the factorization is kept.
  void SetStep(double dt) { dt_ = dt; }
  // The step now over the step the factorization was made at.
  double Ratio() const { return dt_ / factored_dt_; }

  bool Factorize() {
    factored_dt_ = dt_;
    return BandedSolver<double>::Factorize();
  }
  void Solve(double* b) const {
    const double s = Ratio();
    if (!scaled_ || s == 1.0) return BandedSolver<double>::Solve(b);
    const int n = jac.size();
    for (int r = d_; r < n; ++r) b[r] *= s;  // R
    BandedSolver<double>::Solve(b);
    for (int c = 0; c < d_; ++c) b[lambda3_ + c] /= s;  // Q
  }

 private:
  int d_, lambda3_;
  bool scaled_;
  double dt_ = 1.0, factored_dt_ = 1.0;
};

}  // namespace vivp::variational::detail
