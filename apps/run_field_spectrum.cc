// The power spectra of a field run on periodic axes: P(k) of φ at the slices
// nearest the scene's spectra times (solvers/spacetime/power_spectrum.h),
// spectrum.csv and spectrum.png. Parseval's identity Σ_k P(k) = mean of φ²
// is checked for each: a spectrum that misses it is a warning, not a file.
#include <cmath>
#include <fstream>
#include <iomanip>

#include "apps/run_field.h"
#include "report/field_plots.h"
#include "solvers/spacetime/power_spectrum.h"

namespace vivp::apps {

std::vector<std::string> WriteSpectra(const std::filesystem::path& dir,
                                      const scene::FieldScene& s,
                                      const scene::FieldRun& run,
                                      std::vector<std::string>& warnings,
                                      nlohmann::json& spectra) {
  spectra = nlohmann::json::array();
  if (s.output.spectra.empty()) return {};
  const auto grid = s.Grid();
  const int m = s.components;
  const auto& sol = run.solution;
  const std::size_t per = std::size_t(grid.points()) * m;
  std::ofstream csv(dir / "spectrum.csv");
  csv << "t,k,power,modes\n" << std::setprecision(17);
  std::vector<double> k;
  std::vector<std::pair<std::string, std::vector<double>>> curves;
  for (double want : s.output.spectra) {
    const std::size_t best = Nearest(sol.t, want);
    const std::span<const double> slice(sol.phi.data() + best * per, per);
    const auto bins = spacetime::PowerSpectrum(grid, slice, m, 0);
    double total = 0, mean_square = 0;
    for (const auto& b : bins) total += b.power;
    for (int j = 0; j < grid.points(); ++j)
      mean_square += slice[std::size_t(j) * m] * slice[std::size_t(j) * m];
    mean_square /= grid.points();
    // Parseval: the transform's own a-posteriori check.
    const double parseval =
        std::abs(total - mean_square) / std::max(mean_square, 1e-300);
    if (parseval > 1e-10) {
      warnings.push_back("the spectrum at t = " + std::to_string(sol.t[best]) +
                         " misses Parseval's identity by " +
                         std::to_string(parseval) + " (relative); not written");
      continue;
    }
    std::vector<double> power;
    k.clear();
    for (const auto& b : bins) {
      csv << sol.t[best] << "," << b.k << "," << b.power << "," << b.modes
          << "\n";
      k.push_back(b.k);
      power.push_back(b.power);
    }
    std::ostringstream name;
    name << "t = " << std::setprecision(4) << sol.t[best];
    curves.emplace_back(name.str(), power);
    spectra.push_back({{"t", sol.t[best]},
                       {"mean_square", mean_square},
                       {"parseval_error", parseval},
                       {"bins", bins.size()}});
  }
  if (!csv) throw std::runtime_error("cannot write spectrum.csv");
  std::vector<std::string> files = {"spectrum.csv"};
  if (curves.empty()) return files;
  try {
    report::Curves(dir, "spectrum", k, curves,
                   {.title = (s.title.empty() ? s.source : s.title) +
                             "\npower spectrum of φ",
                    .xlabel = "|k|",
                    .ylabel = "P(k)",
                    .log_y = true,
                    .key = "top right"});
    files.push_back("spectrum.png");
  } catch (const std::exception& e) {
    warnings.push_back(std::string("no spectrum.png: ") + e.what());
  }
  return files;
}

}  // namespace vivp::apps
