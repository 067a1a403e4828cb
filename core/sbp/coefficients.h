// Coefficient tables of diagonal-norm first-derivative SBP operators.
//
// A table holds exact rationals per unit grid spacing: the derivative is D/dt
// and the norm is dt*H. It describes one operator completely:
//   * norm_weights: H_00, H_11, ... of the left closure (all other weights 1,
//     the right closure mirrored);
//   * boundary_block: rows 0..r-1 of D, each starting at column 0;
//   * interior_stencil: the centred stencil on offsets -k..k used by every row
//     between the closures.
// The right closure follows by antisymmetry, D[N-1-i][N-1-j] = -D[i][j].
// Tables are facts from the cited papers; builder.h turns them into an
// Operator in any floating-point type.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace vivp::sbp {

// An exact rational p/q, lifted into a floating-point type as the correctly
// rounded quotient of two exactly representable integers.
struct Rational {
  std::int64_t num;
  std::int64_t den;

  template <class Real>
  Real As() const {
    return static_cast<Real>(num) / static_cast<Real>(den);
  }
};

struct Coefficients {
  std::string_view name;  // "sbp21", "sbp42", ...
  std::string_view citation;
  int interior_order;
  int boundary_order;
  // Smallest grid on which the two closures do not overlap (2 * rows).
  int min_points;
  std::vector<Rational> norm_weights;
  std::vector<std::vector<Rational>> boundary_block;
  std::vector<Rational> interior_stencil;

  int boundary_rows() const { return static_cast<int>(boundary_block.size()); }
  int half_width() const {
    return static_cast<int>(interior_stencil.size()) / 2;
  }
};

}  // namespace vivp::sbp
