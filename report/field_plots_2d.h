// Plots of a field in two space dimensions: one slice as a colour map, and
// slices in order as an animated GIF. They take plain arrays, like the 1+1-D
// plots of report/field_plots.h, so a scene run, a figure program and a
// user's own solve draw the same pictures.
//
//   vivp::report::Slice2d s{.x = xs, .y = ys, .values = phi, .t = 2.0};
//   vivp::report::SliceMap(dir, "kink_t2", s, {.title = "sine-Gordon"});
//   vivp::report::SliceAnimation(dir, "kink", slices, {.title = "kink"});
//
// The axes are drawn as evenly spaced (gnuplot's `with image`): a slice on
// an uneven grid is drawn with its points moved onto an even one.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vivp::report {

// One slice of a field on a 2-D grid: value (j1·nx + j0)·components + a at
// (x[j0], y[j1]); axis 0 fastest. Every member has a default, so that a
// designated initializer names only what it sets (and
// -Wmissing-field-initializers stays quiet).
struct Slice2d {
  std::vector<double> x = {}, y = {};  // the axes' coordinates, increasing
  std::vector<double> values = {};     // x.size()·y.size()·components values
  int components = 1;
  double t = 0;  // the slice's time, for the title
};

struct SliceMapStyle {
  std::string title = {};   // a line above the picture; ", t = …" is appended
  std::string label = "φ";  // the colour bar
  int component = 0;
  // The data file is thinned to at most this many points per axis (every
  // k-th, the last one kept), so a 512² slice plots from a small file.
  int max_points = 400;
  bool symmetric = true;  // colour range ±max|φ| (zero in the middle);
                          // else [min, max]
  int width = 800, height = 700;
};

// x horizontally, y upwards, colour = value; square pixels when the axes'
// extents are within a factor 4 of each other. Writes STEM.dat, STEM.gp and
// STEM.png in dir; returns the PNG. Throws std::invalid_argument on sizes
// that disagree, an axis of fewer than 2 points or not increasing, a bad
// component or a value that is not finite, and std::runtime_error if
// gnuplot fails.
std::filesystem::path SliceMap(const std::filesystem::path& dir,
                               const std::string& stem, const Slice2d& s,
                               const SliceMapStyle& style = {});

// An animated GIF of the slices in order, one frame per slice titled with
// its time, delay_centiseconds per frame, looping. One colour range serves
// every frame (from all the slices, symmetric or not as the style says), so
// colours compare across frames. At most max_frames frames (≥ 1): evenly
// spread over the slices, the first and last kept. The slices share their
// axes. Writes STEM.dat (a block per frame, selected with `index`), STEM.gp
// and STEM.gif in dir; returns the GIF. Same errors as SliceMap, and
// std::invalid_argument on no slices, slices with different axes, or a
// delay or frame count out of range.
//
// The data file holds every frame: 120 frames of a 512² field (257² points
// each after thinning) are 8 million rows, 280 MB, and take gnuplot 40 s. A
// smaller style.max_points keeps a long animation small and quick.
std::filesystem::path SliceAnimation(const std::filesystem::path& dir,
                                     const std::string& stem,
                                     const std::vector<Slice2d>& slices,
                                     const SliceMapStyle& style = {},
                                     int delay_centiseconds = 8,
                                     int max_frames = 120);

// Vortex tracks: where the vortices were at each time (the zeros of φ,
// core/action/vortex_tracks.h), drawn on the box [x0, x1] × [y0, y1] as
// points coloured by t, vortices (winding > 0) as filled dots and
// antivortices as open circles. Writes STEM_*.dat, STEM.gp and STEM.png;
// throws std::invalid_argument on no points or an empty box.
struct TrackPoint {
  double t = 0, x = 0, y = 0;
  int winding = 0;
};
std::filesystem::path VortexTracks(const std::filesystem::path& dir,
                                   const std::string& stem,
                                   const std::vector<TrackPoint>& points,
                                   double x0, double x1, double y0, double y1,
                                   const std::string& title = "");

}  // namespace vivp::report
