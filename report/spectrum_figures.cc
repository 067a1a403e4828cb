#include "report/spectrum_figures.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "report/plot.h"

namespace vivp::report {
namespace {

std::vector<std::vector<double>> ComplexRows(
    const std::vector<std::complex<double>>& z) {
  std::vector<std::vector<double>> rows;
  for (const auto& v : z) rows.push_back({v.real(), v.imag()});
  return rows;
}

std::vector<std::vector<double>> IndexRows(const Eigen::VectorXd& v) {
  std::vector<std::vector<double>> rows;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    rows.push_back({static_cast<double>(i), v[i]});
  return rows;
}

}  // namespace

std::filesystem::path NullVectorFigure(const linalg::Spectrum& d,
                                       const std::string& op_name, int points,
                                       const std::filesystem::path& dir) {
  report::Figure fig(dir, "fig03_null_vectors");
  const auto right = fig.Data("right", IndexRows(d.right_null_vector), "i v");
  const auto left = fig.Data("left", IndexRows(d.left_null_vector), "i v");
  fig.script() << "set title 'Null vectors of D (" << op_name
               << ", N_t = " << points << ")'\n"
               << "set xlabel 'node i'\nset ylabel 'component (unit norm)'\n"
               << "set key outside top center horizontal\nset grid\n"
               << "plot '" << right
               << "' using 1:2 with points pt 6 ps 1.5 lc rgb 'red' title "
                  "'right null vector', \\\n     '"
               << left
               << "' using 1:2 with linespoints pt 2 ps 1.5 lc rgb 'blue' "
                  "title 'left null vector'\n";
  return fig.Render();
}

std::filesystem::path SpectrumFigure(const linalg::Spectrum& d,
                                     const linalg::Spectrum& dbar,
                                     const std::string& op_name, int points,
                                     const std::filesystem::path& dir) {
  report::Figure fig(dir, "fig04_spectrum", 1200, 600);
  const auto dfile = fig.Data("D", ComplexRows(d.eigenvalues), "re im");
  const auto dbarfile =
      fig.Data("Dbar", ComplexRows(dbar.eigenvalues), "re im");
  // The inset spans the cluster of the algebraic_multiplicity smallest
  // eigenvalues of D (the split zero eigenvalue).
  double radius = 0;
  const int m = std::max(1, d.zero.algebraic_multiplicity);
  for (int i = 0; i < m && i < static_cast<int>(d.eigenvalues.size()); ++i)
    radius = std::max(radius, std::abs(d.eigenvalues[i]));
  radius = radius > 0 ? 3 * radius : 1e-6;
  auto& s = fig.script();
  s << "set multiplot\n"
    << "set origin 0,0\nset size 0.64,1\n"
    << "set title 'Eigenvalues of D and D̄ (" << op_name << ", N_t = " << points
    << ")'\nset xlabel 'Re {/Symbol n}'\nset ylabel 'Im {/Symbol n}'\n"
    << "set grid\nset key top left box opaque\nset offsets graph 0.05, graph "
       "0.05, graph 0.05, graph 0.05\n"
    << "plot '" << dfile
    << "' using 1:2 with points pt 2 ps 1.4 lc rgb 'blue' title 'D', \\\n"
    << "     '" << dbarfile
    << "' using 1:2 with points pt 6 ps 1.4 lc rgb 'red' title 'D̄ (affine)'\n"
    << "set origin 0.64,0.1\nset size 0.36,0.8\nunset offsets\n"
    << "set title 'zoom on the origin: D keeps a split zero'\n"
    << "set xlabel 'Re {/Symbol n}'\nset ylabel 'Im {/Symbol n}'\n"
    << "set format x '%.0e'\nset format y '%.0e'\nset xtics " << radius
    << "\nset ytics " << radius << "\nunset key\n"
    << "set xrange [" << -radius << ":" << radius << "]\n"
    << "set yrange [" << -radius << ":" << radius << "]\n"
    << "plot '" << dfile
    << "' using 1:2 with points pt 2 ps 1.6 lc rgb 'blue'\n"
    << "unset multiplot\n";
  return fig.Render();
}

}  // namespace vivp::report
