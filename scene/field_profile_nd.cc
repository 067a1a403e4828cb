// The profiles of a field on a grid of 2 or 3 axes, radially symmetric about
// a center or a plane wave along a wave vector, with r = |x − center|:
//
//   gaussian    φ = A exp(−r²/(2σ²)), φ_t = 0 (no exact solution).
//   ring        the sine-Gordon ring soliton of Christiansen & Lomdahl,
//               "Numerical solutions of 2+1 dimensional sine-Gordon solitons"
//               (Physica D 2, 1981): a circular kink φ = 4 atan exp(R − r)
//               at rest, which shrinks, collapses near the center and
//               re-expands, radiating (no exact solution).
//   oscillon    a φ⁴ bubble of Copeland, Gleiser & Müller, "Oscillons:
//               resonant configurations during bubble collapse" (Phys.
//               Rev. D 52, 1995): φ = v + (φ_c − v) exp(−r²/R²) at rest, the
//               core φ_c in the other vacuum by default; it settles into a
//               long-lived oscillating lump (no exact solution).
//   plane_wave  φ = A cos(k·x − ωt) (and φ₁ = A sin(k·x − ωt) for two
//               components), exact with ω² = c²|k|² + w(A²) as in one
//               dimension; with a 'maxwell' term the transverse wave
//               A = A ε sin(k·x − ωt), A₀ = 0, ω = |k|, ε ⊥ k.
#include <cmath>
#include <map>

#include "problems/fields/profiles.h"
#include "scene/field_profile.h"
#include "scene/text.h"

