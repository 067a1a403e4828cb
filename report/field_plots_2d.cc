#include "report/field_plots_2d.h"

#include <gnuplot-iostream.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "report/plot.h"

namespace vivp::report {

namespace fs = std::filesystem;

namespace {

std::string TimeText(double t) {
  std::ostringstream s;
  s << "t = " << t;
  return s.str();
}

void CheckAxis(const std::vector<double>& axis, const char* name) {
  if (axis.size() < 2)
    throw std::invalid_argument(std::string("slice plot: the ") + name +
                                " axis has " + std::to_string(axis.size()) +
                                " points, at least 2 are needed");
  for (std::size_t j = 1; j < axis.size(); ++j)
    if (!(axis[j] > axis[j - 1]))
      throw std::invalid_argument(std::string("slice plot: the ") + name +
                                  " axis does not increase at point " +
                                  std::to_string(j));
}

// Sizes, component and values of a slice. A value that is not finite is
// refused: gnuplot would leave its pixel blank, or the whole picture when
// the colour range comes out NaN, and say nothing.
void CheckSlice(const Slice2d& s, int component) {
  if (s.components < 1 || component < 0 || component >= s.components)
    throw std::invalid_argument("slice plot: component " +
                                std::to_string(component) + " of " +
                                std::to_string(s.components));
  CheckAxis(s.x, "x");
  CheckAxis(s.y, "y");
  if (s.values.size() != s.x.size() * s.y.size() * std::size_t(s.components))
    throw std::invalid_argument(
        "slice plot: " + std::to_string(s.values.size()) + " values for " +
        std::to_string(s.x.size()) + " × " + std::to_string(s.y.size()) +
        " points × " + std::to_string(s.components) + " components");
  for (std::size_t p = 0; p < s.x.size() * s.y.size(); ++p)
    if (!std::isfinite(s.values[p * s.components + component]))
      throw std::invalid_argument(
          "slice plot: the slice at " + TimeText(s.t) + " has the value " +
          std::to_string(s.values[p * s.components + component]) +
          " at point (" + std::to_string(p % s.x.size()) + ", " +
          std::to_string(p / s.x.size()) + ")");
}

// `most` indices spread evenly over 0 … n - 1, the first and last among
// them (all n when n ≤ most). Frames are thinned this way rather than every
// k-th: 121 slices then make 120 frames, not 61.
std::vector<std::size_t> Spread(std::size_t n, int most) {
  std::vector<std::size_t> idx;
  if (n <= std::size_t(most)) {
    for (std::size_t i = 0; i < n; ++i) idx.push_back(i);
  } else if (most == 1) {
    idx.push_back(0);
  } else {
    for (int i = 0; i < most; ++i)
      idx.push_back(std::size_t(
          std::llround(double(i) * double(n - 1) / double(most - 1))));
  }
  return idx;
}

// Appends v with 8 significant digits: the file feeds a palette of a few
// hundred colours, and full precision would make a long animation's file
// twice as large for nothing the picture shows.
void Append(std::string& out, double v) {
  char buf[32];
  const auto end =
      std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 8)
          .ptr;
  out.append(buf, end);
}

// The thinned rows (x, y, value) of one slice, a blank line after each row
// of constant y: gnuplot's grid format, which pm3d needs should anyone
// change the script from `with image`.
void WriteSlice(std::ofstream& out, const Slice2d& s,
                const SliceMapStyle& style) {
  const auto js = Thin(s.x.size(), style.max_points);
  std::string line;
  for (std::size_t j1 : Thin(s.y.size(), style.max_points)) {
    line.clear();
    for (std::size_t j0 : js) {
      Append(line, s.x[j0]);
      line += ' ';
      Append(line, s.y[j1]);
      line += ' ';
      Append(line,
             s.values[(j1 * s.x.size() + j0) * s.components + style.component]);
      line += '\n';
    }
    out << line << '\n';
  }
}

// The colour range, the palette (blue–white–red around zero, or viridis)
// and the axes: everything but the title and the plot command.
void Frame(std::ostream& gp, const std::vector<const Slice2d*>& slices,
           const SliceMapStyle& style) {
  double lo = INFINITY, hi = -INFINITY;
  for (const Slice2d* s : slices)
    for (std::size_t p = 0; p < s->x.size() * s->y.size(); ++p) {
      lo = std::min(lo, s->values[p * s->components + style.component]);
      hi = std::max(hi, s->values[p * s->components + style.component]);
    }
  if (style.symmetric) {
    // A field that is zero everywhere still draws, white.
    hi = std::max(std::abs(lo), std::abs(hi));
    if (hi == 0) hi = 1;
    lo = -hi;
  } else if (lo == hi) {  // gnuplot refuses an empty colour range
    const double d = lo == 0 ? 1 : std::abs(lo) / 2;
    lo -= d;
    hi += d;
  }
  const Slice2d& s = *slices.front();
  gp << std::setprecision(17) << "set encoding utf8\n"
     << "set cblabel " << Quoted(style.label) << "\n"
     << "set cbrange [" << lo << ":" << hi << "]\n"
     << (style.symmetric ? kDivergingPalette : kViridisPalette)
     << "set xlabel 'x'\nset ylabel 'y'\n"
     << "set xrange [" << s.x.front() << ":" << s.x.back() << "]\n"
     << "set yrange [" << s.y.front() << ":" << s.y.back() << "]\n";
  // Square pixels show a round pulse round; on a long thin domain they
  // would squeeze the picture into a strip, which the default shape avoids.
  const double ex = s.x.back() - s.x.front(), ey = s.y.back() - s.y.front();
  if (std::max(ex, ey) <= 4 * std::min(ex, ey)) gp << "set size ratio -1\n";
  gp << std::setprecision(6);
}

std::string Title(const SliceMapStyle& style, double t) {
  return Quoted(style.title.empty() ? TimeText(t)
                                    : style.title + ", " + TimeText(t));
}

std::ofstream OpenData(const fs::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  return out;
}

void CloseData(std::ofstream& out, const fs::path& file) {
  out.close();
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

// Figure::Render for an animated GIF, which Figure (PNG only) cannot make:
// the same pipeline, log and judgement by the file gnuplot leaves.
fs::path RenderGif(const fs::path& dir, const std::string& stem,
                   const SliceMapStyle& style, int delay,
                   const std::string& script) {
  const fs::path gif = dir / (stem + ".gif");
  const fs::path log = dir / (stem + ".gnuplot.log");
  fs::remove(gif);
  {
    Gnuplot gp("(cd '" + dir.string() + "' && tee '" + stem +
               ".gp' | gnuplot 2> '" + log.filename().string() + "'); exit 0");
    gp << "set terminal gif animate delay " << delay << " loop 0 size "
       << style.width << "," << style.height << " enhanced font 'sans,11'\n"
       << "set output '" << stem << ".gif'\n"
       << script << "unset output\n";
  }
  std::error_code ec;
  if (!fs::exists(gif) || fs::file_size(gif) == 0) {
    std::ifstream in(log);
    std::string line, first;
    while (std::getline(in, line) && first.size() < 200)
      if (line.find_first_not_of(" \t^") != std::string::npos)
        first += (first.empty() ? "" : " / ") + line;
    fs::remove(gif, ec);
    throw std::runtime_error(
        "gnuplot did not draw " + gif.filename().string() +
        (first.empty() ? std::string(" (is gnuplot installed?)")
                       : " (gnuplot: " + first + ")") +
        "; the script is " + stem + ".gp, gnuplot's messages " +
        log.filename().string());
  }
  // gnuplot reports "N frames in animation sequence" on success; only a
  // failure keeps the log.
  fs::remove(log, ec);
  return gif;
}

}  // namespace

fs::path SliceMap(const fs::path& dir, const std::string& stem,
                  const Slice2d& s, const SliceMapStyle& style) {
  CheckSlice(s, style.component);
  Figure fig(dir, stem, style.width, style.height);
  const fs::path data = dir / (stem + ".dat");
  auto out = OpenData(data);
  out << "# x y " << style.label << " at " << TimeText(s.t) << "\n";
  WriteSlice(out, s, style);
  CloseData(out, data);
  auto& gp = fig.script();
  Frame(gp, {&s}, style);
  gp << "set title " << Title(style, s.t) << "\n"
     << "plot '" << stem << ".dat' using 1:2:3 with image notitle\n";
  return fig.Render();
}

fs::path SliceAnimation(const fs::path& dir, const std::string& stem,
                        const std::vector<Slice2d>& slices,
                        const SliceMapStyle& style, int delay_centiseconds,
                        int max_frames) {
  if (slices.empty()) throw std::invalid_argument("slice animation: no slices");
  if (delay_centiseconds < 0 || max_frames < 1)
    throw std::invalid_argument(
        "slice animation: delay " + std::to_string(delay_centiseconds) +
        " cs and at most " + std::to_string(max_frames) +
        " frames (a delay ≥ 0 and at least 1 frame are needed)");
  std::vector<const Slice2d*> all;
  for (const Slice2d& s : slices) {
    CheckSlice(s, style.component);
    if (s.x != slices.front().x || s.y != slices.front().y)
      throw std::invalid_argument("slice animation: the slice at " +
                                  TimeText(s.t) +
                                  " has other axes than the first slice");
    all.push_back(&s);
  }
  fs::create_directories(dir);
  const fs::path data = dir / (stem + ".dat");
  auto out = OpenData(data);
  std::ostringstream gp;
  Frame(gp, all, style);  // the colour range of all slices, not the frames'
  int block = 0;
  for (std::size_t i : Spread(slices.size(), max_frames)) {
    // Two blank lines end a block (`index` counts blocks); WriteSlice ends
    // with one.
    out << (block ? "\n" : "") << "# x y " << style.label << " at "
        << TimeText(slices[i].t) << "\n";
    WriteSlice(out, slices[i], style);
    gp << "set title " << Title(style, slices[i].t) << "\n"
       << "plot '" << stem << ".dat' index " << block++
       << " using 1:2:3 with image notitle\n";
  }
  CloseData(out, data);
  return RenderGif(dir, stem, style, delay_centiseconds, gp.str());
}

fs::path VortexTracks(const fs::path& dir, const std::string& stem,
                      const std::vector<TrackPoint>& points, double x0,
                      double x1, double y0, double y1,
                      const std::string& title) {
  if (points.empty())
    throw std::invalid_argument("vortex tracks: no vortex was found");
  if (!(x1 > x0 && y1 > y0))
    throw std::invalid_argument("vortex tracks: the box is empty");
  std::vector<std::vector<double>> plus, minus;
  double t0 = points.front().t, t1 = t0;
  for (const auto& p : points) {
    (p.winding > 0 ? plus : minus).push_back({p.x, p.y, p.t});
    t0 = std::min(t0, p.t);
    t1 = std::max(t1, p.t);
  }
  Figure fig(dir, stem, 800, 700);
  auto& gp = fig.script();
  gp << "set encoding utf8\nset title " << Quoted(title) << "\n"
     << kViridisPalette << "set cblabel 't'\nset cbrange [" << t0 << ":"
     << (t1 > t0 ? t1 : t0 + 1) << "]\nset xlabel 'x'\nset ylabel 'y'\n"
     << "set xrange [" << x0 << ":" << x1 << "]\nset yrange [" << y0 << ":"
     << y1 << "]\nset size ratio -1\nset grid\nset key top left\nplot ";
  bool first = true;
  for (auto* set : {&plus, &minus}) {
    if (set->empty()) continue;
    const bool vortex = set == &plus;
    const auto data =
        fig.Data(vortex ? "vortices" : "antivortices", *set, "x y t");
    gp << (first ? "" : ", ") << "'" << data << "' using 1:2:3 with points pt "
       << (vortex ? 7 : 6) << " ps 0.8 palette title "
       << Quoted(vortex ? "vortex" : "antivortex");
    first = false;
  }
  gp << "\n";
  return fig.Render();
}

}  // namespace vivp::report
