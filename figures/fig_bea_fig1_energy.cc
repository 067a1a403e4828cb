// McLachlan & Offen 2023, Fig. 1 (docs/bea.md §5): the multistep method (4.1)
// with A = -0.2 I on U = exp(-|x|^2/2), x(0) = (1, -1), x'(0) = (0.1, -0.2),
// h = 0.15, 10^4 steps: the trajectory, and the deviations of H0,
// H0 + h^2 H2 and H0 + h^2 H2 + h^4 H4 along it (start values from the
// modified equation to h^4, x' by 6th-order central differences).
// Usage: fig_bea_fig1_energy [DIR]
#include <iostream>

#include "report/plot.h"
#include "studies/bea_experiment.h"

using namespace vivp::bea;

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const vivp::studies::GaussianWellExperiment experiment;
  const auto& r = experiment.derivation;
  const auto& q = experiment.quantities;
  const auto& potential = experiment.potential;
  const ConservationSetup s = experiment.Setup(1500);
  const double h = 0.15;
  const auto dev = Deviations(r, q, potential, s, h);

  std::vector<std::vector<double>> path, energy;
  for (int n = 0; n < dev.run.x.rows(); ++n)
    path.push_back({dev.run.x(n, 0), dev.run.x(n, 1)});
  for (int n = 0; n < dev.t.size(); ++n)
    energy.push_back({dev.t(n), dev.deviation(n, 0), dev.deviation(n, 1),
                      dev.deviation(n, 2)});
  vivp::report::Figure fig(dir, "fig_bea_fig1_energy", 1200, 500);
  const auto p = fig.Data("path", path, "x1 x2");
  const auto e = fig.Data("energy", energy, "t dH0 dH2 dH4");
  fig.script()
      << "set multiplot layout 1,2\n"
      << "set size ratio -1\nset xlabel 'x_1'\nset ylabel 'x_2'\n"
      << "set title 'LMM (4.1), A = -0.2 I, h = 0.15'\n"
      << "plot '" << p << "' using 1:2 with dots notitle\n"
      << "set size noratio\nset xlabel 't'\n"
      << "set ylabel '|H(t) - H(0)|'\nset logscale y\n"
      << "set format y '10^{%L}'\nset key below\n"
      << "set title 'modified energies'\n"
      << "plot '" << e << "' using 1:(abs($2)) with lines title 'H_0', '" << e
      << "' using 1:(abs($3)) with lines title 'H_0 + h^2 H_2', '" << e
      << "' using 1:(abs($4)) with lines lw 2 title 'H_0 + h^2 H_2 + h^4 H_4'\n"
      << "unset multiplot\n";
  std::cout << fig.Render().string() << "\n";
}
