// Plots of 2-D field slices: the PNG and the animated GIF are real images
// (their magic bytes, the GIF's frames counted by walking its blocks), the
// data file is thinned, and slices that cannot be drawn are refused before
// gnuplot runs.
#define BOOST_TEST_MODULE field_plots_2d
#include "report/field_plots_2d.h"

#include <boost/test/unit_test.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using vivp::report::Slice2d;
using vivp::report::SliceAnimation;
using vivp::report::SliceMap;
using vivp::report::SliceMapStyle;

namespace {

// A directory of its own per test, removed afterwards.
struct TempDir {
  fs::path dir =
      fs::temp_directory_path() /
      ("vivp_field_plots_2d_test_" +
       std::to_string(
           std::chrono::steady_clock::now().time_since_epoch().count()));
  TempDir() { fs::create_directories(dir); }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// A Gaussian pulse moving along x on [-1, 1] × [-1, 1], two components (the
// second the negated first).
Slice2d Pulse(std::size_t nx, std::size_t ny, double t) {
  Slice2d s;
  s.components = 2;
  s.t = t;
  for (std::size_t j = 0; j < nx; ++j) s.x.push_back(-1 + 2.0 * j / (nx - 1));
  for (std::size_t j = 0; j < ny; ++j) s.y.push_back(-1 + 2.0 * j / (ny - 1));
  for (double y : s.y)
    for (double x : s.x) {
      const double v = std::exp(-10 * ((x - 0.5 * t) * (x - 0.5 * t) + y * y));
      s.values.push_back(v);
      s.values.push_back(-v);
    }
  return s;
}

std::string Bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The image descriptors of a GIF, found by walking its blocks from the
// header to the trailer (a scan for 0x2C alone would count bytes of the
// compressed pixels too); -1 if the file is not a well-formed GIF.
int GifFrames(const std::string& g) {
  const auto byte = [&](std::size_t p) { return unsigned(uint8_t(g[p])); };
  const auto table = [&](unsigned flags) {
    return flags & 0x80 ? 3u << ((flags & 7) + 1) : 0u;
  };
  if (g.size() < 13 || g.compare(0, 6, "GIF89a") != 0) return -1;
  std::size_t p = 13 + table(byte(10));
  const auto sub_blocks = [&] {  // data sub-blocks up to the empty one
    while (p < g.size() && byte(p) != 0) p += 1 + byte(p);
    ++p;
  };
  int frames = 0;
  while (p < g.size()) {
    if (byte(p) == 0x3B) return frames;  // the trailer
    if (byte(p) == 0x21) {               // an extension: label, sub-blocks
      p += 2;
      sub_blocks();
    } else if (byte(p) == 0x2C && p + 10 < g.size()) {
      ++frames;
      p += 10 + table(byte(p + 9)) + 1;  // descriptor, colours, code size
      sub_blocks();
    } else {
      return -1;
    }
  }
  return -1;
}

// Lines of a data file that hold a point: neither blank nor a comment.
std::size_t DataRows(const fs::path& file) {
  std::ifstream in(file);
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') ++rows;
  return rows;
}

}  // namespace

BOOST_AUTO_TEST_CASE(slice_map_is_a_png) {
  TempDir tmp;
  // Odd sizes put a point on the peak: the colour range is then ±1.
  const auto png = SliceMap(tmp.dir, "pulse", Pulse(41, 31, 0.5),
                            {.title = "pulse", .component = 1});
  BOOST_TEST(png == tmp.dir / "pulse.png");
  BOOST_TEST(Bytes(png).compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  BOOST_TEST(fs::exists(tmp.dir / "pulse.gp"));
  BOOST_TEST(DataRows(tmp.dir / "pulse.dat") == 41u * 31u);
  BOOST_TEST(!fs::exists(tmp.dir / "pulse.gnuplot.log"));
  const std::string gp = Bytes(tmp.dir / "pulse.gp");
  BOOST_TEST(gp.find("\"pulse, t = 0.5\"") != std::string::npos);
  BOOST_TEST(gp.find("set size ratio -1") != std::string::npos);
  BOOST_TEST(gp.find("set cbrange [-1:1]") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_large_slice_is_thinned) {
  TempDir tmp;
  const auto png = SliceMap(tmp.dir, "large", Pulse(512, 512, 0));
  BOOST_TEST(fs::exists(png));
  const std::size_t rows = DataRows(tmp.dir / "large.dat");
  BOOST_TEST_MESSAGE("512² slice: " << rows << " data rows");
  BOOST_TEST(rows <= 400u * 400u);
  BOOST_TEST(rows >= 200u * 200u);
  SliceMap(tmp.dir, "small", Pulse(512, 512, 0), {.max_points = 50});
  BOOST_TEST(DataRows(tmp.dir / "small.dat") <= 50u * 50u);
}

BOOST_AUTO_TEST_CASE(animation_is_a_gif_of_the_thinned_frames) {
  TempDir tmp;
  std::vector<Slice2d> slices;
  for (int i = 0; i < 31; ++i) slices.push_back(Pulse(24, 20, 0.1 * i));
  const auto gif = SliceAnimation(tmp.dir, "moving", slices,
                                  {.title = "moving pulse"}, 5, 12);
  BOOST_TEST(gif == tmp.dir / "moving.gif");
  const std::string bytes = Bytes(gif);
  BOOST_TEST(bytes.compare(0, 6, "GIF89a") == 0);
  BOOST_TEST(GifFrames(bytes) == 12);
  const std::string gp = Bytes(tmp.dir / "moving.gp");
  BOOST_TEST(gp.find("animate delay 5 loop 0") != std::string::npos);
  BOOST_TEST(gp.find("index 11 ") != std::string::npos);
  BOOST_TEST(gp.find("index 12 ") == std::string::npos);
  // The first and last slices are frames.
  BOOST_TEST(gp.find("\"moving pulse, t = 0\"") != std::string::npos);
  BOOST_TEST(gp.find("\"moving pulse, t = 3\"") != std::string::npos);
  BOOST_TEST(DataRows(tmp.dir / "moving.dat") == 12u * 24u * 20u);

  // Fewer slices than max_frames: one frame each; one colour range, from
  // every slice, here [min, max] of the pulse.
  slices.resize(4);
  const auto few =
      SliceAnimation(tmp.dir, "few", slices, {.symmetric = false}, 8, 120);
  BOOST_TEST(GifFrames(Bytes(few)) == 4);
  BOOST_TEST(Bytes(tmp.dir / "few.gp").find("'#fde725'") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(slices_that_cannot_be_drawn_are_refused) {
  TempDir tmp;
  Slice2d s = Pulse(10, 8, 0);
  s.values.pop_back();
  BOOST_CHECK_THROW(SliceMap(tmp.dir, "short", s), std::invalid_argument);
  s = Pulse(10, 8, 0);
  s.y.clear();
  BOOST_CHECK_THROW(SliceMap(tmp.dir, "no_y", s), std::invalid_argument);
  BOOST_CHECK_THROW(
      SliceMap(tmp.dir, "component", Pulse(10, 8, 0), {.component = 2}),
      std::invalid_argument);

  s = Pulse(10, 8, 2.5);
  s.values[2 * (3 * 10 + 4)] = std::numeric_limits<double>::quiet_NaN();
  try {
    SliceMap(tmp.dir, "nan", s);
    BOOST_ERROR("a NaN was plotted");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST_MESSAGE(e.what());
    BOOST_TEST(std::string(e.what()).find("t = 2.5") != std::string::npos);
  }
  BOOST_CHECK_THROW(SliceAnimation(tmp.dir, "nan", {Pulse(10, 8, 0), s}),
                    std::invalid_argument);
  BOOST_CHECK_THROW(
      SliceAnimation(tmp.dir, "axes", {Pulse(10, 8, 0), Pulse(10, 9, 1)}),
      std::invalid_argument);
  BOOST_CHECK_THROW(SliceAnimation(tmp.dir, "none", {}), std::invalid_argument);
  // Nothing reached gnuplot.
  BOOST_TEST(!fs::exists(tmp.dir / "nan.gp"));
  BOOST_TEST(!fs::exists(tmp.dir / "short.png"));
}

BOOST_AUTO_TEST_CASE(a_gnuplot_failure_is_a_runtime_error) {
  TempDir tmp;
  // pngcairo refuses a negative size. (The gif terminal takes its default
  // size instead, and the GIF's failure path is the PNG's.)
  try {
    SliceMap(tmp.dir, "bad", Pulse(10, 8, 0), {.width = -5, .height = -5});
    BOOST_ERROR("a PNG of size -5 × -5 was drawn");
  } catch (const std::runtime_error& e) {
    BOOST_TEST_MESSAGE(e.what());
    BOOST_TEST(std::string(e.what()).find("bad.gp") != std::string::npos);
  }
}
