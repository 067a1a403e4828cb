#include "scene/reference.h"

#include <algorithm>
#include <array>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "problems/anharmonic.h"

namespace vivp::scene {

namespace {

// The effect types of a scene, sorted, e.g. {"central", "kinetic"}.
std::vector<std::string> Types(const Scene& s) {
  std::vector<std::string> t;
  for (const auto& e : s.effects) t.push_back(e.type->name);
  std::sort(t.begin(), t.end());
  return t;
}

double Value(const Scene& s, const std::string& type,
             const std::string& parameter) {
  // The closed forms read the effects' declared parameters (Spec(),
  // problems/effects.h); a name they do not declare is a bug here.
  const EffectType* declared = FindEffectType(type);
  if (!declared ||
      std::none_of(declared->parameters.begin(), declared->parameters.end(),
                   [&](const ParameterSpec& p) { return p.name == parameter; }))
    throw std::logic_error("a closed-form reference reads '" + type + "." +
                           parameter + "', which no effect declares");
  for (const auto& e : s.effects)
    if (e.type->name == type) return e.values.at(parameter).at(0);
  return 0;
}

bool ScalarMass(const Scene& s) {
  for (const auto& e : s.effects)
    if (e.type->name == "kinetic" && e.values.count("matrix")) return false;
  return true;
}

// ẍ = −(κ/m)x³ (kinetic + quartic, dof 1): problems::Anharmonic.
class AnharmonicReference : public Reference {
 public:
  explicit AnharmonicReference(const Scene& s) : t0_(s.t_start) {
    exact_.kappa = Value(s, "quartic", "kappa") / Value(s, "kinetic", "mass");
    exact_.x0 = s.x0[0];
    exact_.v0 = s.v0[0];
  }
  void State(double t, double* x, double* v) override {
    const auto st = exact_.Exact(t - t0_);
    x[0] = st.x;
    v[0] = st.v;
  }
  std::string description() const override {
    return "exact: Jacobi elliptic cn (anharmonic oscillator)";
  }

 private:
  double t0_;
  problems::Anharmonic exact_;
};

// ẍ = −ω² sin x, ω² = s/m, librating (energy below the separatrix):
// sin(x/2) = k sn(ω(t − t0) + u0, k), ẋ = 2kω cn(…), k² = (1 + e/ω²)/2 with
// e = ½ẋ² − ω² cos x. x is reduced to (−π, π] and the offset added back.
class PendulumReference : public Reference {
 public:
  explicit PendulumReference(const Scene& s) : t0_(s.t_start) {
    omega_ = std::sqrt(Value(s, "pendulum", "strength") /
                       Value(s, "kinetic", "mass"));
    offset_ = 2 * M_PI * std::round(s.x0[0] / (2 * M_PI));
    const double x0 = s.x0[0] - offset_, v0 = s.v0[0];
    const double e = 0.5 * v0 * v0 - omega_ * omega_ * std::cos(x0);
    k_ = std::sqrt(std::fmax(0.0, 0.5 * (1 + e / (omega_ * omega_))));
    const double ratio =
        k_ > 0 ? std::fmin(1.0, std::fmax(-1.0, std::sin(0.5 * x0) / k_)) : 0;
    u0_ = k_ > 0 ? boost::math::ellint_1(k_, std::asin(ratio)) : 0;
    if (v0 < 0) u0_ = 2 * boost::math::ellint_1(k_) - u0_;  // cn < 0 there
  }
  void State(double t, double* x, double* v) override {
    double cn = 0, dn = 0;
    const double sn = k_ > 0 ? boost::math::jacobi_elliptic(
                                   k_, omega_ * (t - t0_) + u0_, &cn, &dn)
                             : 0.0;
    x[0] = offset_ + 2 * std::asin(k_ * sn);
    v[0] = 2 * k_ * omega_ * cn;
  }
  std::string description() const override {
    return "exact: Jacobi elliptic sn (pendulum libration)";
  }

