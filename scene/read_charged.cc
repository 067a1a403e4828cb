// The reader's part for charged matter (charged_scene.h): which terms may
// join 'scalar_qed', the grid and method it is solved on, the time grid of
// whole windows, and the 'charge_pair' profile with its neutrality check.
// Every refusal names the value and what would fix it.
#include <cmath>
#include <complex>

#include "core/action/charged_field.h"
#include "core/sbp/builder.h"
#include "scene/charged_scene.h"
#include "scene/field_profile.h"
#include "scene/field_sections.h"
#include "scene/text.h"
#include "solvers/spacetime/charged_march.h"

namespace vivp::scene::detail {

namespace {

const ListedEffect* Listed(const FieldScene& s, const std::string& name) {
  for (const auto& e : s.terms)
    if (e.type->name == name) return &e;
  return nullptr;
}

}  // namespace

void ReadChargedField(const TomlReader& r, const toml::table& root,
                      FieldScene& s) {
  const ListedEffect* qed = Listed(s, "scalar_qed");
  const ListedEffect* higgs = Listed(s, "abelian_higgs");
  if (!qed)
    r.Fail(higgs->line, higgs->column,
           "term 'abelian_higgs' is the potential of a charged field, and no "
           "'scalar_qed' term gives one",
           "expected a 'scalar_qed' term (the charged field) and 'maxwell'");
  if (!Listed(s, "maxwell"))
    r.Fail(qed->line, qed->column,
           "term 'scalar_qed' couples φ to a gauge field, and no 'maxwell' "
           "term gives that field its dynamics",
           "expected a 'maxwell' term as well");
  for (const auto& e : s.terms) {
    const std::string& n = e.type->name;
    if (n != "maxwell" && n != "scalar_qed" && n != "abelian_higgs")
      r.Fail(e.line, e.column,
             "term " + Quote(n) +
                 " cannot join 'scalar_qed': the charged field's kinetic, "
                 "gradient and mass terms are its own",
             "expected 'maxwell', 'scalar_qed' (mass = m) and optionally "
             "'abelian_higgs'");
  }
  const double a = qed->values.at("modulation").at(0);
  if (!(std::abs(a) < 1))
    r.Fail(qed->line, qed->column,
           "modulation = " + FormatNumber(a) +
               " makes e(t) = e(1 + a sin ωt) vanish, and the action's 1/e(t)² "
               "is then not finite",
           "expected |modulation| < 1");
  if (s.Dim() > 2)
    r.Fail(qed->line, qed->column,
           "a charged field is marched on 1 or 2 axes; 3 are not built",
           "expected a [field] of 1 or 2 axes");
  const toml::node* field = root.get("field");
  for (const char* key : {"components", "space_order", "space_operator"})
    if (const toml::node* n = (*field->as_table()).get(key))
      r.Fail(*n,
             std::string("a charged field has no '") + key +
                 "': its components are φ and the links' A, and its spatial "
                 "differences the lattice's covariant forward differences",
             std::string("expected no '") + key + "' in [field]");
  // Boundary data would have to move with every gauge transformation: only
  // a torus, whose links wrap around, keeps the action invariant.
  for (int b = 0; b < s.Dim(); ++b)
    if (s.Axis(b).boundary != "periodic")
      r.Fail(qed->line, qed->column,
             std::string("a charged field is solved on periodic axes (its "
                         "links wrap around); axis ") +
                 "xyz"[b] + " is " + s.Axis(b).boundary +
                 ", whose boundary data would break gauge invariance",
             "expected boundary = \"periodic\" on every axis");
  s.components = 2 + s.Dim();  // the written values, ChargedValueNames
  s.output.phi_t = false;
}

void ReadChargedMethod(const TomlReader& r, const toml::table& t,
                       FieldScene& s) {
  if (const toml::node* n = t.get("tolerance"))
    r.Fail(*n, "error control is not built for a charged field",
           "expected [time] points and no tolerance");
  if (const toml::node* n = t.get("linear_solver"))
    r.Fail(*n,
           "a charged field's window is solved through its damped normal "
           "equations (sparse LDLᵀ), the one solver its gauge directions take",
           "expected no linear_solver");
  const long long minimum = sbp::Table(s.method.op).min_points;
  s.method.linear_solver = "normal-equations";
  s.method.window_points = 16;
  if (const toml::node* n = t.get("window_points")) {
    const std::string expected =
        "at least " + std::to_string(minimum) + " for " + s.method.op;
    s.method.window_points = r.Whole(*n, "window_points", 0, expected);
    if (s.method.window_points < minimum)
      r.Fail(*n,
             "window_points = " + std::to_string(s.method.window_points) +
                 (s.method.window_points == 0
                      ? " asks for one global solve; a charged field marches"
                      : " is below the operator's minimum"),
             "expected " + expected + " (16 is typical)");
  }
}

void ReadChargedPoints(const TomlReader& r, const toml::table& t,
                       FieldScene& s) {
  const toml::node& points =
      r.Require(t, "time", "points", "points = Nt, time points on [0, end]");
  s.where_time_points = r.Where(points);
  const long long w = s.method.window_points;
  s.time_points = r.Whole(points, "points", w, "at least one window's points");
  // Windows of equal Δt end to end: (points − 1) a multiple of (w − 1).
  if ((s.time_points - 1) % (w - 1) != 0) {
    const long long n = (s.time_points - 1) / (w - 1);
    r.Fail(points,
           "points = " + std::to_string(s.time_points) +
               " does not fill whole windows of " + std::to_string(w),
           "expected 1 + a multiple of " + std::to_string(w - 1) + ", e.g. " +
               std::to_string(n * (w - 1) + 1) + " or " +
               std::to_string((n + 1) * (w - 1) + 1));
  }
  const long long slice = s.GridPoints() * s.components;
  if (s.time_points > kMaxFieldValues / slice)
    r.Fail(points,
           "points = " + std::to_string(s.time_points) + " keeps more than " +
               std::to_string(kMaxFieldValues) + " values",
           "expected at most " + std::to_string(kMaxFieldValues / slice) +
               " time points on this spatial grid");
}

const std::vector<std::string>& ChargedProfileNames(int d) {
  static const std::vector<std::string> line = {"charge_pair"},
                                        plane = {"vortex_pair",
                                                 "vortex_collision"};
  return d == 1 ? line : plane;
}

std::vector<ProfileKey> ChargedProfileKeys(const FieldScene& s) {
  const double l = s.x1 - s.x0;
  if (s.initial.profile == "vortex_pair")
    return {{"separation", l / 2, "the vortex and antivortex's distance"}};
  if (s.initial.profile == "vortex_collision")
    return {{"offset", 3.0, "the vortices start at ± offset from the centre"},
            {"speed", 0.4, "their speed towards it"},
            {"transition", 1.0, "width of the velocity's change of sign"}};
  return {{"center", s.x0 + 0.35 * l,
           "the first packet's center; the second is its mirror x0 + x1 − c"},
          {"k", 0.8, "the packets' wave number"},
          {"amplitude", 0.5, "the packets' largest |φ|"},
          {"width", 1.5, "w of exp(−((x − c)/w)²)"},
          {"electric", 0.0, "a uniform background field E"}};
}

// Two packets A g(x − c)e^{ikx} on the vacuum φ = 0, the first with
// velocity −iωφ (charge −2ω|φ|²), the second at the mirror point with +iωφ,
// ω² = V'(0) + k²; A = 0 with ∂_tA = E.
ProfileFormulas MakeChargedProfile(const ProfileValues& p,
                                   const FieldScene& s) {
  const auto model = ChargedModel(s);
  const double k = p["k"], width = p["width"], amp = p["amplitude"];
  const double w2 = model.PotentialSlope(0) + k * k;
  if (!(w2 > 0))
    p.Fail(
        "profile",
        "the packets sit on φ = 0, where V'(0) + k² = " + FormatNumber(w2) +
            " is not positive: φ = 0 is not a stable vacuum of these terms",
        "expected 'abelian_higgs' with λv² < m² + k², or no 'abelian_higgs'");
  if (!(width > 0)) p.Fail("width", "width must be positive", "width > 0");
  const double c1 = p["center"], c2 = s.x0 + s.x1 - c1, e = p["electric"];
  const double omega = std::sqrt(w2);
  ProfileFormulas f;
  f.no_exact = "a charged field's scene has no exact solution";
  f.initial = [=](double, const double* x, double* phi, double* pi) {
    const std::complex<double> I(0, 1), wave = std::polar(1.0, k * x[0]);
    const auto g = [&](double c) {
      const double u = (x[0] - c) / width;
      return amp * std::exp(-u * u) * wave;
    };
    const std::complex<double> p1 = g(c1), p2 = g(c2);
    const std::complex<double> v = -I * omega * p1 + I * omega * p2;
    phi[0] = (p1 + p2).real();
    phi[1] = (p1 + p2).imag();
    phi[2] = 0;
    pi[0] = v.real();
    pi[1] = v.imag();
    pi[2] = e;
  };
  return f;
}

// The vortex profiles on a square torus: the reader checks what the
// parameters alone decide; the relaxation from the ansatz, and its refusal
// when a vortex moved or annihilated, belong to the run (PrepareVortexStart
// in charged_scene.h), so that reading a scene stays cheap.
void MakeVortexProfile(const TomlReader& r, const toml::table& t,
                       const toml::node& at, FieldScene& s) {
  const auto model = ChargedModel(s);
  const FieldAxis& y = s.Axis(1);
  if (y.space_points != s.space_points ||
      std::abs((y.x1 - y.x0) - (s.x1 - s.x0)) > 1e-12 * (s.x1 - s.x0))
    r.Fail(at,
           "the vortex profiles are built on a square torus; this grid is " +
               std::to_string(s.space_points) + " × " +
               std::to_string(y.space_points) + " points on " +
               FormatNumber(s.x1 - s.x0) + " × " + FormatNumber(y.x1 - y.x0),
           "expected equal points and domain lengths on both axes");
  if (!(model.lambda > 0 && model.v2 > 0))
    r.Fail(at,
           "a vortex needs the broken vacuum |φ| = v of an 'abelian_higgs' "
           "term with λ > 0 and v ≠ 0",
           "expected an 'abelian_higgs' term (λ = e² is critical coupling)");
  const char* key =
      s.initial.profile == "vortex_pair" ? "separation" : "offset";
  const toml::node* n = t.get(key);
  s.where_initial = r.Where(n ? *n : at);
  s.phi0.clear();
  s.phi_t0.clear();
  s.no_exact = "a charged field's scene has no exact solution";
}

void CheckNeutral(const TomlReader& r, const toml::node& at,
                  const FieldScene& s) {
  std::vector<double> phi, pi;
  ChargedSystemData(s, phi, pi);
  const std::string why = spacetime::NetChargeReason<
      action::ChargedFieldSystem<fields::ScalarQed, 1>>(s.Grid(), phi, pi);
  if (!why.empty())
    r.Fail(at, why,
           "expected packets at mirrored points (leave 'center' well inside "
           "the domain)");
}

}  // namespace vivp::scene::detail
