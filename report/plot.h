// A figure as three kinds of file side by side: data (.dat), the gnuplot
// script that draws it (.gp), and the PNG. Anyone can edit the script and
// re-run `gnuplot STEM.gp` in the directory.
//
//   vivp::report::Figure fig(dir, "fig04_spectrum");
//   auto d = fig.Data("D", {{re, im}, ...}, "re im");
//   fig.script() << "plot '" << d << "' using 1:2 with points\n";
//   fig.Render();  // writes fig04_spectrum.gp, runs gnuplot, checks the PNG
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace vivp::report {

class Figure {
 public:
  Figure(std::filesystem::path dir, std::string stem, int width = 900,
         int height = 600);

  // Writes rows (one line each, full double precision) to STEM_NAME.dat with
  // a '# columns' header; returns the file name relative to the directory.
  std::string Data(const std::string& name,
                   const std::vector<std::vector<double>>& rows,
                   const std::string& columns);

  std::ostringstream& script() { return script_; }

  // Writes STEM.gp (terminal, output and the script body), pipes it through
  // gnuplot in the figure directory and checks that STEM.png was made.
  // Returns the PNG path; throws std::runtime_error on failure.
  std::filesystem::path Render();

  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  std::string stem_;
  int width_, height_;
  std::ostringstream script_;
};

// gnuplot palettes of the heat maps: blue–white–red around zero for a
// signed field, and viridis (spelled out: gnuplot 5.4 has no `set palette
// viridis`).
inline constexpr const char* kDivergingPalette =
    "set palette defined (0 '#2166ac', 0.5 '#f7f7f7', 1 '#b2182b')\n";
inline constexpr const char* kViridisPalette =
    "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', "
    "0.75 '#5ec962', 1 '#fde725')\n";

// Indices 0, k, 2k, … of n and always the last one, at most `most` of them:
// the rows of a plot's data file thinned.
std::vector<std::size_t> Thin(std::size_t n, int most);

// s as a gnuplot string: in double quotes, with quotes and backslashes
// escaped and a line break as gnuplot writes it.
std::string Quoted(const std::string& s);

}  // namespace vivp::report
