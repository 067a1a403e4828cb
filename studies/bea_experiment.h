// The experiment of McLachlan & Offen 2023 (docs/bea.md §5): the multistep
// method (4.1) with A = −0.2 I on the Gaussian well U = exp(−|x|²/2) in
// d = 2, from x(0) = (1, −1), ẋ(0) = (0.1, −0.2); its modified quantities
// derived to h⁴ in the radial potential model, with the plane rotation as the
// symmetry whose charge is the modified angular momentum. Shared by the
// figures of the paper, the step-size sweep, the conservation test and the
// bench.
#pragma once

#include "solvers/bea/conservation.h"

namespace vivp::studies {

struct GaussianWellExperiment {
  GaussianWellExperiment();
  // The quantities are compiled from the derivation they refer to.
  GaussianWellExperiment(const GaussianWellExperiment&) = delete;
  GaussianWellExperiment& operator=(const GaussianWellExperiment&) = delete;

  // The trajectory's data up to t_end, ẋ recovered from it by central
  // differences of the given order.
  bea::ConservationSetup Setup(double t_end, int difference_order = 6) const;

  bea::BeaResult derivation;
  bea::RadialGaussian potential{2};
  bea::ModifiedQuantities quantities;
};

}  // namespace vivp::studies
