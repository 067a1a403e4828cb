// Two vortices of the Abelian Higgs model at critical coupling (e = v = λ
// = 1) colliding head-on at speed 0.4 on the periodic square [−8, 8)² of
// 32² points, marched with the space-time action (SBP21 in windows of 8,
// Δt = 0.1, to t = 14; studies/vortex_scattering.h, docs/gauge.md §9): the
// zeros of φ, found gauge invariantly at every node, and their outgoing
// directions. Ruback (1988) and Moriarty, Myers & Rebbi (1988): a head-on
// collision scatters them at 90°.
//
// - fig_vortex_scattering: the tracks, coloured by t (the two antivortices
//   that make the torus neutral sit at (8, ±6)).
//
// Usage: fig_vortex_scattering [OUTPUT_DIR [N [SPEED [DT]]]]  (a few minutes)
//   N points per axis (Δt = 3.2/N unless DT is given: Δt·ω_max ≈ 0.6, below
//   SBP21's limit 0.7)
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "report/field_plots_2d.h"
#include "studies/vortex_scattering.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : ".";
  vivp::studies::ScatteringSetup s;
  if (argc > 2) s.n = std::atoi(argv[2]);
  if (argc > 3) s.speed = std::atof(argv[3]);
  s.dt = argc > 4 ? std::atof(argv[4]) : 3.2 / s.n;
  const auto r = vivp::studies::ScatterVortices(s);
  std::printf(
      "%d² points on [−%g, %g)², speed %g, %s windows of %d, Δt = %g: %s\n"
      "  static start relaxed to %.1e; %d windows, %lld Newton iterations, "
      "%.0f s\n"
      "  closest %.3f at t = %.2f; outgoing directions",
      s.n, s.length / 2, s.length / 2, s.speed, s.op.c_str(), s.window, s.dt,
      r.ok ? "ok" : r.reason.c_str(), r.relax_residual, r.windows, r.newton,
      r.seconds, r.closest, r.collision_time);
  for (double a : r.outgoing) std::printf(" %.4f°", a);
  std::printf(" from the incoming axis (mean %.4f°)\n", r.angle);
  std::printf(
      "  Gauss's law of the action ≤ %.1e; energy of the handed "
      "states within %.1e\n",
      r.gauss, r.energy_drift);
  if (!r.ok) return 1;
  std::vector<vivp::report::TrackPoint> points;
  for (const auto& p : r.tracks) points.push_back({p.t, p.x, p.y, p.winding});
  std::filesystem::create_directories(dir);
  const double h = s.length / 2;
  vivp::report::VortexTracks(dir, "fig_vortex_scattering", points, -h, h, -h, h,
                             "Abelian Higgs vortices colliding head-on, u = " +
                                 std::to_string(s.speed).substr(0, 4));
  return 0;
}
