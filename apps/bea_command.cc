// `vivp bea derive` and `vivp bea verify`: backward error analysis
// (McLachlan & Offen 2023) from the command line. The engine (solvers/bea)
// derives; this file registers the commands and prints and writes what
// derive finds. bea_options.cc parses the method, bea_verify.cc verifies.
#include "apps/bea_command.h"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/command.h"
#include "solvers/bea/conservation.h"
#include "solvers/bea/derivation.h"

namespace vivp::apps {
namespace {

using bea::Series;

// Stormer-Verlet's W = -U: U_a -> -W_a for printing.
GiNaC::exmap ToW(const bea::BeaResult& r) {
  GiNaC::exmap m;
  if (r.jet->model() != bea::PotentialModel::kGeneric) return m;
  const int d = r.jet->dim();
  std::vector<int> a(d, 0);
  std::function<void(int, int)> walk = [&](int i, int left) {
    if (i == d) {
      const GiNaC::symbol u = r.jet->U(a);
      std::string name = u.get_name(), tex = "W";
      name[0] = 'W';
      if (name.size() > 1) {
        tex += "_{";
        tex += name.substr(2);
        tex += '}';
      }
      m[u] = -GiNaC::symbol(name, tex);
      return;
    }
    for (a[i] = 0; a[i] <= left; ++a[i]) walk(i + 1, left - a[i]);
    a[i] = 0;
  };
  walk(0, r.order + 4);
  return m;
}

std::string Show(const GiNaC::ex& e, const std::string& format) {
  std::ostringstream out;
  if (format == "latex") out << GiNaC::latex;
  out << e;
  return out.str();
}

std::string ShowSeries(const Series& s, const GiNaC::exmap& w,
                       const std::string& format) {
  std::string out;
  for (int p = 0; p <= s.order(); ++p) {
    const GiNaC::ex c = GiNaC::expand(s[p].subs(w));
    if (c.is_zero()) continue;
    if (!out.empty()) out += "\n    + ";
    if (p == 0)
      out += Show(c, format);
    else
      out += (format == "latex" ? "h^{" + std::to_string(p) + "} \\left("
                                : "h^" + std::to_string(p) + " (") +
             Show(c, format) + (format == "latex" ? "\\right)" : ")");
  }
  return out.empty() ? "0" : out;
}

nlohmann::json SeriesJson(const Series& s, const GiNaC::exmap& w) {
  nlohmann::json j = nlohmann::json::array();
  for (int p = 0; p <= s.order(); ++p)
    j.push_back(Show(GiNaC::expand(s[p].subs(w)), "text"));
  return j;
}

int RunDerive(BeaOptions o) {
  GiNaC::symtab symbols;
  const bea::Method method = MakeBeaMethod(o, symbols);
  if (o.format != "text" && o.format != "latex" && o.format != "json")
    throw UsageError("--format must be text, latex or json");
  try {  // numeric coefficients: warn about instability (eq. 4.1, alpha > 0)
    const auto stability =
        bea::CheckStability(bea::NumericCoefficients(method));
    if (!stability.stable)
      std::cerr << "vivp: warning: " << stability.reason << "\n";
  } catch (const std::invalid_argument&) {
    // Symbolic coefficients: stability depends on their values.
  }
  const auto r = bea::Derive(method, BeaDeriveOptions(o, o.radial));
  const GiNaC::exmap w = o.in_w ? ToW(r) : GiNaC::exmap{};
  const int d = r.jet->dim();
  auto coord = [&](int a) {
    return (a < d ? "x" : "v") + std::to_string(a % d + 1);
  };
  if (o.format == "json") {
    nlohmann::json j = {{"method", method.name},
                        {"dim", d},
                        {"order", r.order},
                        {"seconds", r.seconds}};
    for (int i = 0; i < d; ++i)
      j["modified_equation"].push_back(SeriesJson(r.f[i], w));
    j["hamiltonian"] = SeriesJson(r.hamiltonian, w);
    for (int a = 0; a < 2 * d; ++a)
      for (int b = a + 1; b < 2 * d; ++b)
        j["omega"][coord(a) + "," + coord(b)] = SeriesJson(r.omega[a][b], w);
    if (r.charge) j["charge"] = SeriesJson(*r.charge, w);
    if (r.modified_lagrangian)
      j["modified_lagrangian"] = SeriesJson(*r.modified_lagrangian, w);
    for (const auto& c : r.checks)
      j["checks"].push_back({{"name", c.name}, {"passed", c.passed}});
    std::cout << j.dump(1) << "\n";
    return 0;
  }
  const std::string& f = o.format;
  std::cout << "# " << method.name << ", d = " << d << ", to h^" << r.order
            << " (derived in " << std::setprecision(3) << r.seconds
            << " s). Conventions: x'' = grad U, L = |v|^2/2 + U, v = x'"
            << (o.in_w ? ", printed with W = -U" : "") << "\n";
  for (int i = 0; i < d; ++i)
    std::cout << "x" << i + 1 << "'' = " << ShowSeries(r.f[i], w, f) << "\n";
  std::cout << "H_mod = " << ShowSeries(r.hamiltonian, w, f) << "\n";
  std::cout << "omega (frame x, v; omega z' = grad H):\n";
  for (int a = 0; a < 2 * d; ++a)
    for (int b = a + 1; b < 2 * d; ++b)
      if (!r.omega[a][b].IsZero())
        std::cout << "  omega[" << coord(a) << "," << coord(b)
                  << "] = " << ShowSeries(r.omega[a][b], w, f) << "\n";
  if (r.charge)
    std::cout << "I (rotation) = " << ShowSeries(*r.charge, w, f) << "\n";
  if (r.modified_lagrangian)
    std::cout << "L_mod = " << ShowSeries(*r.modified_lagrangian, w, f) << "\n";
  else
    std::cout << "L_mod: none in the original variables (the v-v block of "
                 "omega is nonzero, Proposition 6.1)\n";
  for (const auto& c : r.checks)
    std::cout << "check: " << c.name << ": " << (c.passed ? "ok" : "FAILED")
              << "\n";
  return 0;
}

void AddMethodOptions(CLI::App* cmd, BeaOptions& o) {
  cmd->add_option("--method", o.method, "sv, lmm4 (eq. 4.1) or midpoint")
      ->capture_default_str();
  cmd->add_option("--alpha", o.alpha,
                  "lmm4 with A = alpha I (a number, or a name to keep it "
                  "symbolic; default: symbolic alpha)");
  cmd->add_option("--matrix", o.matrix,
                  "lmm4 with the symmetric A = [[a11, a12], [a12, a22]]: "
                  "a11,a12,a22 (implies --dim 2)");
  cmd->add_option("--dim", o.dim,
                  "dimension d (default 1, or 2 with --matrix)");
  cmd->add_option("--order", o.order, "truncation order K (even): h^K")
      ->capture_default_str();
}

}  // namespace

Runner AddBeaCommand(CLI::App& app) {
  auto o = std::make_shared<BeaOptions>();
  CLI::App* bea = app.add_subcommand(
      "bea",
      "Backward error analysis (McLachlan & Offen 2023): modified "
      "equations, Hamiltonians, symplectic forms and charges");
  bea->require_subcommand(1);
  CLI::App* derive = bea->add_subcommand(
      "derive", "Print the modified equation, H_mod, omega, charges, L_mod");
  AddMethodOptions(derive, *o);
  derive->add_flag("--radial", o->radial,
                   "U = V(|x|^2)/2 and its rotation charge (d = 2)");
  derive->add_flag("--w", o->in_w, "print with W = -U (Appendix A's W)");
  derive->add_option("--format", o->format, "text, latex or json")
      ->capture_default_str();
  CLI::App* verify = bea->add_subcommand(
      "verify",
      "Run the method and measure the conservation of H_mod and "
      "I_mod over a step-size sweep");
  AddMethodOptions(verify, *o);
  verify->add_option("--steps", o->steps, "step sizes h1,h2,...")->required();
  verify->add_option("--t-end", o->t_end, "end time T")
      ->check(FiniteNumber())
      ->capture_default_str();
  verify
      ->add_option("--differences", o->differences,
                   "order of the central differences for x' (2..12, even)")
      ->check(CLI::IsMember({2, 4, 6, 8, 10, 12}))
      ->capture_default_str();
  verify->add_option("--potential", o->potential,
                     "pendulum (d = 1) or gaussian U = exp(-|x|^2/2)");
  verify->add_option("--x0", o->x0, "x(0), comma-separated");
  verify->add_option("--v0", o->v0, "x'(0), comma-separated");
  verify->add_option("--json", o->json, "write rows and slopes (- for stdout)");
  verify->add_flag("--force", o->force, "overwrite existing output");
  return [o, derive, verify] {
    if (derive->parsed()) return RunDerive(*o);
    if (verify->parsed()) return RunBeaVerify(*o);
    return 0;
  };
}

}  // namespace vivp::apps
