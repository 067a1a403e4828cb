#include "figures/plot.h"

#include <gnuplot-iostream.h>

#include <fstream>
#include <iomanip>
#include <limits>
#include <stdexcept>

namespace vivp::plot {

namespace fs = std::filesystem;

Figure::Figure(fs::path dir, std::string stem, int width, int height)
    : dir_(std::move(dir)),
      stem_(std::move(stem)),
      width_(width),
      height_(height) {
  fs::create_directories(dir_);
}

std::string Figure::Data(const std::string& name,
                         const std::vector<std::vector<double>>& rows,
                         const std::string& columns) {
  const std::string file = stem_ + "_" + name + ".dat";
  std::ofstream out(dir_ / file);
  out << "# " << columns << "\n"
      << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (const auto& row : rows) {
    for (std::size_t j = 0; j < row.size(); ++j)
      out << (j ? " " : "") << row[j];
    out << "\n";
  }
  if (!out) throw std::runtime_error("cannot write " + (dir_ / file).string());
  return file;
}

fs::path Figure::Render() {
  const fs::path png = dir_ / (stem_ + ".png");
  fs::remove(png);
  {
    // tee keeps the script next to the PNG; gnuplot runs in the figure
    // directory so the script refers to its data by relative names.
    const std::string dir = dir_.string();
    Gnuplot gp("cd '" + dir + "' && tee '" + stem_ + ".gp' | gnuplot");
    gp << "set terminal pngcairo size " << width_ << "," << height_
       << " enhanced font 'sans,11'\n"
       << "set output '" << stem_ << ".png'\n"
       << script_.str() << "unset output\n";
  }
  if (!fs::exists(png) || fs::file_size(png) == 0)
    throw std::runtime_error("gnuplot did not produce " + png.string() +
                             "; see its messages above and " + stem_ + ".gp");
  return png;
}

}  // namespace vivp::plot
