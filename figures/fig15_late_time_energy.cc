// Fig. 15 of Rothkopf & Nordström (2023): energy ½μẋ² + ½κx² of the late-time
// damped oscillator (eq. 43, regularized SBP42 on [0, 204.8]) along x1 with
// ẋ = D x1, for N_t = 512 (green), 1024 (blue) and 2048 (red), against the
// exact decay (black): the shift and the oscillations shrink under refinement.
// Usage: fig15_late_time_energy [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"
#include "problems/damped_oscillator.h"

int main(int argc, char** argv) {
  using namespace vivp::figures;
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const vivp::studies::NamedProblem& damped =
      vivp::studies::FindProblem("damped");
  const vivp::problems::DampedOscillator p;
  Panel energy{"energy of the damped oscillator, SBP42",
               "t",
               "E = ½μ(dx/dt)^2 + ½κx^2",
               {},
               "set key top right"};
  energy.series = {Curve(
      "exact",
      [&](double t) {
        const auto e = damped.exact(t);
        return p.Energy(e.x[0], e.v[0]);
      },
      0, 204.8, kBlackLine, 2000)};
  const char* styles[] = {kGreenCrosses, kBlueCrosses, kRedCircles};
  for (int k = 0; k < 3; ++k) {
    const long long n = 512LL << k;
    const auto s = LateTimeDamped(n);
    Series e{"N_t = " + std::to_string(n), {}, styles[k]};
    for (int i = 0; i < s.points(); ++i)
      e.rows.push_back({s.t[i], p.Energy(s.x1(i, 0), s.velocity(i, 0))});
    energy.series.push_back(e);
  }
  std::cout << PanelFigure(dir, "fig15_late_time_energy", {energy}).string()
            << "\n";
}
