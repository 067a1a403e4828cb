// The files of a field run written as HDF5 (scene/field_hdf5.h), and the
// pictures of a field on 2 or 3 axes: heat maps of the slices nearest the
// scene's heat_maps times and the animated GIF of the written slices
// (report/field_plots_2d.h). A field on 3 axes is drawn in its middle
// z-plane.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <span>
#include <sstream>

#include "apps/run_field.h"
#include "report/field_plots_2d.h"
#include "scene/charged_scene.h"
#include "scene/field_hdf5.h"

namespace vivp::apps {

namespace {

namespace fs = std::filesystem;

// |E| of a gauge field's slice k at every point: E_b = −D_bA₀ − ∂_tA_b
// (the potentials depend on the gauge, E does not).
std::vector<double> ElectricMagnitude(const sbp::SpaceGrid<double>& grid,
                                      const scene::FieldRun& run,
                                      std::size_t k) {
  const int d = grid.dim(), m = d + 1;
  const std::size_t n = grid.points(), per = n * m;
  const std::span<const double> phi(run.solution.phi.data() + k * per, per);
  std::vector<double> gx(per * d), e(n);
  sbp::SpaceGrid<double>::GradientWork<double> w;
  grid.Gradient<double>(m, phi, gx, w);
  for (std::size_t j = 0; j < n; ++j) {
    double e2 = 0;
    for (int b = 0; b < d; ++b) {
      const double eb =
          -gx[(j * d + b) * m] - run.solution.phi_t[k * per + j * m + 1 + b];
      e2 += eb * eb;
    }
    e[j] = std::sqrt(e2);
  }
  return e;
}

// Every component of slice k (|E| of a gauge field) in the plane
// z = middle (the whole slice on 2 axes), as a 2-D slice to draw.
report::Slice2d PlaneOf(const scene::FieldScene& s,
                        const sbp::SpaceGrid<double>& grid,
                        const scene::FieldRun& run, std::size_t k) {
  const int nx = grid.points(0), ny = grid.points(1);
  report::Slice2d out;
  out.t = run.solution.t[k];
  for (int i = 0; i < nx; ++i) out.x.push_back(grid.axis(0).x(i));
  for (int i = 0; i < ny; ++i) out.y.push_back(grid.axis(1).x(i));
  const std::size_t plane =
      grid.dim() == 3 ? std::size_t(grid.points(2) / 2) * nx * ny : 0;
  if (s.Gauge()) {
    const auto e = ElectricMagnitude(grid, run, k);
    out.values.assign(e.begin() + std::ptrdiff_t(plane),
                      e.begin() + std::ptrdiff_t(plane + std::size_t(nx) * ny));
    return out;
  }
  const int m = s.components;
  out.components = m;
  const std::size_t per = std::size_t(grid.points()) * m;
  const double* first = run.solution.phi.data() + k * per + plane * m;
  out.values.assign(first, first + std::size_t(nx) * ny * m);
  return out;
}

// |E| of a charged field's slice on two axes (values |φ|, E_x, E_y, ρ).
report::Slice2d ElectricOfCharged(const report::Slice2d& s) {
  report::Slice2d e{.x = s.x, .y = s.y, .values = {}, .t = s.t};
  const std::size_t n = s.x.size() * s.y.size();
  for (std::size_t p = 0; p < n; ++p)
    e.values.push_back(std::hypot(s.values[p * s.components + 1],
                                  s.values[p * s.components + 2]));
  return e;
}

// vortices.csv (t, x, y, winding of every vortex of every kept slice) and
// tracks.png, of a charged field on two axes.
std::vector<std::string> WriteVortexTracks(const fs::path& dir,
                                           const scene::FieldScene& s,
                                           const scene::FieldRun& run,
                                           std::vector<std::string>& warnings) {
  std::vector<std::string> files;
  {
    std::ofstream f(dir / "vortices.csv");
    f << "t,x,y,winding\n" << std::setprecision(17);
    for (const auto& v : run.vortices)
      f << v.t << "," << v.x << "," << v.y << "," << v.winding << "\n";
    if (!f) throw std::runtime_error("cannot write vortices.csv");
    files.push_back("vortices.csv");
  }
  std::vector<report::TrackPoint> points;
  for (const auto& v : run.vortices)
    points.push_back({v.t, v.x, v.y, v.winding});
  try {
    const auto grid = s.Grid();
    const double hx = grid.axis(0).dx(), hy = grid.axis(1).dx();
    report::VortexTracks(
        dir, "tracks", points, s.x0, s.x0 + hx * s.space_points, s.Axis(1).x0,
        s.Axis(1).x0 + hy * s.Axis(1).space_points,
        (s.title.empty() ? s.source : s.title) + ": vortex tracks");
    files.push_back("tracks.png");
  } catch (const std::exception& e) {
    warnings.push_back(std::string("no tracks.png: ") + e.what());
  }
  return files;
}

}  // namespace

std::size_t Nearest(const std::vector<double>& t, double time) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < t.size(); ++k)
    if (std::abs(t[k] - time) < std::abs(t[best] - time)) best = k;
  return best;
}

