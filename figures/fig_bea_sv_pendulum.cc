// Stormer-Verlet on the pendulum x'' = -sin x, x(0) = 1, x'(0) = 0, T = 100:
// maximum deviation of the modified Hamiltonian of Appendix A truncated at
// h^0, h^2, h^4 against h, with fitted slopes (2, ~4, 6).
// Usage: fig_bea_sv_pendulum [DIR]
#include <cstdio>
#include <iostream>

#include "report/plot.h"
#include "solvers/bea/conservation.h"

using namespace vivp::bea;

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  DeriveOptions o;
  o.order = 4;
  const auto r = Derive(MakeStormerVerlet(1), o);
  const Pendulum potential;
  const ModifiedQuantities q(r, potential);
  ConservationSetup s;
  s.x0 = Eigen::VectorXd::Constant(1, 1.0);
  s.v0 = Eigen::VectorXd::Zero(1);
  s.t_end = 100;
  const std::vector<double> steps = {0.2,  0.15,   0.1,  0.075,
                                     0.05, 0.0375, 0.025};
  const auto sweep = ConservationSweep(r, q, potential, s, steps);
  std::vector<std::vector<double>> rows;
  for (const auto& row : sweep.rows) {
    std::vector<double> v = {row.h};
    v.insert(v.end(), row.max_deviation.begin(), row.max_deviation.end());
    rows.push_back(v);
  }
  vivp::report::Figure fig(dir, "fig_bea_sv_pendulum", 800, 600);
  const auto d = fig.Data("sweep", rows, "h H0 H2 H4");
  fig.script() << "set logscale xy\nset xlabel 'h'\n"
               << "set ylabel 'max |H(t) - H(0)| over [0, 100]'\n"
               << "set key top left\nset format y '10^{%L}'\n"
               << "set title 'Stormer-Verlet, pendulum: modified Hamiltonian'\n"
               << "plot ";
  for (std::size_t c = 0; c < sweep.names.size(); ++c) {
    char t[64];
    std::snprintf(t, sizeof t, "%s (slope %.2f)", sweep.names[c].c_str(),
                  sweep.slopes[c]);
    fig.script() << (c ? ", " : "") << "'" << d << "' using 1:" << c + 2
                 << " with linespoints title '" << t << "'";
  }
  fig.script() << "\n";
  std::cout << fig.Render().string() << "\n";
}
