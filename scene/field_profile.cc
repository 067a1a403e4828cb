#include "scene/field_profile.h"

#include <ceres/jet.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "problems/fields/exact.h"
#include "problems/fields/profiles.h"
#include "scene/text.h"

namespace vivp::scene::detail {

namespace {

using Formula = FieldFormula;

// φ and φ_t of an exact solution of exact.h (one component) at
// (t − t_c, x − x_c), φ_t by a Jet in t.
template <class U>
Formula FromExact(U u, double t_c, double x_c) {
  return [u, t_c, x_c](double t, const double* x, double* phi, double* phi_t) {
    using J = ceres::Jet<double, 1>;
    const J v = u(J(t - t_c, 0), J(x[0] - x_c));
    phi[0] = v.a;
    phi_t[0] = v.v[0];
  };
}

ProfileFormulas Gaussian(const ProfileValues& p, const TermSet& terms) {
  if (!(p["width"] > 0))
    p.Fail("width", "width = " + FormatNumber(p["width"]) + " is not positive",
           "a width σ > 0");
  const double c = terms.Value("gradient", "c", 1.0);
  fields::MovingGaussian g{p["amplitude"], p["width"], p["center"],
                           p["velocity"], c};
  ProfileFormulas f;
  f.initial = [g](double t, const double* x, double* phi, double* phi_t) {
    std::tie(phi[0], phi_t[0]) = g(t, x[0]);
  };
  if (!terms.Are({"kinetic", "gradient"})) {
    f.no_exact =
        "a Gaussian pulse is exact for the wave equation only (the terms "
        "'kinetic' and 'gradient')";
    return f;
  }
  // The images that make the pulse exact: periodic, or even (φ_x = 0) or
  // odd (φ = 0) reflections at ends of the same kind with zero data.
  using Images = fields::MovingGaussian::Images;
  const auto& e = p.s.ends;
  const bool zero = p.s.boundary_values == std::array<double, 2>{0, 0};
  const bool even = e[0] != "dirichlet" && e[1] != "dirichlet";
  const bool odd = e[0] == "dirichlet" && e[1] == "dirichlet";
  if (p.s.boundary != "periodic" && !(zero && (even || odd))) {
    f.no_exact =
        "a Gaussian pulse has an exact solution (its images) only for zero "
        "data at ends of one kind: both dirichlet, or both natural or neumann";
    return f;
  }
  g.images = p.s.boundary == "periodic" ? Images::kPeriodic
             : even                     ? Images::kMirrored
                                        : Images::kAntiMirrored;
  g.x0 = p.s.x0;
  g.length = p.s.x1 - p.s.x0;
  f.exact = [g](double t, const double* x, double* phi, double* phi_t) {
    std::tie(phi[0], phi_t[0]) = g(t, x[0]);
  };
  return f;
}

void CheckSpeed(const ProfileValues& p, const std::string& key, bool zero_ok) {
  const double v = p[key];
  if (!(std::abs(v) < 1) || (!zero_ok && v == 0))
    p.Fail(key, key + " = " + FormatNumber(v) + " is not a soliton's speed",
           zero_ok ? "|v| < 1 (the speed of light is 1)"
                   : "0 < |v| < 1 (the speed of light is 1)");
}

// The sine-Gordon profiles; exact when the density is sine-Gordon with c = 1.
ProfileFormulas SineGordonProfile(const ProfileValues& p, const TermSet& terms,
                                  Formula formula) {
  ProfileFormulas f{formula, {}, ""};
  if (terms.Are({"kinetic", "gradient", "sine_gordon"}) &&
      terms.Value("gradient", "c", 1.0) == 1.0)
    f.exact = formula;
  else
    f.no_exact = "the profile " + Quote(p.s.initial.profile) +
                 " is exact for the terms kinetic, gradient (c = 1) and "
                 "sine_gordon only";
  return f;
}

ProfileFormulas Kink(const ProfileValues& p, const TermSet& terms) {
  const bool sg = terms.Has("sine_gordon"), phi4 = terms.Has("phi4");
  if (sg == phi4)
    p.Fail("profile",
           std::string("profile 'kink' needs the kink of one potential, and "
                       "the terms list ") +
               (sg ? "both 'sine_gordon' and 'phi4'" : "neither"),
           "a 'sine_gordon' or a 'phi4' term");
  CheckSpeed(p, "velocity", true);
  if (sg)
    return SineGordonProfile(
        p, terms,
        FromExact(fields::SineGordonKink{p["velocity"], 0.0}, 0.0,
                  p["position"]));
  const fields::Phi4 density{terms.Value("phi4", "lambda", 2.0),
                             terms.Value("phi4", "v", 1.0)};
  const Formula formula = FromExact(
      fields::Phi4Kink{density, p["velocity"], 0.0}, 0.0, p["position"]);
  ProfileFormulas f{formula, {}, ""};
  if (terms.Are({"kinetic", "gradient", "phi4"}) &&
      terms.Value("gradient", "c", 1.0) == 1.0)
    f.exact = formula;
  else
    f.no_exact =
        "the φ⁴ kink is exact for the terms kinetic, gradient (c = 1) and "
        "phi4 only";
  return f;
}

ProfileFormulas PlaneWave(const ProfileValues& p, const TermSet& terms) {
  const FieldScene& s = p.s;
  const auto [omega, exact] = PlaneWaveOmega(p, terms, p["k"] * p["k"]);
  const fields::PlaneWave plane{p["amplitude"], p["k"], omega, s.components};
  const Formula wave = [plane](double t, const double* x, double* phi,
                               double* phi_t) { plane(t, x[0], phi, phi_t); };
  ProfileFormulas f{wave, {}, ""};
  if (exact)
    f.exact = wave;
  else
    f.no_exact = s.components == 1
                     ? "a plane wave of one component is exact for the terms "
                       "kinetic, gradient and mass only"
                     : "a plane wave of two components is exact for the "
                       "terms kinetic, gradient, mass, quartic and phi4 only";
  return f;
}

}  // namespace

PlaneWaveFrequency PlaneWaveOmega(const ProfileValues& p, const TermSet& terms,
                                  double k2) {
  const double c = terms.Value("gradient", "c", 0.0);
  const double mass = terms.Value("mass", "m", 0.0), a = p["amplitude"];
  double omega2 = c * c * k2 + mass * mass;
  bool exact = terms.Within({"kinetic", "gradient", "mass"});
  if (p.s.components == 2) {
    const double lq = terms.Value("quartic", "lambda", 0.0);
    const double l4 = terms.Value("phi4", "lambda", 0.0);
    const double v = terms.Value("phi4", "v", 0.0);
    omega2 += lq * a * a + l4 * (a * a - v * v);
    exact = terms.Within({"kinetic", "gradient", "mass", "quartic", "phi4"});
  }
  if (!(omega2 >= 0) || !std::isfinite(omega2))
    p.Fail("amplitude",
           "the plane wave's ω² = " + FormatNumber(omega2) +
               " is not a finite number >= 0 for these terms",
           "an amplitude and k with ω² = c²|k|² + m² + λ_q A² + λ_4(A² − v²) "
           ">= 0");
  return {std::sqrt(omega2), exact};
}

ProfileFormulas MakeProfile(const TomlReader& r, const toml::table& initial,
                            const FieldScene& s) {
  const ProfileValues p{r, initial, s};
  const TermSet terms{s};
  const std::string& name = s.initial.profile;
  if (name == "plane_wave") return PlaneWave(p, terms);
  if (s.components != 1)
    p.Fail("profile",
           "profile " + Quote(name) + " is for one component, not " +
               std::to_string(s.components),
           "profile = \"plane_wave\" or \"csv\" for a complex field");
  if (name == "gaussian") return Gaussian(p, terms);
  if (name == "kink") return Kink(p, terms);
  if (name == "kink_antikink") {
    CheckSpeed(p, "velocity", false);
    return SineGordonProfile(
        p, terms,
        FromExact(fields::SineGordonKinkAntikink{p["velocity"]},
                  p["collision_time"], p["position"]));
  }
  // breather
  if (!(p["omega"] > 0 && p["omega"] < 1))
    p.Fail("omega", "omega = " + FormatNumber(p["omega"]) + " has no breather",
           "0 < omega < 1");
  return SineGordonProfile(
      p, terms,
      FromExact(fields::SineGordonBreather{p["omega"]}, 0.0, p["position"]));
}

void ReadProfileCsv(const TomlReader& r, const toml::node& file,
                    const std::filesystem::path& base, FieldScene& s) {
  const int m = s.components, columns = 2 * m;
  const std::string layout = m == 1 ? "φ, φ_t" : "φ_0, φ_1, φ_t,0, φ_t,1";
  const std::string expected = "expected " + std::to_string(s.space_points) +
                               " rows " + layout +
                               ", one per spatial point ([field] points = " +
                               std::to_string(s.space_points) + ")";
  const std::string given = r.String(file, "file", "a path to a CSV file");
  std::filesystem::path path(given);
  if (path.is_relative()) path = base / path;
  s.initial.file = path.string();
  std::error_code ec;
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path, ec))
    r.Fail(file,
           "cannot read the profile file " + Quote(path.string()) + " (" +
               (std::filesystem::exists(path, ec) ? "not a readable file"
                                                  : "no such file") +
               ")",
           "expected a CSV file, its path relative to the scene file");
  const std::string where = Quote(path.string());
  std::vector<double> rows;
  std::string line;
  long long rows_read = 0;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    // A first line of names is a header.
    if (rows_read == 0 && rows.empty() &&
        std::isalpha(static_cast<unsigned char>(line[first])) &&
        line.compare(first, 3, "nan") != 0 &&
        line.compare(first, 3, "inf") != 0)
      continue;
    std::stringstream cells(line);
    std::string cell;
    int column = 0;
    while (std::getline(cells, cell, ',')) {
      ++column;
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      const bool blank = cell.find_first_not_of(" \t") == std::string::npos;
      if (blank || end == cell.c_str() ||
          std::string(end).find_first_not_of(" \t") != std::string::npos)
        r.Fail(file,
               where + " line " + std::to_string(number) + ": " + Quote(cell) +
                   " in column " + std::to_string(column) + " is not a number",
               "expected " + std::to_string(columns) + " numbers " + layout +
                   " per row");
      if (!std::isfinite(v))
        r.Fail(file,
               where + " line " + std::to_string(number) +
                   ": non-finite value " + Quote(cell) + " in column " +
                   std::to_string(column),
               "expected finite numbers " + layout);
      if (column <= columns) rows.push_back(v);
    }
    if (column != columns)
      r.Fail(file,
             where + " line " + std::to_string(number) + " has " +
                 std::to_string(column) + " columns",
             "expected " + std::to_string(columns) + " columns " + layout);
    if (++rows_read > s.space_points) break;
  }
  if (rows_read != s.space_points)
    r.Fail(file,
           "the profile file " + where + " has " +
               (rows_read > s.space_points ? "more than " : "") +
               std::to_string(std::min(rows_read, s.space_points)) +
               " rows of samples",
           expected);
  s.phi0.resize(std::size_t(s.space_points) * m);
  s.phi_t0.resize(s.phi0.size());
  for (long long j = 0; j < s.space_points; ++j)
    for (int a = 0; a < m; ++a) {
      s.phi0[j * m + a] = rows[j * columns + a];
      s.phi_t0[j * m + a] = rows[j * columns + m + a];
    }
}

}  // namespace vivp::scene::detail
