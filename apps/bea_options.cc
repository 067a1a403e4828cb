// The options of `vivp bea` made into a method and the options of the
// derivation (McLachlan & Offen 2023).
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "apps/bea_command.h"
#include "apps/command.h"

namespace vivp::apps {
namespace {

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

}  // namespace

std::vector<double> ParseNumberList(const std::string& s,
                                    const std::string& what) {
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

bea::Method MakeBeaMethod(BeaOptions& o, GiNaC::symtab& symbols) {
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
bea::DeriveOptions BeaDeriveOptions(const BeaOptions& o, bool radial) {
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

}  // namespace vivp::apps
