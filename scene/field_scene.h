// A field scene: a field in 1, 2 or 3 spatial dimensions stated as a sum of
// named density terms, its domain and spatial operator per axis, an initial
// profile, the time grid,
// the method and what to output (docs/field_scenes.md). A scene with a
// [field] table is a field scene; one with [system] is a point-mechanics
// scene (scene.h), and a file with sections of both kinds is refused.
// Errors are SceneErrors "FILE:LINE:COL: what is wrong; what is expected".
//
//   title = "Sine-Gordon breather"          # optional
//   [field]
//   components = 1                          # 1 or 2 (a complex field)
//   domain = [-20.0, 20.0]                  # [x0, x1]
//   points = 200                            # spatial points
//   boundary = "periodic"                   # periodic | natural |
//                                           # dirichlet | neumann, or
//                                           # ["dirichlet", "natural"]
//   boundary_values = [0.0, 0.0]            # φ or φ_x at the two ends
//   space_order = 8                         # periodic: 2, 4, 6, 8
//   space_operator = "sbp42"                # natural: sbp21 … sbp84
//   [[term]]                                # one table per density term
//   type = "kinetic"
//   [initial]
//   profile = "breather"                    # gaussian, kink, kink_antikink,
//   omega = 0.5                             # breather, plane_wave, csv
//   allow_jump = false                      # periodic: accept a jump
//   [time]
//   end = 6.283185307179586
//   points = 129                            # none with a tolerance
//   [method]
//   operator = "sbp42"
//   window_points = 16                      # 0: one global solve
//   tolerance = 1e-6                        # error control (or
//                                           # {absolute = …, relative = …})
//   linear_solver = "modes"                 # modes | sparse-lu | fourier
//   [output]
//   diagnostics = ["energy", "error"]       # energy, momentum, charge, error
//   stride = 1                              # every stride-th slice
//   format = "csv"                          # csv | binary
//   phi_t = true                            # write φ_t next to φ
//
// In 2+1 or 3+1 dimensions the [field] keys take one entry per axis (a
// single value applies to every axis), the slices go to an HDF5 file, and
// heat maps of chosen slices and an animated GIF are drawn:
//
//   [field]
//   domain = [[-10.0, 10.0], [-10.0, 10.0]] # [[x0, x1], [y0, y1]]
//   points = [64, 64]                       # or 64 for both
//   boundary = ["periodic", "neumann"]      # per axis; an axis's entry may
//                                           # be [left, right]
//   boundary_values = [[0, 0], [0, 0]]      # per axis, ∂φ along it
//   [initial]
//   profile = "ring"                        # gaussian, ring, oscillon,
//   radius = 6.0                            # plane_wave
//   center = [0.0, 0.0]
//   [output]
//   format = "hdf5"                         # the only format in d > 1
//   heat_maps = [0.0, 5.0]                  # times of PNG heat maps
//   animation = true                        # field.gif
//   spectra = [0.0, 5.0]                    # P(k) of φ (periodic axes)
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/sbp/space.h"
#include "core/sbp/space_grid.h"
#include "problems/fields/terms.h"
#include "scene/scene.h"
#include "solvers/spacetime/solve.h"

