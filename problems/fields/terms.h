// A field density composed of named terms chosen at run time (a field
// scene's [[term]] tables), the field counterpart of problems/composed.h:
//
//   using namespace vivp::fields;
//   ComposedDensity<1> sine_gordon{{terms::Kinetic{}, terms::Gradient{},
//                                   terms::SineGordon{}}};
//
// L is the sum of the listed terms only, so a term that is not listed costs
// nothing. Each term is L(φ, φ_t, ∇φ) for M components in d spatial
// dimensions, templated on the scalar, and the sum is a density of
// densities.h (ComposedDensity<M, d>, d = 1 by default): the pointwise
// automatic differentiation of the field system applies unchanged. Spec() is
// the term's scene name, formula and parameter table (effect_parameters.h),
// from which the scene reader and its help are generated. With |φ|² = Σ_a φ_a²:
//
//   kinetic       L += ½|φ_t|²
//   gradient      L −= ½c²|∇φ|²  (Σ over the d axes and M components)
//   mass          L −= ½m²|φ|²
//   sine_gordon   L −= 1 − cos φ              (one component)
//   phi4          L −= ¼λ(|φ|² − v²)²
//   quartic       L −= ¼λ|φ|⁴
//   maxwell       L += ½|E|² − ½|F|²          (the potentials; alone)
//   scalar_qed    L += |D_tφ|² − |∇_Aφ|² − m²|φ|² with maxwell/e(t)²
//   abelian_higgs L −= (λ/2)(|φ|² − v²)²      (with scalar_qed)
//
// kinetic + gradient + mass is Klein–Gordon, + sine_gordon sine-Gordon,
// + phi4 the φ⁴ theory, and with two components kinetic + gradient + mass +
// quartic the complex |φ|⁴ field (densities.h, which these reproduce).
#pragma once

#include <cmath>
#include <variant>
#include <vector>

#include "problems/effect_parameters.h"
#include "problems/fields/densities.h"
#include "problems/fields/gauge.h"

