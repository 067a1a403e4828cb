// The classical diagonal-norm SBP operators of orders 2/1 and 4/2.
//
// Sources: H.-O. Kreiss, G. Scherer (1974), "Finite element and finite
// difference methods for hyperbolic partial differential equations", in
// Mathematical Aspects of Finite Elements in PDEs, Academic Press, 195-212;
// B. Strand (1994), "Summation by parts for finite difference approximations
// for d/dx", J. Comput. Phys. 110(1), 47-67, doi:10.1006/jcph.1994.1005.
// The 4/2 operator is also eq. (22) of Rothkopf & Nordström (2023), whose
// printed row 3 has typos; the row below is the SBP-consistent one (it matches
// SummationByPartsOperators.jl, MattssonNordström2004(), accuracy_order = 4).
// The `measured` rows are this code's measurements, not the papers'
// (coefficients.h, Measured).
#pragma once

#include "core/sbp/coefficients.h"

namespace vivp::sbp {

inline constexpr std::string_view kSbp21Citation =
    "Kreiss & Scherer (1974), Mathematical Aspects of Finite Elements in "
    "PDEs, 195-212; Strand (1994), J. Comput. Phys. 110, 47-67";
inline constexpr std::string_view kSbp42Citation = kSbp21Citation;

// SBP21: interior order 2, boundary order 1.
inline const Coefficients& Sbp21() {
  static const Coefficients kCoefficients{
      .name = "sbp21",
      .citation = kSbp21Citation,
      .interior_order = 2,
      .boundary_order = 1,
      .min_points = 2,
      .norm_weights = {{1, 2}},
      .boundary_block =
          {
              {{-1, 1}, {1, 1}},
          },
      .interior_stencil = {{-1, 2}, {0, 1}, {1, 2}},
      .measured =
          {
              .stability_limit = 0.70,
              // Not an estimate: its ratio to the true error of x_N is
              // 0.02–19, and the corrected x_N is not more accurate than
              // x_N; the velocity estimate is one (ratio 0.9–1.1).
              .position_estimate = false,
              // Step doubling of a first-order end velocity.
              .estimate_order = 1.0,
              .lm_window_points = 192,
              // No fill: 512 × 512 in 710 MB (docs/fields.md §8).
              .field_values_at_once = 1LL << 18,
          },
  };
  return kCoefficients;
}

// SBP42: interior order 4, boundary order 2.
inline const Coefficients& Sbp42() {
  static const Coefficients kCoefficients{
      .name = "sbp42",
      .citation = kSbp42Citation,
      .interior_order = 4,
      .boundary_order = 2,
      .min_points = 8,
      .norm_weights = {{17, 48}, {59, 48}, {43, 48}, {49, 48}},
      .boundary_block =
          {
              {{-24, 17}, {59, 34}, {-4, 17}, {-3, 34}},
              {{-1, 2}, {0, 1}, {1, 2}},
              {{4, 43}, {-59, 86}, {0, 1}, {59, 86}, {-4, 43}},
              {{3, 98}, {0, 1}, {-59, 98}, {0, 1}, {32, 49}, {-4, 49}},
          },
      .interior_stencil = {{1, 12}, {-2, 3}, {0, 1}, {2, 3}, {-1, 12}},
      .measured =
          {
              .stability_limit = 1.00,
              .position_estimate = true,
              // Measured 2.1–2.7.
              .estimate_order = 2.1,
              .lm_window_points = 128,
              // Fills: a global Klein–Gordon solve took 0.35 GB and 3.3 s at
              // 257 × 128, 1.1 GB at 257 × 256 (peak memory, `vivp converge
              // --field klein_gordon`).
              .field_values_at_once = 1LL << 15,
          },
  };
  return kCoefficients;
}

}  // namespace vivp::sbp
