// Step-size sweep for the multistep method (4.1), A = -0.2 I, U =
// exp(-|x|^2/2), T = 150: maximum deviations of the truncated modified
// energies and angular momenta against h, with fitted slopes. With
// 6th-order differences for x', H4 and I4 fall as h^6; with 4th-order
// differences (dashed) they stall near h^4 -- the measurement, not the
// method. Usage: fig_bea_step_sweep [DIR]
#include <cstdio>
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
  ConservationSetup s = experiment.Setup(150);
  const std::vector<double> steps = {0.3,   0.2,  0.15, 0.1,
                                     0.075, 0.05, 0.04, 0.03};
  const auto six = ConservationSweep(r, q, potential, s, steps);
  s.difference_order = 4;
  const auto four = ConservationSweep(r, q, potential, s, steps);

  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    std::vector<double> row = {steps[k]};
    for (double d : six.rows[k].max_deviation) row.push_back(d);
    row.push_back(four.rows[k].max_deviation[2]);  // H4
    row.push_back(four.rows[k].max_deviation[5]);  // I4
    rows.push_back(row);
  }
  vivp::report::Figure fig(dir, "fig_bea_step_sweep", 900, 650);
  const auto d = fig.Data("sweep", rows, "h H0 H2 H4 I0 I2 I4 H4_d4 I4_d4");
  auto title = [](const std::string& name, double slope) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s (slope %.2f)", name.c_str(), slope);
    return std::string(buf);
  };
  fig.script() << "set logscale xy\nset xlabel 'h'\n"
               << "set ylabel 'max |deviation| over [0, 150]'\n"
               << "set key bottom right\nset format y '10^{%L}'\n"
               << "set title 'LMM (4.1), A = -0.2 I: modified energy and "
                  "angular momentum'\n"
               << "plot ";
  const char* styles[] = {"pt 4", "pt 6", "pt 8", "pt 5", "pt 7", "pt 9"};
  for (std::size_t c = 0; c < six.names.size(); ++c)
    fig.script() << "'" << d << "' using 1:" << c + 2 << " with linespoints "
                 << styles[c] << " title '"
                 << title(six.names[c], six.slopes[c]) << "', ";
  fig.script() << "'" << d << "' using 1:8 with linespoints dt 2 title '"
               << title("H4, 4th-order differences", four.slopes[2]) << "', '"
               << d << "' using 1:9 with linespoints dt 2 title '"
               << title("I4, 4th-order differences", four.slopes[5]) << "'\n";
  std::cout << fig.Render().string() << "\n";
}