namespace vivp::scene::detail {

namespace {

using Formula = FieldFormula;

// |x − center|² over the scene's d axes.
struct Radius {
  std::vector<double> center;
  double Squared(const double* x) const {
    double r2 = 0;
    for (std::size_t a = 0; a < center.size(); ++a)
      r2 += (x[a] - center[a]) * (x[a] - center[a]);
    return r2;
  }
};

// A profile at rest, φ = f(r²).
template <class F>
Formula AtRest(Radius r, F f) {
  return [r, f](double, const double* x, double* phi, double* phi_t) {
    phi[0] = f(r.Squared(x));
    phi_t[0] = 0;
  };
}

ProfileFormulas Radial(const ProfileValues& p, const TermSet& terms,
                       const std::string& name) {
  const FieldScene& s = p.s;
  const Radius r{s.initial.vectors.at("center")};
  if (name == "gaussian") {
    if (!(p["width"] > 0))
      p.Fail("width",
             "width = " + FormatNumber(p["width"]) + " is not positive",
             "a width σ > 0");
    const double a = p["amplitude"], w2 = 2 * p["width"] * p["width"];
    return {AtRest(r, [a, w2](double r2) { return a * std::exp(-r2 / w2); }),
            {},
            "a Gaussian pulse in 2 or 3 dimensions has no exact solution here"};
  }
  if (!(p["radius"] > 0))
    p.Fail("radius",
           "radius = " + FormatNumber(p["radius"]) + " is not positive",
           "a radius R > 0");
  const double radius = p["radius"];
  if (name == "ring") {
    if (!terms.Has("sine_gordon"))
      p.Fail("profile", "profile 'ring' is a sine-Gordon ring soliton",
             "a 'sine_gordon' term");
    return {AtRest(r,
                   [radius](double r2) {
                     return 4 * std::atan(std::exp(radius - std::sqrt(r2)));
                   }),
            {},
            "the sine-Gordon ring soliton has no exact solution"};
  }
  // oscillon
  if (!terms.Has("phi4"))
    p.Fail("profile", "profile 'oscillon' is a φ⁴ bubble",
           "a 'phi4' term (its vacuum v sets the outside value)");
  const double v = terms.Value("phi4", "v", 1.0);
  const double core = p.t.get("core") ? p["core"] : -v;
  const double r0 = radius * radius;
  return {
      AtRest(r, [v, core, r0](
                    double r2) { return v + (core - v) * std::exp(-r2 / r0); }),
      {},
      "a φ⁴ oscillon has no exact solution"};
}

ProfileFormulas PlaneWaveNd(const ProfileValues& p, const TermSet& terms) {
  const FieldScene& s = p.s;
  const std::vector<double> k = s.initial.vectors.at("k");
  double k2 = 0;
  for (double ka : k) k2 += ka * ka;
  const auto [omega, exact] = PlaneWaveOmega(p, terms, k2);
  // PlaneWave takes the phase k·x as its x with k = 1.
  const fields::PlaneWave plane{p["amplitude"], 1.0, omega, s.components};
  const Formula wave = [plane, k](double t, const double* x, double* phi,
                                  double* phi_t) {
    double phase = 0;
    for (std::size_t b = 0; b < k.size(); ++b) phase += k[b] * x[b];
    plane(t, phase, phi, phi_t);
  };
  ProfileFormulas f{wave, {}, ""};
  if (exact)
    f.exact = wave;
  else
    f.no_exact =
        "a plane wave is exact for the terms kinetic, gradient and "
        "mass only (and quartic, phi4 for two components)";
  return f;
}

// Electromagnetism: A = A ε sin(k·x − ωt), A₀ = 0, ω = |k|, ε a unit
// vector ⊥ k (in 2 D (−k_y, k_x)/|k|; in 3 D along k × ẑ, or k × x̂ when
// k ∥ ẑ): the continuum's transverse wave, exact in the gauge A₀ = 0.
ProfileFormulas MaxwellWave(const ProfileValues& p) {
  const std::vector<double> k = p.s.initial.vectors.at("k");
  const int d = int(k.size());
  double k2 = 0;
  for (double ka : k) k2 += ka * ka;
  if (!(k2 > 0)) p.Fail("k", "k = 0 is not a wave", "a wave vector k ≠ 0");
  const double omega = std::sqrt(k2), amplitude = p["amplitude"];
  std::vector<double> eps(d);
  if (d == 2) {
    eps = {-k[1] / omega, k[0] / omega};
  } else {
    const bool along_z = k[0] == 0 && k[1] == 0;
    const double u[3] = {along_z ? 1.0 : 0.0, 0.0, along_z ? 0.0 : 1.0};
    eps = {k[1] * u[2] - k[2] * u[1], k[2] * u[0] - k[0] * u[2],
           k[0] * u[1] - k[1] * u[0]};
    const double norm =
        std::sqrt(eps[0] * eps[0] + eps[1] * eps[1] + eps[2] * eps[2]);
    for (double& e : eps) e /= norm;
  }
  const Formula wave = [k, eps, omega, amplitude](double t, const double* x,
                                                  double* phi, double* phi_t) {
    double phase = -omega * t;
    for (std::size_t b = 0; b < k.size(); ++b) phase += k[b] * x[b];
    phi[0] = phi_t[0] = 0;
    for (std::size_t b = 0; b < k.size(); ++b) {
      phi[1 + b] = amplitude * eps[b] * std::sin(phase);
      phi_t[1 + b] = -omega * amplitude * eps[b] * std::cos(phase);
    }
  };
  return {wave, wave, ""};
}

}  // namespace

const std::vector<std::string>& ProfileNamesNd() {
  static const std::vector<std::string> names = {"gaussian", "ring", "oscillon",
                                                 "plane_wave"};
  return names;
}

const std::vector<ProfileKey>& ProfileKeysNd(const std::string& profile) {
  static const std::map<std::string, std::vector<ProfileKey>> keys = {
      {"gaussian",
       {{"amplitude", 1.0, "A"},
        {"width", 1.0, "σ > 0"},
        {"center", 0.0, "the center, one coordinate per axis", true}}},
      {"ring",
       {{"radius", 6.0, "R > 0"},
        {"center", 0.0, "the center, one coordinate per axis", true}}},
      {"oscillon",
       {{"radius", 2.0, "R > 0"},
        {"core", 0.0, "φ at the center (default −v, the other vacuum)"},
        {"center", 0.0, "the center, one coordinate per axis", true}}},
      {"plane_wave",
       {{"amplitude", 1.0, "A"},
        {"k", 1.0, "the wave vector, one component per axis", true}}}};
  return keys.at(profile);
}

ProfileFormulas MakeProfileNd(const TomlReader& r, const toml::table& initial,
                              const FieldScene& s) {
  const ProfileValues p{r, initial, s};
  const TermSet terms{s};
  const std::string& name = s.initial.profile;
  if (s.Gauge()) {
    if (name != "plane_wave")
      p.Fail("profile",
             "profile " + Quote(name) +
                 " is for a scalar field, not the "
                 "potentials of a 'maxwell' term",
             "profile = \"plane_wave\" (a transverse wave)");
    return MaxwellWave(p);
  }
  if (name == "plane_wave") return PlaneWaveNd(p, terms);
  if (s.components != 1)
    p.Fail("profile",
           "profile " + Quote(name) + " is for one component, not " +
               std::to_string(s.components),
           "profile = \"plane_wave\" for a complex field");
  return Radial(p, terms, name);
}

}  // namespace vivp::scene::detail
