// `vivp bea derive` and `vivp bea verify`: backward error analysis
// (McLachlan & Offen 2023) from the command line. The engine (solvers/bea)
// derives; this file parses, prints and writes.
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/command.h"
#include "solvers/bea/conservation.h"
#include "solvers/bea/derivation.h"

namespace vivp::app {
namespace {

using bea::Series;

struct BeaOptions {
  std::string method = "sv";
  std::string alpha;   // number or symbol name
  std::string matrix;  // a11,a12,a22
  int dim = 0;         // 0: 2 with --matrix, else 1
  int order = 4;
  bool radial = false;
  bool in_w = false;
  std::string format = "text";
  // verify
  std::string steps;
  double t_end = 100;
  int differences = 6;
  std::string potential;
  std::string x0, v0;
  std::string json;
  bool force = false;
};

// "-0.2" -> -1/5 exactly, "3/4", "alpha" -> a symbol.
GiNaC::ex ParseCoefficient(const std::string& s, GiNaC::symtab& symbols) {
  if (s.empty()) throw UsageError("empty coefficient");
  const auto dot = s.find('.');
  if (dot != std::string::npos &&
      s.find_first_not_of("+-0123456789.") == std::string::npos) {
    std::string digits = s.substr(0, dot) + s.substr(dot + 1);
    const std::string scale = "1" + std::string(s.size() - dot - 1, '0');
    return GiNaC::numeric((digits + "/" + scale).c_str());
  }
  try {
    GiNaC::parser reader(symbols);
    auto e = reader(s);
    symbols = reader.get_syms();
    return e;
  } catch (const std::exception&) {
    throw UsageError("cannot read coefficient '" + s +
                     "' (use a number such as -0.2 or -1/5, or a name)");
  }
}

std::vector<std::string> SplitCommas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

std::vector<double> Numbers(const std::string& s, const std::string& what) {
  std::vector<double> out;
  for (const auto& item : SplitCommas(s)) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(v))
      throw UsageError(what + ": expected comma-separated numbers, got '" + s +
                       "'");
    out.push_back(v);
  }
  return out;
}

bea::Method MakeMethod(BeaOptions& o, GiNaC::symtab& symbols) {
  if (!o.alpha.empty() && !o.matrix.empty())
    throw UsageError("give either --alpha or --matrix, not both");
  if (o.dim == 0) o.dim = o.matrix.empty() ? 1 : 2;
  if (o.dim < 1 || o.dim > 3)
    throw UsageError("--dim must be 1, 2 or 3, got " + std::to_string(o.dim));
  if (o.method != "lmm4" && (!o.alpha.empty() || !o.matrix.empty()))
    throw UsageError("--alpha and --matrix belong to --method lmm4");
  if (o.method == "sv") return bea::MakeStormerVerlet(o.dim);
  if (o.method == "midpoint") return bea::MakeMidpoint(o.dim);
  if (o.method != "lmm4")
    throw UsageError("unknown method '" + o.method +
                     "' (use sv, lmm4 or midpoint)");
  if (!o.matrix.empty()) {
    const auto a = SplitCommas(o.matrix);
    if (a.size() != 3)
      throw UsageError(
          "--matrix takes the three entries a11,a12,a22 of a "
          "symmetric 2x2 matrix, got '" +
          o.matrix + "'");
    if (o.dim != 2) throw UsageError("--matrix needs --dim 2");
    return bea::MakeLmm4(bea::SymmetricMatrix2(
        ParseCoefficient(a[0], symbols), ParseCoefficient(a[1], symbols),
        ParseCoefficient(a[2], symbols)));
  }
  const GiNaC::ex alpha =
      ParseCoefficient(o.alpha.empty() ? "alpha" : o.alpha, symbols);
  return bea::MakeLmm4(bea::ScalarMatrix(alpha, o.dim));
}

// Rotation charge with the radial model in d = 2 when asked for (derive) or
// possible (verify: scalar coefficients).
bea::DeriveOptions Options(const BeaOptions& o, bool radial) {
  bea::DeriveOptions d;
  d.order = o.order;
  if (radial) {
    if (o.dim != 2)
      throw UsageError(
          "--radial (U = V(|x|^2)/2 and the angular momentum) "
          "needs --dim 2");
    d.model = bea::PotentialModel::kRadial;
    GiNaC::matrix g(2, 2);
    g(0, 1) = -1;
    g(1, 0) = 1;
    d.symmetry = g;
  }
  return d;
}

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
  const bea::Method method = MakeMethod(o, symbols);
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
  const auto r = bea::Derive(method, Options(o, o.radial));
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

