// field.csv or field.bin of a field run on one axis, and diagnostics.csv
// (docs/field_scenes.md §5).
#include <bit>
#include <fstream>
#include <iomanip>

#include "apps/run_field.h"
#include "scene/charged_scene.h"

namespace vivp::apps {

namespace fs = std::filesystem;

namespace {

// The names of the values of one spatial point in the field files.
std::vector<std::string> PointColumns(const scene::FieldScene& s) {
  if (s.Charged()) return scene::ChargedValueNames(s.Dim());
  std::vector<std::string> c;
  for (const char* q : {"phi", "phi_t"}) {
    if (std::string(q) == "phi_t" && !s.output.phi_t) break;
    for (int a = 0; a < s.components; ++a)
      c.push_back(s.components == 1 ? q : q + std::to_string(a));
  }
  return c;
}

}  // namespace

// field.csv (t, x, φ[, φ_t] per row) or field.bin (float64, slice-major);
// returns the file's layout for summary.json.
nlohmann::json WriteField(const fs::path& dir, const scene::FieldScene& s,
                          const scene::FieldRun& run,
                          const std::vector<std::size_t>& slices) {
  const auto& sol = run.solution;
  const int m = s.components;
  const std::size_t n = run.x.size() * m;
  const std::vector<std::string> columns = PointColumns(s);
  std::vector<double> times;
  for (std::size_t k : slices) times.push_back(sol.t[k]);
  const bool binary = s.output.format == "binary";
  const std::string name = binary ? "field.bin" : "field.csv";
  std::ofstream f(dir / name, binary ? std::ios::binary : std::ios::out);
  if (!binary) {
    f << "t,x";
    for (const auto& c : columns) f << "," << c;
    f << "\n" << std::setprecision(17);
  }
  std::vector<double> row;
  for (std::size_t k : slices)
    for (std::size_t j = 0; j < run.x.size(); ++j) {
      row.assign(sol.phi.begin() + k * n + j * m,
                 sol.phi.begin() + k * n + (j + 1) * m);
      if (s.output.phi_t)
        row.insert(row.end(), sol.phi_t.begin() + k * n + j * m,
                   sol.phi_t.begin() + k * n + (j + 1) * m);
      if (binary) {
        f.write(reinterpret_cast<const char*>(row.data()),
                std::streamsize(row.size() * sizeof(double)));
        continue;
      }
      f << sol.t[k] << "," << run.x[j];
      for (double v : row) f << "," << v;
      f << "\n";
    }
  if (!f) throw std::runtime_error("cannot write " + name);
  nlohmann::json layout = {
      {"file", name},
      {"format", s.output.format},
      {"slices", slices.size()},
      {"points", run.x.size()},
      {"values", columns},
      {"x",
       {{"first", s.x0}, {"step", s.Space().dx()}, {"count", run.x.size()}}},
      {"t", times}};
  if (binary) {
    layout["dtype"] = "float64";
    layout["byte_order"] =
        std::endian::native == std::endian::little ? "little" : "big";
    layout["shape"] = {slices.size(), run.x.size(), columns.size()};
    layout["order"] =
        "slice-major: value (slice·points + j)·values + column, no header";
  } else {
    layout["order"] = "one row per slice and point, slices in time order";
  }
  return layout;
}

void WriteDiagnostics(const fs::path& dir, const scene::FieldRun& run,
                      const std::vector<std::size_t>& slices) {
  std::ofstream f(dir / "diagnostics.csv");
  f << "t";
  for (const auto& c : run.columns) f << "," << c;
  f << "\n" << std::setprecision(17);
  for (std::size_t k : slices) {
    f << run.solution.t[k];
    for (const auto& v : run.values) f << "," << v[k];
    f << "\n";
  }
  if (!f) throw std::runtime_error("cannot write diagnostics.csv");
}

}  // namespace vivp::apps