nlohmann::json WriteFieldHdf5(const fs::path& dir, const scene::FieldScene& s,
                              const scene::FieldRun& run,
                              const std::vector<std::size_t>& slices) {
  const auto grid = s.Grid();
  const int m = s.components;
  const std::size_t per = std::size_t(grid.points()) * m;
  std::vector<double> t, phi, phi_t;
  for (std::size_t k : slices) {
    t.push_back(run.solution.t[k]);
    const auto at = std::ptrdiff_t(k * per);
    phi.insert(phi.end(), run.solution.phi.begin() + at,
               run.solution.phi.begin() + at + std::ptrdiff_t(per));
    if (!s.Charged())
      phi_t.insert(phi_t.end(), run.solution.phi_t.begin() + at,
                   run.solution.phi_t.begin() + at + std::ptrdiff_t(per));
  }
  // φ_t is written but for a charged field: a slice of an HDF5 file is a
  // restartable state, and a charged field's values (|φ|, E, ρ) are not.
  scene::WriteFieldSlices((dir / "field.h5").string(), grid, m, t, phi, phi_t);
  std::vector<long long> shape = {(long long)slices.size()};
  for (int a = grid.dim() - 1; a >= 0; --a) shape.push_back(grid.points(a));
  shape.push_back(m);
  nlohmann::json datasets = {"t", "phi", "phi_t"};
  if (s.Charged()) datasets = {"t", "phi"};
  return {{"file", "field.h5"},
          {"format", "hdf5"},
          {"slices", slices.size()},
          {"points", grid.points()},
          {"datasets", datasets},
          {"values", s.Charged() ? scene::ChargedValueNames(s.Dim())
                                 : std::vector<std::string>{}},
          {"shape", shape},
          {"order",
           "datasets /phi and /phi_t of shape slices × N_{d−1} × … × N_0 × "
           "components (axis 0 fastest); /t the times; each axis's first "
           "point, step, points and kind as attributes axisA_first, axisA_dx, "
           "axisA_points, axisA_kind"},
          {"t", t}};
}

std::vector<std::string> WriteSlicePictures(
    const fs::path& dir, const scene::FieldScene& s, const scene::FieldRun& run,
    const std::vector<std::size_t>& slices, std::vector<std::string>& warnings,
    nlohmann::json& pictures) {
  std::vector<std::string> files;
  const auto grid = s.Grid();
  const std::string title = s.title.empty() ? s.source : s.title;
  const std::string plane =
      grid.dim() == 3
          ? " (plane z = " +
                std::to_string(grid.axis(2).x(grid.points(2) / 2)) + ")"
          : "";
  const std::string label = s.Gauge() ? "|E|" : s.Charged() ? "|φ|" : "φ";
  // |E| and |φ| ≥ 0: their own range.
  const bool symmetric = !s.Gauge() && !s.Charged();
  pictures = {{"heat_maps", nlohmann::json::array()}};
  for (std::size_t i = 0; i < s.output.heat_maps.size(); ++i) {
    const std::size_t k = Nearest(run.solution.t, s.output.heat_maps[i]);
    const std::string stem = "heat_map_" + std::to_string(i);
    try {
      const report::Slice2d slice = PlaneOf(s, grid, run, k);
      report::SliceMap(
          dir, stem, slice,
          {.title = title + plane, .label = label, .symmetric = symmetric});
      files.push_back(stem + ".png");
      pictures["heat_maps"].push_back(
          {{"file", stem + ".png"}, {"t", run.solution.t[k]}});
      if (s.Charged()) {  // and |E| beside |φ|
        report::SliceMap(dir, stem + "_E", ElectricOfCharged(slice),
                         {.title = title, .label = "|E|", .symmetric = false});
        files.push_back(stem + "_E.png");
      }
    } catch (const std::exception& e) {
      warnings.push_back("no " + stem + ".png: " + e.what());
    }
  }
  if (!run.vortices.empty()) {
    for (const auto& f : WriteVortexTracks(dir, s, run, warnings))
      files.push_back(f);
    pictures["tracks"] = "tracks.png";
  }
  if (!s.output.animation) return files;
  try {
    // At most kFrames frames, evenly among the written slices (the first and
    // last among them): a GIF of thousands of frames helps no one.
    constexpr std::size_t kFrames = 120;
    std::vector<report::Slice2d> frames;
    const std::size_t n = slices.size();
    for (std::size_t i = 0; i < std::min(n, kFrames); ++i) {
      const std::size_t pick =
          n <= kFrames ? i : (i * (n - 1) + (kFrames - 1) / 2) / (kFrames - 1);
      frames.push_back(PlaneOf(s, grid, run, slices[pick]));
    }
    report::SliceAnimation(
        dir, "field", frames,
        {.title = title + plane, .label = label, .symmetric = symmetric});
    files.push_back("field.gif");
    pictures["animation"] = "field.gif";
  } catch (const std::exception& e) {
    warnings.push_back(std::string("no field.gif: ") + e.what());
  }
  return files;
}

}  // namespace vivp::apps
