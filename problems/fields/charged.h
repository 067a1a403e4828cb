// Scalar electrodynamics and the Abelian Higgs model: a complex scalar φ of
// unit charge coupled to a U(1) gauge field with coupling e(t) in front of
// the field strength (core/action/charged_field.h),
//
//   ℒ = (1/(2e(t)²)) (E² − B²) + |D_0φ|² − |∇_Aφ|² − V(|φ|²),
//   V(s) = m² s + (λ/2)(s − v²)²,
//
// which with A → eA is the usual form with charge e. A coupling that depends
// on time sits inside the action, so the discrete action stays gauge
// invariant at every e(t).
#pragma once

#include <functional>

namespace vivp::fields {

struct ScalarQed {
  double mass2 = 0;   // m²
  double lambda = 0;  // λ of the quartic term
  double v2 = 0;      // v², the vacuum's |φ|² when λ > 0 and m² = 0
  std::function<double(double)> coupling = [](double) { return 1.0; };

  double Potential(double s) const {
    return mass2 * s + 0.5 * lambda * (s - v2) * (s - v2);
  }
  double PotentialSlope(double s) const { return mass2 + lambda * (s - v2); }
  double PotentialCurvature(double) const { return lambda; }
  double InverseCouplingSquared(double t) const {
    const double e = coupling(t);
    return 1.0 / (e * e);
  }
};

}  // namespace vivp::fields
