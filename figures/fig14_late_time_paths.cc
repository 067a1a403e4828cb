// Fig. 14 of Rothkopf & Nordström (2023): the damped oscillator of eq. (43)
// at late times, regularized SBP42 on [0, 204.8]. Left: x1 at N_t = 2048
// (Δt ≈ 0.1; x2 takes the same values) against the exact solution (gray).
// Right: the last oscillations for N_t = 512 (green), 1024 (blue) and 2048
// (red): bounded, with a phase (dispersion) error that shrinks with Δt.
// Usage: fig14_late_time_paths [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  using namespace vivp::figures;
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const vivp::studies::NamedProblem& damped =
      vivp::studies::FindProblem("damped");
  const auto exact = [&](double t) { return damped.exact(t).x[0]; };
  const double t2 = 204.8, t_late = 190.0;
  const auto s = LateTimeDamped(2048);
  Panel whole{"damped oscillator, SBP42, N_t = 2048",
              "t",
              "x(t)",
              {},
              "set key top right"};
  whole.series = {Curve("exact", exact, 0, t2, kGrayLine, 4000),
                  PathSeries("x_1", s.x1, s.t, kRedDots)};
  Panel late{"late times",
             "t",
             "x(t)",
             {},
             "set key outside bottom center horizontal\nset xrange [" +
                 std::to_string(t_late) + ":" + std::to_string(t2) + "]"};
  late.series = {Curve("exact", exact, t_late, t2, kGrayLine)};
  const char* styles[] = {kGreenCrosses, kBlueCrosses, kRedCircles};
  for (int k = 0; k < 3; ++k) {
    const long long n = 512LL << k;
    const auto sk = n == 2048 ? s : LateTimeDamped(n);
    late.series.push_back(
        PathSeries("N_t = " + std::to_string(n), sk.x1, sk.t, styles[k]));
  }
  std::cout << PanelFigure(dir, "fig14_late_time_paths", {whole, late}).string()
            << "\n";
}