namespace vivp::fields {

namespace terms {

using problems::EffectSpec;
using problems::ParameterKind;

namespace detail {
template <int M, class T>
T Square(const T* a) {
  T s = a[0] * a[0];
  for (int c = 1; c < M; ++c) s += a[c] * a[c];
  return s;
}
}  // namespace detail

struct Kinetic {
  static EffectSpec<Kinetic> Spec() {
    return {"kinetic", "L += ½|φ_t|²", {}, /*kinetic=*/true};
  }
  template <int M, int d, class T>
  T Density(const T*, const T* phi_t, const T*) const {
    return T(0.5) * detail::Square<M>(phi_t);
  }
};

struct Gradient {
  double c = 1.0;
  static EffectSpec<Gradient> Spec() {
    return {"gradient",
            "L −= ½c²|∇φ|²",
            {{"c", ParameterKind::kPositive, &Gradient::c, "wave speed c"}}};
  }
  template <int M, int d, class T>
  T Density(const T*, const T*, const T* phi_x) const {
    T s = GradientSquared<d, M>(phi_x, 0);
    for (int a = 1; a < M; ++a) s += GradientSquared<d, M>(phi_x, a);
    return T(-0.5 * c * c) * s;
  }
};

struct Mass {
  double m = 1.0;
  static EffectSpec<Mass> Spec() {
    return {"mass",
            "L −= ½m²|φ|²",
            {{"m", ParameterKind::kNonNegative, &Mass::m, "mass m"}}};
  }
  template <int M, int d, class T>
  T Density(const T* phi, const T*, const T*) const {
    return T(-0.5 * m * m) * detail::Square<M>(phi);
  }
};

// Units with m = c = 1 (the exact kink and breather of exact.h are those).
struct SineGordon {
  static EffectSpec<SineGordon> Spec() {
    return {"sine_gordon", "L −= 1 − cos φ  (one component)", {}};
  }
  template <int M, int d, class T>
  T Density(const T* phi, const T*, const T*) const {
    using std::cos;
    return cos(phi[0]) - T(1.0);
  }
};

struct Phi4 {
  double lambda = 2.0, v = 1.0;
  static EffectSpec<Phi4> Spec() {
    using K = ParameterKind;
    return {"phi4",
            "L −= ¼λ(|φ|² − v²)²",
            {{"lambda", K::kNonNegative, &Phi4::lambda, "coupling λ"},
             {"v", K::kReal, &Phi4::v, "vacuum |φ| = v"}}};
  }
  template <int M, int d, class T>
  T Density(const T* phi, const T*, const T*) const {
    const T w = detail::Square<M>(phi) - T(v * v);
    return T(-0.25 * lambda) * w * w;
  }
};

struct Quartic {
  double lambda = 1.0;
  static EffectSpec<Quartic> Spec() {
    return {"quartic",
            "L −= ¼λ|φ|⁴",
            {{"lambda", ParameterKind::kNonNegative, &Quartic::lambda,
              "coupling λ"}}};
  }
  template <int M, int d, class T>
  T Density(const T* phi, const T*, const T*) const {
    const T r2 = detail::Square<M>(phi);
    return T(-0.25 * lambda) * r2 * r2;
  }
};

// Electromagnetism, −¼F_μνF^μν (gauge.h): the field's components are the
// potentials (A₀, A₁ … A_d), and the term stands alone (a scene with it is
// solved as fields::MaxwellIn<d>, whose A₀ has no time derivative; with
// 'scalar_qed' the scene is solved on links, core/action/charged_field.h).
struct Maxwell {
  static EffectSpec<Maxwell> Spec() {
    return {"maxwell",
            "L += ½|E|² − ½|F|², E = −∇A₀ − ∂_tA  (components A₀ … A_d; "
            "alone, or with 'scalar_qed')",
            {},
            /*kinetic=*/true};
  }
  template <int M, int d, class T>
  T Density(const T* phi, const T* phi_t, const T* phi_x) const {
    if constexpr (M == d + 1)
      return MaxwellIn<d>{}(phi, phi_t, phi_x);
    else
      return T(0.0);  // the reader refuses other component counts
  }
};

// Charged matter (charged.h): a complex scalar of unit charge under D_μ =
// ∂_μ − iA_μ with the coupling e(t) = e(1 + a sin ωt) in front of the
// 'maxwell' term, L = (E² − B²)/(2e(t)²) + |D_tφ|² − |∇_Aφ|² − m²|φ|². Not
// a nodal density: a scene with it is solved as core/action/charged_field.h
// on links, with 'maxwell' and no other terms but 'abelian_higgs'.
struct ScalarQed {
  double charge = 1.0, modulation = 0.0, frequency = 0.0, mass = 0.0;
  static EffectSpec<ScalarQed> Spec() {
    using K = ParameterKind;
    return {
        "scalar_qed",
        "L += |D_tφ|² − |∇_Aφ|² − m²|φ|², D = ∂ − iA, with 'maxwell' as "
        "(E² − B²)/(2e(t)²), e(t) = e(1 + a sin ωt)",
        {{"charge", K::kPositive, &ScalarQed::charge, "coupling e"},
         {"modulation", K::kReal, &ScalarQed::modulation, "a of e(t), |a| < 1"},
         {"frequency", K::kNonNegative, &ScalarQed::frequency, "ω of e(t)"},
         {"mass", K::kNonNegative, &ScalarQed::mass, "mass m"}},
        /*kinetic=*/true};
  }
  template <int M, int d, class T>
  T Density(const T*, const T*, const T*) const {
    return T(0.0);  // on links (charged_field.h), not a nodal density
  }
};

// The Abelian Higgs potential of a 'scalar_qed' field; critical coupling
// (Bogomolny) is λ = e².
struct AbelianHiggs {
  double lambda = 1.0, v = 1.0;
  static EffectSpec<AbelianHiggs> Spec() {
    using K = ParameterKind;
    return {"abelian_higgs",
            "L −= (λ/2)(|φ|² − v²)²  (with 'scalar_qed')",
            {{"lambda", K::kNonNegative, &AbelianHiggs::lambda, "coupling λ"},
             {"v", K::kReal, &AbelianHiggs::v, "vacuum |φ| = v"}}};
  }
  template <int M, int d, class T>
  T Density(const T*, const T*, const T*) const {
    return T(0.0);  // with 'scalar_qed' (charged_field.h)
  }
};

}  // namespace terms

// Every term a field scene may list; a new term is its struct above and its
// name here.
using FieldTerm =
    std::variant<terms::Kinetic, terms::Gradient, terms::Mass,
                 terms::SineGordon, terms::Phi4, terms::Quartic, terms::Maxwell,
                 terms::ScalarQed, terms::AbelianHiggs>;

template <int M, int d = 1>
struct ComposedDensity {
  static constexpr int kDim = M, kSpaceDim = d;
  std::vector<FieldTerm> terms;

  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    T sum = T(0.0);
    for (const FieldTerm& term : terms)
      std::visit(
          [&](const auto& t) {
            sum += t.template Density<M, d>(phi, phi_t, phi_x);
          },
          term);
    return sum;
  }
};

}  // namespace vivp::fields
