// README "Add a Lagrangian": the struct between the markers is shown there
// verbatim; tests/example_add_a_lagrangian.cc checks its trajectory against
// the exact circle, and lagrangians/cyclotron.cc registers it by name (the
// problem and scene type "cyclotron").
#pragma once

namespace vivp::problems {

// --- example ---
// A charge in a uniform magnetic field B ẑ (symmetric gauge):
//   L = ½|ẋ|² + ½B (x ẏ − y ẋ),   so   ẍ = B ẏ,  ÿ = −B ẋ.
struct Cyclotron {
  static constexpr int kDim = 2;
  double B = 2.0;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * (v[0] * v[0] + v[1] * v[1]) +
           T(0.5 * B) * (x[0] * v[1] - x[1] * v[0]);
  }
};
// --- end of example ---

}  // namespace vivp::problems