 private:
  double t0_, omega_, offset_, k_, u0_;
};

// ẍ = −μ x/|x|³, μ = k/m, bound orbit: Lagrange's f and g with the change of
// eccentric anomaly ΔE from Kepler's equation in difference form,
//   nΔt = ΔE + (σ0/√a)(1 − cos ΔE) − (1 − r0/a) sin ΔE,  σ0 = r0·v0/√μ,
// whose derivative r/a is positive: safeguarded Newton converges from any
// bracket. Circular orbits need no special case.
class KeplerReference : public Reference {
 public:
  explicit KeplerReference(const Scene& s) : t0_(s.t_start) {
    mu_ = Value(s, "central", "k") / Value(s, "kinetic", "mass");
    r0_ = {s.x0[0], s.x0[1]};
    v0_ = {s.v0[0], s.v0[1]};
    r0n_ = std::hypot(r0_[0], r0_[1]);
    const double v2 = v0_[0] * v0_[0] + v0_[1] * v0_[1];
    a_ = 1 / (2 / r0n_ - v2 / mu_);
    sigma0_ = (r0_[0] * v0_[0] + r0_[1] * v0_[1]) / std::sqrt(mu_);
    n_ = std::sqrt(mu_ / (a_ * a_ * a_));
  }
  void State(double t, double* x, double* v) override {
    // Whole orbits drop out: ΔE and ΔE + 2π give the same state.
    const double m = std::remainder(n_ * (t - t0_), 2 * M_PI);
    const double sa = std::sqrt(a_), c1 = sigma0_ / sa, c2 = 1 - r0n_ / a_;
    auto kepler = [&](double de) {
      return de + c1 * (1 - std::cos(de)) - c2 * std::sin(de) - m;
    };
    double lo = m - 2, hi = m + 2, de = m;  // |ΔE − nΔt| ≤ 2e < 2
    for (int it = 0; it < 200; ++it) {
      const double f = kepler(de);
      if (f > 0)
        hi = de;
      else
        lo = de;
      const double slope = 1 + c1 * std::sin(de) - c2 * std::cos(de);
      double next = de - f / slope;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::fabs(next - de) <= 4e-16 * (1 + std::fabs(de))) {
        de = next;
        break;
      }
      de = next;
    }
    const double c = std::cos(de), s = std::sin(de);
    const double r = a_ + (r0n_ - a_) * c + sigma0_ * sa * s;
    const double f = 1 - a_ / r0n_ * (1 - c);
    const double g = a_ * sigma0_ / std::sqrt(mu_) * (1 - c) +
                     r0n_ * std::sqrt(a_ / mu_) * s;
    const double fdot = -std::sqrt(mu_ * a_) / (r * r0n_) * s;
    const double gdot = 1 - a_ / r * (1 - c);
    for (int k = 0; k < 2; ++k) {
      x[k] = f * r0_[k] + g * v0_[k];
      v[k] = fdot * r0_[k] + gdot * v0_[k];
    }
  }
  std::string description() const override {
    return "exact: Kepler's equation (bound orbit)";
  }

 private:
  double t0_, mu_, r0n_, a_, sigma0_, n_;
  std::array<double, 2> r0_, v0_;
};

const char* kClosedForms =
    "closed forms exist for linear systems (kinetic, spring, gravity, "
    "damping, growth, chain with beta = 0), kinetic + quartic (dof 1), "
    "kinetic + pendulum (dof 1, librating) and kinetic + central (dof 2, "
    "bound orbit)";

}  // namespace

bool LinearScene(const Scene& s) {
  for (const auto& e : s.effects) {
    const std::string& n = e.type->name;
    const bool linear = n == "kinetic" || n == "spring" || n == "gravity" ||
                        n == "damping" || n == "growth" ||
                        (n == "chain" && e.values.at("beta")[0] == 0);
    if (!linear) return false;
  }
  return true;
}

std::string ExactSolutionUnavailable(const Scene& s) {
  if (LinearScene(s)) return "";
  const auto types = Types(s);
  const bool scalar = ScalarMass(s);
  using V = std::vector<std::string>;
  if (s.dof == 1 && scalar && types == V{"kinetic", "quartic"}) return "";
  if (s.dof == 1 && scalar && types == V{"kinetic", "pendulum"}) {
    const double w2 =
        Value(s, "pendulum", "strength") / Value(s, "kinetic", "mass");
    const double x0 = s.x0[0] - 2 * M_PI * std::round(s.x0[0] / (2 * M_PI));
    if (0.5 * s.v0[0] * s.v0[0] - w2 * std::cos(x0) < w2) return "";
    return "the pendulum rotates over the top (energy above the separatrix), "
           "for which no closed form is implemented";
  }
  if (s.dof == 2 && scalar && types == V{"central", "kinetic"}) {
    const double mu = Value(s, "central", "k") / Value(s, "kinetic", "mass");
    const double r = std::hypot(s.x0[0], s.x0[1]);
    const double energy =
        0.5 * (s.v0[0] * s.v0[0] + s.v0[1] * s.v0[1]) - mu / r;
    if (r > 0 && energy < 0) return "";
    return "the orbit is not bound (energy >= 0) or starts at the centre; "
           "only bound orbits have the closed form implemented";
  }
  std::string list;
  for (const auto& t : types) list += (list.empty() ? "" : " + ") + t;
  return "no closed form for " + list + "; " + kClosedForms;
}

std::unique_ptr<Reference> MakeClosedForm(const Scene& s) {
  const auto types = Types(s);
  using V = std::vector<std::string>;
  if (types == V{"kinetic", "quartic"})
    return std::make_unique<AnharmonicReference>(s);
  if (types == V{"kinetic", "pendulum"})
    return std::make_unique<PendulumReference>(s);
  if (types == V{"central", "kinetic"})
    return std::make_unique<KeplerReference>(s);
  return nullptr;
}

namespace detail {

void LinearReference::State(double t, double* x, double* v) {
  const Eigen::VectorXd y = (a_ * (t - t0_)).exp() * y0_;
  for (int c = 0; c < d_; ++c) x[c] = y[c];
  if (a_.rows() == 2 * d_ + 1)
    for (int c = 0; c < d_; ++c) v[c] = y[d_ + c];
  else
    for (int c = 0; c < d_; ++c) v[c] = (a_.row(c) * y)(0);
}

std::string LinearReference::description() const {
  return "exact: matrix exponential of the linear equation of motion";
}

}  // namespace detail

}  // namespace vivp::scene