int RunVerify(BeaOptions o) {
  if (!o.json.empty() && o.json != "-") CheckOutputFile(o.json, o.force);
  if (o.method == "midpoint")
    throw UsageError("verify runs multistep methods: --method sv or lmm4");
  GiNaC::symtab symbols;
  const bea::Method method = MakeMethod(o, symbols);
  const auto coefficients = [&] {
    try {
      return bea::NumericCoefficients(method);
    } catch (const std::invalid_argument&) {
      throw UsageError(
          "verify needs numeric coefficients: give --alpha or "
          "--matrix as numbers");
    }
  }();
  // derive only warns (the modified equation of an unstable method is still
  // a formula); verify would integrate it and measure nothing but the
  // blow-up of the parasitic root, ending in overflow.
  const auto stability = bea::CheckStability(coefficients);
  if (!stability.stable)
    throw UsageError(
        "verify cannot measure conservation with an unstable "
        "method: " +
        stability.reason);
  if (o.potential.empty()) o.potential = o.dim == 1 ? "pendulum" : "gaussian";
  const bool radial =
      o.dim == 2 && o.matrix.empty() && o.potential == "gaussian";
  const auto r = bea::Derive(method, Options(o, radial));
  const auto potential = bea::MakePotential(o.potential, o.dim, r.jet->model());
  const bea::ModifiedQuantities q(r, *potential);
  bea::ConservationSetup s;
  std::vector<double> x0 =
      o.x0.empty() ? std::vector<double>{} : Numbers(o.x0, "--x0");
  std::vector<double> v0 =
      o.v0.empty() ? std::vector<double>{} : Numbers(o.v0, "--v0");
  if (x0.empty())
    x0 = o.dim == 2 ? std::vector<double>{1, -1}
                    : std::vector<double>(o.dim, 1.0);
  if (v0.empty())
    v0 = o.dim == 2 ? std::vector<double>{0.1, -0.2}
                    : std::vector<double>(o.dim, 0.0);
  if (static_cast<int>(x0.size()) != o.dim ||
      static_cast<int>(v0.size()) != o.dim)
    throw UsageError("--x0 and --v0 need " + std::to_string(o.dim) +
                     " numbers");
  s.x0 = Eigen::Map<Eigen::VectorXd>(x0.data(), o.dim);
  s.v0 = Eigen::Map<Eigen::VectorXd>(v0.data(), o.dim);
  s.t_end = o.t_end;
  s.difference_order = o.differences;
  if (!(o.t_end > 0))
    throw UsageError("--t-end: the end time must be positive, got " +
                     std::to_string(o.t_end));
  const auto steps = Numbers(o.steps, "--steps");
  for (double h : steps)
    if (!(h > 0) || o.t_end / h > 1e7 || o.t_end / h < 20) {
      // Between 20 steps (a slope needs a trajectory) and 1e7 (time).
      std::ostringstream m;
      m << "--steps: each h must lie in [t_end/1e7, t_end/20] = ["
        << o.t_end / 1e7 << ", " << o.t_end / 20 << "] for --t-end " << o.t_end
        << ", got h = " << h;
      throw UsageError(m.str());
    }
  const auto sweep = bea::ConservationSweep(r, q, *potential, s, steps);

  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  human << "# " << method.name << ", " << o.potential << ", d = " << o.dim
        << ", T = " << o.t_end << ", " << o.differences
        << "th-order differences; max |deviation|\n"
        << std::setw(8) << "h";
  for (const auto& n : sweep.names) human << std::setw(12) << n;
  human << "\n" << std::setprecision(3);
  for (const auto& row : sweep.rows) {
    human << std::setw(8) << row.h;
    for (double v : row.max_deviation) human << std::setw(12) << v;
    human << "\n";
  }
  if (!sweep.slopes.empty()) {
    human << std::setw(8) << "slope";
    for (double v : sweep.slopes) human << std::setw(12) << v;
    human << "\n";
  }
  if (!o.json.empty()) {
    nlohmann::json j = {{"method", method.name},
                        {"potential", o.potential},
                        {"dim", o.dim},
                        {"t_end", o.t_end},
                        {"difference_order", o.differences},
                        {"stable", stability.stable}};
    for (const auto& row : sweep.rows) {
      nlohmann::json jr = {{"h", row.h}, {"steps", row.steps}};
      for (std::size_t c = 0; c < sweep.names.size(); ++c)
        jr[sweep.names[c]] = JsonNumber(row.max_deviation[c]);
      j["rows"].push_back(jr);
    }
    j["slopes"] = nlohmann::json::object();
    for (std::size_t c = 0; c < sweep.slopes.size(); ++c)
      j["slopes"][sweep.names[c]] = JsonNumber(sweep.slopes[c]);
    WriteJson(o.json, j);
  }
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
    if (verify->parsed()) return RunVerify(*o);
    return 0;
  };
}

}  // namespace vivp::app