namespace vivp::scene {

// φ_a(t, x) and φ_t,a(t, x) of a profile's formula, a < components; x
// holds the point's d coordinates.
using FieldFormula =
    std::function<void(double t, const double* x, double* phi, double* phi_t)>;

// One spatial axis of a field scene: its interval, points, boundary and
// spatial operator.
struct FieldAxis {
  double x0 = 0, x1 = 1;
  long long space_points = 0;
  // periodic, or the ends' kinds: natural | dirichlet | neumann, one for
  // both ends or "left/right" when they differ.
  std::string boundary = "periodic";
  std::array<std::string, 2> ends = {"natural", "natural"};
  // φ (dirichlet) or the slope ∂φ along the axis (neumann) at the two
  // ends, every component.
  std::array<double, 2> boundary_values = {0, 0};
  int space_order = 8;                   // periodic differences
  std::string space_operator = "sbp42";  // natural: an SBP operator
  sbp::SpaceDerivative<double> Space() const;
};

// The scene itself is its first axis (the only one of a 1+1-dimensional
// field); cross_axes are y and z of a 2+1- or 3+1-dimensional one.
struct FieldScene : FieldAxis {
  std::string source;  // file name, for messages
  std::string title;
  int components = 1;
  std::vector<FieldAxis> cross_axes;
  int Dim() const { return 1 + int(cross_axes.size()); }
  const FieldAxis& Axis(int a) const {
    return a == 0 ? *this : cross_axes.at(std::size_t(a) - 1);
  }
  long long GridPoints() const {
    long long n = space_points;
    for (const auto& a : cross_axes) n *= a.space_points;
    return n;
  }
  sbp::SpaceGrid<double> Grid() const;
  std::vector<ListedEffect> terms;  // type from FieldTermCatalogue()
  struct Initial {
    std::string profile;
    std::map<std::string, double> parameters;  // defaults filled in
    // d > 1: the vector parameters (center, k), one entry per axis.
    std::map<std::string, std::vector<double>> vectors;
    std::string file;  // csv: as resolved
    bool allow_jump = false;
    double jump = 0;  // periodic: |φ(x_last + Δx) − φ(x0)|, max over a
  } initial;
  // The initial data on the grid, value j·components + a.
  std::vector<double> phi0, phi_t0;
  // The exact solution when the profile has one for these terms, else empty
  // with the reason in no_exact.
  FieldFormula exact;
  std::string no_exact;
  double t_end = 1;
  long long time_points = 0;
  struct Method {
    std::string op = "sbp42";
    long long window_points = 0;  // 0: one global solve (error control: 16)
    // Error control: each window's Δt from its estimates ([time] points
    // is then not given).
    variational::Tolerance tolerance;
    // The window's linear solver: "modes" (the space-diagonalized solve)
    // or "sparse-lu" (the reference).
    std::string linear_solver = "modes";
  } method;
  struct Output {
    std::vector<std::string> diagnostics;
    long long stride = 1;
    std::string format = "csv";  // d > 1: hdf5
    bool phi_t = true;
    std::vector<double> heat_maps;  // d > 1: times of the PNG heat maps
    bool animation = true;          // d > 1: the GIF of the slices
    std::vector<double> spectra;    // periodic axes: times of P(k) of φ
  } output;
  // "FILE:LINE:COL: " of [time] points, where an under-resolved grid is
  // reported, and warnings for the reader (an accepted jump).
  std::string where_time_points;
  // "FILE:LINE:COL: " of a vortex profile's key, where a start whose
  // relaxation moved or annihilated a vortex is reported (phi0 is then
  // empty until the run relaxes it: charged_scene.h).
  std::string where_initial;
  std::vector<std::string> warnings;

  bool Wants(const std::string& diagnostic) const;
  // A gauge field: the 'maxwell' term alone, solved as
  // fields::MaxwellIn<d>.
  bool Gauge() const;
  // Charged matter: 'scalar_qed' (+ 'abelian_higgs') with 'maxwell', solved
  // on links (charged_scene.h); phi0 and phi_t0 then hold (Re φ, Im φ, A_b)
  // and (Re π, Im π, ∂_tA_b) per point, and `components` counts the values
  // written per point (|φ|, E_b, ρ).
  bool Charged() const;
  // The ends' data for the solver (constant in time); on a grid of d > 1
  // axes, Neumann faces.
  spacetime::FieldBoundary Boundary() const;
  // The density of the terms, for components() = M.
  template <int M, int d = 1>
  fields::ComposedDensity<M, d> Density() const {
    return {Terms()};
  }
  std::vector<fields::FieldTerm> Terms() const;
};

// Every slice of φ and φ_t is kept for the output: 2^24 values are 256 MB.
// (Under error control the slices are not known in advance: the march stops
// when it would keep more, FieldSolveOptions::max_points.)
inline constexpr long long kMaxFieldValues = 1LL << 24;

// A point-mechanics or a field scene, as the file says.
using AnyScene = std::variant<Scene, FieldScene>;

AnyScene ParseAnyScene(std::string_view text, const std::string& source);
// Reads FILE and parses it; a CSV profile's path is relative to FILE.
AnyScene ReadAnyScene(const std::filesystem::path& file);

// The scene as parsed, defaults filled in (for summary.json).
nlohmann::json FieldSceneJson(const FieldScene& scene);

// The terms a field scene may list, and the values names.
const std::vector<EffectType>& FieldTermCatalogue();
fields::FieldTerm MakeFieldTerm(const EffectType& type,
                                const ParameterValues& values);
const std::vector<std::string>& FieldProfileNames();
const std::vector<std::string>& FieldDiagnosticNames();

// The field part of `vivp run --help`.
std::string FieldSchemaHelp();

}  // namespace vivp::scene
