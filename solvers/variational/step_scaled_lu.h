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
//
// A factorization that serves many chord steps (the halves of spectral
// elements keep one for a whole march: about 400 substitutions on the
// anharmonic oscillator at 10⁻⁸) is also kept as its explicit inverse once
// it has served 2n substitutions, n ≤ kMaxInverse unknowns: a substitution
// sweeps short band columns one at a time (1411 instructions for an lgl8
// element of one coordinate, n = 10; 3492 for two, n = 20), the inverse's
// matrix–vector product is one vectorized sweep (565 and 1219). Forming
// it costs n substitutions, so it pays after about 1.5 n (callgrind,
// dense bands n = 10 … 36: 2.5–2.9 times fewer instructions per solve).
// The product rounds otherwise than the substitutions (the two agree to
// within the Jacobian's condition number times ε); the chord steps
// converge to the same round-off either way. A march's factorizations are
// alike, so one that follows a factorization which served 2n substitutions
// is inverted at its first: under error control a step change refactors
// every 30–50 windows, and waiting for 2n again left half the windows
// substituting (anharmonic SBP42 at 10⁻⁵, 24-point windows: solves 0.060
// → 0.039 µs per node, the march 1.54 → 1.28 times the uniform one's
// price; docs/performance.md §9).
#pragma once

#include <Eigen/Core>

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
    // A march's factorizations are alike: one that follows a factorization
    // which served 2n substitutions is inverted at its first.
    threshold_ = uses_ >= 2 * jac.size() ? 1 : 2 * jac.size();
    uses_ = 0;
    inverted_ = false;
    return BandedSolver<double>::Factorize();
  }
  void Solve(double* b) const {
    const double s = Ratio();
    if (!scaled_ || s == 1.0) return Unscaled(b);
    const int n = jac.size();
    for (int r = d_; r < n; ++r) b[r] *= s;  // R
    Unscaled(b);
    for (int c = 0; c < d_; ++c) b[lambda3_ + c] /= s;  // Q
  }

  // The largest system kept as an inverse: the sizes measured (an lgl16
  // element of two coordinates has n = 36).
  static constexpr int kMaxInverse = 36;
  // Whether solves go through the inverse (tests).
  bool inverted() const { return inverted_; }

 private:
  // b ← J(Δt_f)⁻¹ b: by substitution, or by the inverse once formed.
  void Unscaled(double* b) const {
    const int n = jac.size();
    if (inverted_) {
      Eigen::Map<Eigen::VectorXd> v(b, n);
      product_.noalias() = inverse_ * v;
      v = product_;
      ++uses_;
      return;
    }
    BandedSolver<double>::Solve(b);
    if (n > kMaxInverse || ++uses_ < threshold_) return;
    inverse_.setIdentity(n, n);
    for (int j = 0; j < n; ++j)
      BandedSolver<double>::Solve(inverse_.col(j).data());
    product_.resize(n);
    inverted_ = true;
  }

  int d_, lambda3_;
  bool scaled_;
  double dt_ = 1.0, factored_dt_ = 1.0;
  // Substitutions since the factorization, and its inverse once formed
  // (Unscaled; Solve is const for Newton, these are its cache).
  mutable int uses_ = 0, threshold_ = 0;
  mutable bool inverted_ = false;
  mutable Eigen::MatrixXd inverse_;
  mutable Eigen::VectorXd product_;
};

}  // namespace vivp::variational::detail
