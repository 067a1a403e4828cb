// Scalar electrodynamics in 1 + 1 D measured (docs/gauge.md §8): the data
// of a particle and an antiparticle moving towards each other on a periodic
// line, and one run of the Gauss-law study — the pair marched window by
// window with A₀ free at every node, the action's Gauss law at every node
// and the textbook law beside it.
#pragma once

#include <string>
#include <vector>

#include "core/sbp/space_grid.h"
#include "problems/fields/charged.h"

namespace vivp::studies {

// φ and π (charged_field.h's layout, m = 4) of g(x − x₁)e^{ikx} and
// g(x − x₂)e^{ikx} with velocities −iωφ₁ and +iωφ₂, g = 0.5 exp(−((x −
// x_c)/1.5)²), k = 0.8, ω = √(m² + k²), x₁ = 7, x₂ = L − 7: the grid's mirror
// symmetry makes the total charge vanish to round-off, as Gauss's law on
// a torus demands.
struct ChargedData {
  std::vector<double> phi, pi;
};
ChargedData ChargedPair(const sbp::SpaceGrid<double>& line, double mass2);

// The sweep of the Gauss-law tables (bench/gauge_bench, charged_bench):
// SBP21, SBP42, SBP63 and windows of 8 to 64 points, or SBP42 and windows
// of 16 when quick.
struct GaussSweep {
  std::vector<std::string> ops;
  std::vector<int> windows;
};
GaussSweep GaussSweepOf(bool quick);

// The model of the study: m² = 1, e = 0.7.
fields::ScalarQed StudyQed();

// The pair on [0, 20) with n points marched to t_end with windows of
// `window` points of `op`, Δt = fraction × the operator's resolution limit
// over the lattice's highest frequency √(m² + 4/h²).
struct ChargedGaussRun {
  std::string op;
  int window = 0, n = 0;
  double fraction = 1, dt = 0;
  int windows = 0;
  long long newton = 0;
  int retries = 0;               // windows solved again with full Newton steps
  double gauss = 0;              // the action's law, max over every node
  double textbook = 0;           // (D⁻·E)/e² − 2 Im(φ̄ D_0φ), the same
  double textbook_absolute = 0;  // its largest |·|, not relative
  double energy = 0;             // drift of the handed states' energy
  double seconds = 0;
  std::string failure;  // why it did not run, if it did not
};
ChargedGaussRun RunChargedGauss(const std::string& op, int window,
                                double fraction, int n, double t_end);

}  // namespace vivp::studies
