#include "report/plot.h"

#include <gnuplot-iostream.h>

#include <fstream>
#include <iomanip>
#include <limits>
#include <stdexcept>

namespace vivp::report {

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
  const fs::path log = dir_ / (stem_ + ".gnuplot.log");
  fs::remove(png);
  {
    // tee keeps the script next to the PNG; gnuplot runs in the figure
    // directory so the script refers to its data by relative names. Its
    // messages go to a log, and the pipeline always exits 0: a failure is
    // judged by the PNG and reported once, with gnuplot's first words, by
    // the exception below (not as "pclose returned error" and a page of
    // gnuplot output on the terminal).
    const std::string dir = dir_.string();
    Gnuplot gp("(cd '" + dir + "' && tee '" + stem_ + ".gp' | gnuplot 2> '" +
               log.filename().string() + "'); exit 0");
    gp << "set terminal pngcairo size " << width_ << "," << height_
       << " enhanced font 'sans,11'\n"
       << "set output '" << stem_ << ".png'\n"
       << script_.str() << "unset output\n";
  }
  std::error_code ec;
  if (!fs::exists(png) || fs::file_size(png) == 0) {
    std::ifstream in(log);
    std::string line, first;
    while (std::getline(in, line) && first.size() < 200)
      if (line.find_first_not_of(" \t^") != std::string::npos)
        first += (first.empty() ? "" : " / ") + line;
    fs::remove(png, ec);
    throw std::runtime_error(
        "gnuplot did not draw " + png.filename().string() +
        (first.empty() ? std::string(" (is gnuplot installed?)")
                       : " (gnuplot: " + first + ")") +
        "; the script is " + stem_ + ".gp, gnuplot's messages " +
        log.filename().string());
  }
  fs::remove(log, ec);
  return png;
}

std::string Quoted(const std::string& s) {
  std::string q;
  for (char c : s) {
    if (c == '\n') {  // a line break of a title, as gnuplot writes it
      q += "\\n";
      continue;
    }
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return "\"" + q + "\"";
}

std::vector<std::size_t> Thin(std::size_t n, int most) {
  const std::size_t k =
      std::max<std::size_t>(1, (n + std::size_t(std::max(most, 2)) - 2) /
                                   std::size_t(std::max(most - 1, 1)));
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < n; i += k) idx.push_back(i);
  if (idx.back() != n - 1) idx.push_back(n - 1);
  return idx;
}

}  // namespace vivp::report
