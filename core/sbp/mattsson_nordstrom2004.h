// Diagonal-norm SBP first-derivative operators of orders 6/3 and 8/4.
//
// Source: K. Mattsson, J. Nordström (2004), "Summation by parts operators for
// finite difference approximations of second derivatives", J. Comput. Phys.
// 199(2), 503-540, doi:10.1016/j.jcp.2004.03.001; exact rationals as shipped in
// SummationByPartsOperators.jl (MattssonNordström2004(), commit 6255f4c).
//
// Cautions (both are facts about these particular family members):
//  * SBP63 fixes the free parameter x1 = Q[4][5] = 342523/518400. The member
//    with x1 = 0.70127 found in other codes has the same norm but a different
//    boundary block; do not mix rows from the two.
//  * SBP84 fixes r67 = -231661/322560, r68 = 7120007/33868800,
//    r78 = 70710683/101606400. Its boundary block has entries up to about 130,
//    so its spectral radius is about 124/dt against 1.73/dt for the interior
//    stencil alone.
// The `measured` rows are this code's measurements, not the paper's
// (coefficients.h, Measured).
#pragma once

#include "core/sbp/coefficients.h"

namespace vivp::sbp {

// The tables keep one closure row per line, as in the paper.
// clang-format off

inline constexpr std::string_view kSbp63Citation =
    "Mattsson & Nordström (2004), J. Comput. Phys. 199, 503-540 "
    "(x1 = 342523/518400)";
inline constexpr std::string_view kSbp84Citation =
    "Mattsson & Nordström (2004), J. Comput. Phys. 199, 503-540";

// SBP63: interior order 6, boundary order 3.
inline const Coefficients& Sbp63() {
  static const Coefficients kCoefficients{
      .name = "sbp63",
      .citation = kSbp63Citation,
      .interior_order = 6,
      .boundary_order = 3,
      .min_points = 12,
      .norm_weights = {{13649, 43200}, {12013, 8640}, {2711, 4320}, {5359, 4320}, {7877, 8640}, {43801, 43200}},
      .boundary_block =
          {
              {{-21600, 13649}, {104009, 54596}, {30443, 81894}, {-33311, 27298}, {16863, 27298}, {-15025, 163788}},
              {{-104009, 240260}, {0, 1}, {-311, 72078}, {20229, 24026}, {-24337, 48052}, {36661, 360390}},
              {{-30443, 162660}, {311, 32532}, {0, 1}, {-11155, 16266}, {41287, 32532}, {-21999, 54220}},
              {{33311, 107180}, {-20229, 21436}, {485, 1398}, {0, 1}, {4147, 21436}, {25427, 321540}, {72, 5359}},
              {{-16863, 78770}, {24337, 31508}, {-41287, 47262}, {-4147, 15754}, {0, 1}, {342523, 472620}, {-1296, 7877}, {144, 7877}},
              {{15025, 525612}, {-36661, 262806}, {21999, 87602}, {-25427, 262806}, {-342523, 525612}, {0, 1}, {32400, 43801}, {-6480, 43801}, {720, 43801}},
          },
      .interior_stencil = {{-1, 60}, {3, 20}, {-3, 4}, {0, 1}, {3, 4}, {-3, 20}, {1, 60}},
      .measured =
          {
              .stability_limit = 0.95,
              .position_estimate = true,
              .estimate_order = 2.4,  // measured 2.4–3.1
              .lm_window_points = 16,
              // Fills as SBP42 and SBP84 do; their limit.
              .field_values_at_once = 1LL << 15,
          },
  };
  return kCoefficients;
}

// SBP84: interior order 8, boundary order 4.
inline const Coefficients& Sbp84() {
  static const Coefficients kCoefficients{
      .name = "sbp84",
      .citation = kSbp84Citation,
      .interior_order = 8,
      .boundary_order = 4,
      .min_points = 16,
      .norm_weights = {{1498139, 5080320}, {1107307, 725760}, {20761, 80640}, {1304999, 725760}, {299527, 725760}, {103097, 80640}, {670091, 725760}, {5127739, 5080320}},
      .boundary_block =
          {
              {{-2540160, 1498139}, {5544277, 5992556}, {198794991, 29962780}, {-256916579, 17977668}, {20708767, 1498139}, {-41004357, 5992556}, {27390659, 17977668}, {-2323531, 29962780}},
              {{-5544277, 31004596}, {0, 1}, {-85002381, 22146140}, {49607267, 4429228}, {-165990199, 13287684}, {7655859, 1107307}, {-7568311, 4429228}, {48319961, 465068940}},
              {{-66264997, 8719620}, {9444709, 415220}, {0, 1}, {-20335981, 249132}, {32320879, 249132}, {-35518713, 415220}, {2502774, 103805}, {-3177073, 1743924}},
              {{256916579, 109619916}, {-49607267, 5219996}, {61007943, 5219996}, {0, 1}, {-68748371, 5219996}, {65088123, 5219996}, {-66558305, 15659988}, {3870214, 9134993}},
              {{-20708767, 2096689}, {165990199, 3594324}, {-96962637, 1198108}, {68748371, 1198108}, {0, 1}, {-27294549, 1198108}, {14054993, 1198108}, {-42678199, 25160268}, {-2592, 299527}},
              {{13668119, 8660148}, {-850651, 103097}, {35518713, 2061940}, {-21696041, 1237164}, {9098183, 1237164}, {0, 1}, {-231661, 412388}, {7120007, 43300740}, {3072, 103097}, {-288, 103097}},
              {{-27390659, 56287644}, {7568311, 2680364}, {-22524966, 3350455}, {66558305, 8041092}, {-14054993, 2680364}, {2084949, 2680364}, {0, 1}, {70710683, 93812740}, {-145152, 670091}, {27648, 670091}, {-2592, 670091}},
              {{2323531, 102554780}, {-48319961, 307664340}, {9531219, 20510956}, {-3870214, 5127739}, {2246221, 3238572}, {-21360021, 102554780}, {-70710683, 102554780}, {0, 1}, {4064256, 5127739}, {-1016064, 5127739}, {193536, 5127739}, {-18144, 5127739}},
          },
      .interior_stencil = {{1, 280}, {-4, 105}, {1, 5}, {-4, 5}, {0, 1}, {4, 5}, {-1, 5}, {4, 105}, {-1, 280}},
      .measured =
          {
              .stability_limit = 0.90,
              .position_estimate = true,
              .estimate_order = 4.3,  // measured 4.3–4.5
              // None: the condition number is ~1e9 in every window.
              .lm_window_points = 0,
              // Fills: a global Klein–Gordon solve took 2.1 GB and 55 s at
              // 257 × 256 (peak memory, `vivp converge --field klein_gordon`).
              .field_values_at_once = 1LL << 15,
          },
  };
  return kCoefficients;
}

// clang-format on

}  // namespace vivp::sbp
