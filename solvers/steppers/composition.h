// Symmetric composition Φ_h = Φ_{β_s h} ∘ … ∘ Φ_{β_1 h} of a symmetric base
// method of order p (Hairer–Lubich–Wanner II.4; docs/steppers.md §2):
//   triple jump      β₁ = β₃ = 1/(2 − 2^{1/(p+1)}), β₂ = 1 − 2β₁   (p → p+2)
//   Suzuki fractal   β₁ = β₂ = β₄ = β₅ = 1/(4 − 4^{1/(p+1)}), β₃ = 1 − 4β₁
//   order 6          the triple jump applied to the order-4 triple jump
//                    (Yoshida 1990): nine substeps of the order-2 base.
// A method is its coefficient list; the engine is the same for all.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "solvers/steppers/step_result.h"

namespace vivp::steppers {

struct CompositionCoefficients {
  std::string name;
  int order = 0;
  std::vector<double> beta;
};

inline std::vector<double> TripleJump(int p) {
  const double b1 = 1 / (2 - std::pow(2.0, 1.0 / (p + 1)));
  return {b1, 1 - 2 * b1, b1};
}

inline std::vector<double> SuzukiFractal(int p) {
  const double b1 = 1 / (4 - std::pow(4.0, 1.0 / (p + 1)));
  return {b1, b1, 1 - 4 * b1, b1, b1};
}

// Composition of compositions: outer coefficient times the inner list.
inline std::vector<double> Compose(const std::vector<double>& outer,
                                   const std::vector<double>& inner) {
  std::vector<double> out;
  for (double a : outer)
    for (double b : inner) out.push_back(a * b);
  return out;
}

inline CompositionCoefficients TripleJump4() {
  return {"triple_jump", 4, TripleJump(2)};
}
inline CompositionCoefficients Suzuki4() {
  return {"suzuki", 4, SuzukiFractal(2)};
}
inline CompositionCoefficients TripleJump6() {
  return {"triple_jump6", 6, Compose(TripleJump(4), TripleJump(2))};
}

template <class Base>
class Composition {
 public:
  using Vector = typename Base::Vector;

  Composition(Base base, CompositionCoefficients coefficients)
      : base_(std::move(base)), coefficients_(std::move(coefficients)) {}

  std::string name() const { return coefficients_.name; }
  int order() const { return coefficients_.order; }
  const auto& system() const { return base_.system(); }
  long evaluations() const { return base_.evaluations(); }

  StepReport Step(Vector& y, double h) {
    StepReport total;
    for (double b : coefficients_.beta) {
      const StepReport r = base_.Step(y, b * h);
      total.iterations += r.iterations;
      if (r.status != StepOutcome::kOk) {
        total.status = r.status;
        break;
      }
    }
    return total;
  }

 private:
  Base base_;
  CompositionCoefficients coefficients_;
};

}  // namespace vivp::steppers
