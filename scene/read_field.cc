// A field scene's [[term]], [method], [time] and [output] tables ([field] is
// read_field_axes.cc, [initial] read_profile.cc), and the order they are
// read in.
#include <algorithm>

#include "core/sbp/builder.h"
#include "scene/field_sections.h"
#include "scene/sections.h"
#include "scene/text.h"
#include "solvers/spacetime/composed.h"

namespace vivp::scene::detail {

namespace {

// A 'maxwell' term: the field is the potentials (A₀, A₁ … A_d) on a
// periodic grid of 2 or 3 axes, alone (docs/field_scenes.md).
void ReadGaugeField(const TomlReader& r, const toml::table& root,
                    FieldScene& s) {
  const ListedEffect* maxwell = nullptr;
  for (const auto& e : s.terms)
    if (e.type->name == "maxwell") maxwell = &e;
  for (const auto& e : s.terms)
    if (e.type->name != "maxwell")
      r.Fail(e.line, e.column,
             "term " + Quote(e.type->name) +
                 " cannot join 'maxwell': a gauge field's matter is "
                 "'scalar_qed' (charged, on links), not a nodal term",
             "expected the 'maxwell' term alone, or with 'scalar_qed'");
  if (s.Dim() == 1)
    r.Fail(maxwell->line, maxwell->column,
           "term 'maxwell' on one axis has no waves and no charges: nothing "
           "would evolve",
           "expected a [field] of 2 or 3 axes");
  for (int a = 0; a < s.Dim(); ++a)
    if (s.Axis(a).boundary != "periodic")
      r.Fail(maxwell->line, maxwell->column,
             std::string("term 'maxwell' is solved on periodic grids only; "
                         "axis ") +
                 "xyz"[a] + " is " + s.Axis(a).boundary,
             "expected boundary = \"periodic\" on every axis");
  if (const toml::node* n = root["field"]["components"].node())
    r.Fail(*n,
           "a 'maxwell' field's components are its potentials (A₀, A₁ … "
           "A_d), one more than the axes",
           "expected no 'components' in [field]");
  s.components = s.Dim() + 1;
}

}  // namespace

void ReadTerms(const TomlReader& r, const toml::table& root, FieldScene& s) {
  const toml::node* n = root.get("term");
  const std::string names = Join([] {
    std::vector<std::string> v;
    for (const auto& t : FieldTermCatalogue()) v.push_back(t.name);
    return v;
  }());
  if (!n)
    r.Fail(1, 1, "the field scene lists no density term",
           "expected [[term]] tables with a type, one of " + names);
  const toml::array* list = n->as_array();
  if (!list || !list->is_array_of_tables())
    r.Fail(*n, "'term' must be an array of tables",
           "expected [[term]] sections, each with type = \"...\"");
  for (const toml::node& item : *list) {
    const toml::table& t = *item.as_table();
    const ListedEffect spec =
        ReadTypedTable(r, t, FieldTermCatalogue(), "term", s.components);
    const std::string& type = spec.type->name;
    for (const auto& e : s.terms)
      if (e.type == spec.type)
        r.Fail(t, "term " + Quote(type) + " is listed twice",
               "expected each term once (one table holds its parameters)");
    if (type == "sine_gordon" && s.components != 1)
      r.Fail(t, "term 'sine_gordon' is for a real field, not components = 2",
             "expected components = 1, or a 'mass', 'phi4' or 'quartic' term");
    s.terms.push_back(spec);
  }
  if (s.Charged())
    ReadChargedField(r, root, s);
  else if (s.Gauge())
    ReadGaugeField(r, root, s);
  if (std::none_of(s.terms.begin(), s.terms.end(),
                   [](const ListedEffect& e) { return e.type->kinetic; }))
    r.Fail(s.terms.front().line, s.terms.front().column,
           "the terms have no kinetic energy, so φ has no time evolution",
           "expected a 'kinetic' term (L += ½|φ_t|²)");
}

void ReadFieldMethod(const TomlReader& r, const toml::table& root,
                     FieldScene& s) {
  const toml::table& t = r.Table(root, "method", false);
  r.CheckKeys(t, "[method]",
              {"operator", "window_points", "tolerance", "linear_solver"});
  if (const toml::node* n = t.get("operator"))
    s.method.op = r.Choice(*n, "operator", sbp::OperatorNames());
  if (s.Charged()) return ReadChargedMethod(r, t, s);
  if (const toml::node* n = t.get("tolerance"))
    s.method.tolerance = ReadTolerance(r, *n);
  // A gauge field's window is singular along the gauge: only the Fourier
  // window solve takes it, in windows (16 points unless given).
  if (s.Gauge()) s.method.linear_solver = "fourier";
  if (const toml::node* n = t.get("linear_solver")) {
    s.method.linear_solver =
        r.Choice(*n, "linear_solver", {"modes", "sparse-lu", "fourier"});
    if (s.Gauge() && s.method.linear_solver != "fourier")
      r.Fail(*n,
             "linear_solver = " + Quote(s.method.linear_solver) +
                 " cannot solve a 'maxwell' field, whose window is singular "
                 "along the gauge",
             "expected linear_solver = \"fourier\" (or none)");
    if (s.method.linear_solver == "fourier")
      for (int a = 0; a < s.Dim(); ++a)
        if (s.Axis(a).boundary != "periodic")
          r.Fail(*n,
                 std::string("linear_solver = \"fourier\" needs periodic "
                             "axes; axis ") +
                     "xyz"[a] + " is " + s.Axis(a).boundary,
                 "expected \"modes\" or \"sparse-lu\" on this grid");
  }
  if (s.method.linear_solver == "fourier" && !t.get("window_points"))
    s.method.window_points = 16;
  if (const toml::node* n = t.get("window_points")) {
    const long long minimum = sbp::Table(s.method.op).min_points;
    const std::string expected = "0 (one global solve) or at least " +
                                 std::to_string(minimum) + " for " +
                                 s.method.op;
    s.method.window_points = r.Whole(*n, "window_points", 0, expected);
    if (s.method.window_points > 0 && s.method.window_points < minimum)
      r.Fail(*n,
             "window_points = " + std::to_string(s.method.window_points) +
                 " is below the operator's minimum",
             "expected " + expected);
    if (s.method.window_points == 0 && s.method.linear_solver == "fourier")
      r.Fail(*n,
             "window_points = 0 asks for one global solve, but the Fourier "
             "window solve is dense in a window's time points",
             "expected window_points >= " + std::to_string(minimum) +
                 " (16 to 64 is typical)");
    if (s.method.window_points == 0 && s.method.tolerance.enabled())
      r.Fail(*n,
             "window_points = 0 asks for one global solve, but a tolerance "
             "marches in windows",
             "expected window_points >= " + std::to_string(minimum) +
                 ", or no window_points (16), or no tolerance");
  }
}

namespace {

// The Fourier window solve holds a dense complex system of (W + 2)m
// unknowns per wave vector of the half spectrum (solvers/spacetime/
// fourier_solver.h): N (W + 2)² m² / 2 complex numbers.
void CheckFourierSize(const TomlReader& r, const toml::table& root,
                      const FieldScene& s) {
  const double w =
      double(s.method.window_points > 0 ? s.method.window_points : 16);
  const double bytes = 8.0 * double(s.GridPoints()) * (w + 2) * (w + 2) *
                       s.components * s.components;
  if (bytes <= spacetime::kFourierBytes) return;
  const toml::node* n = root["method"]["window_points"].node();
  if (!n) n = root["field"]["points"].node();
  r.Fail(*n,
         "the Fourier window solve would hold " +
             FormatNumber(bytes / (1 << 30)) + " GiB of factors",
         "expected at most " +
             FormatNumber(spacetime::kFourierBytes / (1 << 30)) +
             " GiB: fewer spatial points or shorter [method] window_points");
}

}  // namespace

void ReadFieldTime(const TomlReader& r, const toml::table& root,
                   FieldScene& s) {
  const toml::table& t = r.Table(root, "time", true);
  r.CheckKeys(t, "[time]", {"end", "points"});
  const toml::node& end =
      r.Require(t, "time", "end", "end = T, the final time (start is 0)");
  s.t_end = r.Number(end, "end", "a finite end time > 0");
  if (!(s.t_end > 0))
    r.Fail(end, "end = " + FormatNumber(s.t_end) + " is not after 0",
           "expected end > 0 (a field scene starts at t = 0)");
  if (s.Charged()) return ReadChargedPoints(r, t, s);
  const long long slice = s.GridPoints() * s.components;
  const long long minimum = sbp::Table(s.method.op).min_points;
  const spacetime::WindowLinearSolver linear =
      spacetime::WindowLinearSolverNamed(s.method.linear_solver);
  const long long most = spacetime::MaxSolvedAtOnce(s.method.op, linear);
  if (linear == spacetime::WindowLinearSolver::kFourier)
    CheckFourierSize(r, root, s);
  if (s.method.tolerance.enabled()) {
    // Error control chooses the time grid: no points, windows of 16 unless
    // given.
    if (const toml::node* p = t.get("points"))
      r.Fail(*p,
             "points and [method] tolerance exclude each other: the "
             "tolerance chooses the grid",
             "expected no points (error control), or no tolerance (a uniform "
             "grid)");
    s.where_time_points = r.Where(end);
    const long long w =
        s.method.window_points > 0 ? s.method.window_points : 16;
    if (w * slice > most)
      r.Fail(end,
             "windows of " + std::to_string(w) + " × " + std::to_string(slice) +
                 " values are too large for " + s.method.op,
             "expected at most " + std::to_string(most) +
                 " values solved at once: fewer spatial points or a shorter "
                 "[method] window_points");
    return;
  }
  const toml::node& points =
      r.Require(t, "time", "points", "points = Nt, time points on [0, end]");
  s.where_time_points = r.Where(points);
  const std::string at_least =
      "at least " + std::to_string(minimum) + " for " + s.method.op;
  s.time_points = r.Whole(points, "points", 0, "a whole number, " + at_least);
  if (s.time_points < minimum)
    r.Fail(
        points,
        "points = " + std::to_string(s.time_points) + " is below the minimum",
        "expected " + at_least);
  const long long kept_slices = kMaxFieldValues / slice;
  if (s.time_points > kept_slices)
    r.Fail(points,
           "points = " + std::to_string(s.time_points) + " keeps more than " +
               std::to_string(kMaxFieldValues) + " values of φ",
           "expected at most " + std::to_string(kept_slices) +
               " time points on this spatial grid");
  const long long w = s.method.window_points;
  if (w > s.time_points) {
    const toml::node* n = root["method"]["window_points"].node();
    r.Fail(n ? *n : points,
           "window_points = " + std::to_string(w) +
               " exceeds points = " + std::to_string(s.time_points),
           "expected window_points <= points (or 0 for one global solve)");
  }
  const long long at_once = (w > 0 ? w : s.time_points) * slice;
  if (at_once <= most) return;
  // The longest window of at most 16 points that fits, if any does.
  const long long fits = std::min<long long>(16, most / slice);
  const std::string fix =
      fits >= minimum
          ? "march with [method] window_points = " + std::to_string(fits)
          : "use fewer spatial points (" + std::to_string(most / minimum) +
                " values per slice at most for windows of " +
                std::to_string(minimum) + ")";
  r.Fail(w > 0 ? *root["method"]["window_points"].node() : points,
         std::string(w > 0 ? "a window" : "one global solve") + " of " +
             std::to_string(w > 0 ? w : s.time_points) + " × " +
             std::to_string(slice) + " values is too large for " + s.method.op,
         "expected at most " + std::to_string(most) +
             " values solved at once: " + fix);
}

// KEY = [t, …], times in [0, end]; `what` names one in a refusal.
std::vector<double> ReadTimes(const TomlReader& r, const toml::node& n,
                              const std::string& key, const std::string& what,
                              const FieldScene& s) {
  const std::string expected =
      key + " = [t, …], times between 0 and end = " + FormatNumber(s.t_end);
  const toml::array* a = n.as_array();
  if (!a)
    r.Fail(n, Quote(key) + " must be a list of times", "expected " + expected);
  const std::vector<double> times = r.Numbers(n, key, a->size(), expected);
  for (std::size_t k = 0; k < a->size(); ++k)
    if (!(times[k] >= 0 && times[k] <= s.t_end))
      r.Fail(*a->get(k),
             what + " time " + FormatNumber(times[k]) + " is outside the run",
             "expected " + expected);
  return times;
}

// heat_maps = [t, …] and animation = true|false, pictures of the slices of
// a field on 2 or 3 axes (a 1+1-dimensional field has its space-time heat
// map); by default heat maps at the start, middle and end, and the GIF.
void ReadFieldPictures(const TomlReader& r, const toml::table& t,
                       FieldScene& s) {
  const bool grid = s.Dim() > 1;
  for (const char* key : {"heat_maps", "animation"})
    if (const toml::node* n = t.get(key); n && !grid)
      r.Fail(*n,
             Quote(key) +
                 " draws slices of a field on 2 or 3 axes; this one "
                 "has one axis",
             "expected no " + std::string(key) +
                 " (field.png is the space-time heat map)");
  if (!grid) return;
  s.output.heat_maps = {0.0, 0.5 * s.t_end, s.t_end};
  if (const toml::node* n = t.get("heat_maps"))
    s.output.heat_maps = ReadTimes(r, *n, "heat_maps", "heat map", s);
  if (const toml::node* n = t.get("animation")) {
    if (!n->is_boolean())
      r.Fail(*n, "'animation' must be true or false, got " + TypeName(*n),
             "expected animation = true (field.gif) or false");
    s.output.animation = *n->value<bool>();
  }
}

// spectra = [t, …]: times of the power spectrum of φ (every axis
// periodic: the discrete Fourier transform needs it).
void ReadSpectra(const TomlReader& r, const toml::table& t, FieldScene& s) {
  const toml::node* n = t.get("spectra");
  if (!n) return;
  if (s.Gauge() || s.Charged())
    r.Fail(*n,
           "'spectra' are of φ, and a gauge field's potentials (and a "
           "charged φ's phase) depend on the gauge",
           "expected no spectra (heat maps show |E|, or |φ| and E)");
  for (int a = 0; a < s.Dim(); ++a)
    if (s.Axis(a).boundary != "periodic")
      r.Fail(*n,
             std::string("'spectra' needs periodic axes; axis ") + "xyz"[a] +
                 " is " + s.Axis(a).boundary,
             "expected boundary = \"periodic\" on every axis, or no spectra");
  s.output.spectra = ReadTimes(r, *n, "spectra", "spectrum", s);
}

void ReadFieldOutput(const TomlReader& r, const toml::table& root,
                     FieldScene& s) {
  const toml::table& t = r.Table(root, "output", false);
  r.CheckKeys(t, "[output]",
              {"diagnostics", "stride", "format", "phi_t", "heat_maps",
               "animation", "spectra"});
  if (const toml::node* n = t.get("stride"))
    s.output.stride = r.Whole(*n, "stride", 1, "a whole number >= 1");
  const bool grid = s.Dim() > 1;
  if (grid) s.output.format = "hdf5";
  if (const toml::node* n = t.get("format")) {
    s.output.format = r.Choice(*n, "format", {"csv", "binary", "hdf5"});
    if (grid && s.output.format != "hdf5")
      r.Fail(*n,
             "format = " + Quote(s.output.format) + " is for one axis; a " +
                 std::to_string(s.Dim()) + "-axis field is written as HDF5",
             "expected format = \"hdf5\" (or no format)");
  }
  ReadFieldPictures(r, t, s);
  ReadSpectra(r, t, s);
  if (const toml::node* n = t.get("phi_t")) {
    if (!n->is_boolean())
      r.Fail(*n, "'phi_t' must be true or false, got " + TypeName(*n),
             "expected phi_t = true (write φ_t next to φ) or false");
    s.output.phi_t = *n->value<bool>();
    if (s.output.phi_t && s.Charged())
      r.Fail(*n,
             "a charged field writes |φ|, E and ρ per point, which are gauge "
             "invariant; φ_t is not",
             "expected no phi_t");
  }
  if (const toml::node* n = t.get("diagnostics"))
    s.output.diagnostics = ReadDiagnosticList(
        r, *n, FieldDiagnosticNames(),
        [&](const toml::node& e, const std::string& d) {
          if ((d == "gauss" || d == "gauss_textbook") && !s.Gauge() &&
              !s.Charged())
            r.Fail(e,
                   "diagnostic " + Quote(d) +
                       " is Gauss's law of a gauge field (A₀'s equation)",
                   "expected a 'maxwell' term, or no " + Quote(d));
          if (d == "momentum" && (s.Gauge() || s.Charged()))
            r.Fail(e,
                   "diagnostic 'momentum' is the canonical momentum of the "
                   "potentials, which is not gauge invariant",
                   "expected energy, error, gauss or gauss_textbook");
          if (d == "charge" && s.components != 2 && !s.Charged())
            r.Fail(e,
                   "diagnostic 'charge' is the U(1) charge of two components",
                   "expected components = 2, or no 'charge'");
          if (d == "error" && !s.exact)
            r.Fail(e,
                   "diagnostic 'error' needs an exact solution: " + s.no_exact,
                   "expected no 'error' for this profile and these terms");
        });
}

FieldScene ReadFieldScene(const TomlReader& r, const toml::table& root) {
  FieldScene s;
  s.source = r.source();
  r.CheckKeys(
      root, "the top level of a field scene",
      {"title", "field", "term", "initial", "time", "method", "output"});
  if (const toml::node* t = root.get("title"))
    s.title = r.String(*t, "title", "a short text");
  ReadField(r, root, s);
  ReadTerms(r, root, s);
  ReadFieldMethod(r, root, s);
  ReadFieldTime(r, root, s);
  const std::filesystem::path base =
      std::filesystem::path(s.source).parent_path();
  ReadProfile(r, root, base, s);
  ReadFieldOutput(r, root, s);
  return s;
}

}  // namespace vivp::scene::detail
