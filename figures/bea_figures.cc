#include "figures/bea_figures.h"

#include <vector>

#include "report/plot.h"
#include "studies/bea_experiment.h"

namespace vivp::figures {

std::filesystem::path GaussianWellFigure(const std::filesystem::path& dir,
                                         const ModifiedQuantity& q) {
  const studies::GaussianWellExperiment experiment;
  const bea::ConservationSetup s = experiment.Setup(1500);
  const double h = 0.15;
  const auto dev = bea::Deviations(experiment.derivation, experiment.quantities,
                                   experiment.potential, s, h);

  std::vector<std::vector<double>> path, deviation;
  for (int n = 0; n < dev.run.x.rows(); ++n)
    path.push_back({dev.run.x(n, 0), dev.run.x(n, 1)});
  const int c = q.first_column;
  for (int n = 0; n < dev.t.size(); ++n)
    deviation.push_back({dev.t(n), dev.deviation(n, c), dev.deviation(n, c + 1),
                         dev.deviation(n, c + 2)});
  report::Figure fig(dir, q.stem, 1200, 500);
  const auto p = fig.Data("path", path, "x1 x2");
  const std::string d = q.symbol + "0 d" + q.symbol + "2 d" + q.symbol + "4";
  const auto e = fig.Data(q.name, deviation, "t d" + d);
  fig.script() << "set multiplot layout 1,2\n"
               << "set size ratio -1\nset xlabel 'x_1'\nset ylabel 'x_2'\n"
               << "set title 'LMM (4.1), A = -0.2 I, h = 0.15'\n"
               << "plot '" << p << "' using 1:2 with dots notitle\n"
               << "set size noratio\nset xlabel 't'\n"
               << "set ylabel '|" << q.symbol << "(t) - " << q.symbol
               << "(0)|'\nset logscale y\n"
               << "set format y '10^{%L}'\nset key below\n"
               << "set title 'modified " << q.title << "'\n"
               << "plot '" << e << "' using 1:(abs($2)) with lines title '"
               << q.titles[0] << "', '" << e
               << "' using 1:(abs($3)) with lines title '" << q.titles[1]
               << "', '" << e << "' using 1:(abs($4)) with lines lw 2 title '"
               << q.titles[2] << "'\n"
               << "unset multiplot\n";
  return fig.Render();
}

}  // namespace vivp::figures
