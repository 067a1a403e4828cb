#include "solvers/bea/potentials.h"

#include <stdexcept>
#include <string>

namespace vivp::bea {

std::unique_ptr<NumericPotential> MakePotential(const std::string& name,
                                                int dim, PotentialModel model) {
  if (name == "pendulum") {
    if (dim != 1 || model != PotentialModel::kGeneric)
      throw std::invalid_argument(
          "the pendulum potential is one-dimensional and generic (dim 1, "
          "PotentialModel::kGeneric); got dim " +
          std::to_string(dim));
    return std::make_unique<Pendulum>();
  }
  if (name == "gaussian") {
    if (model == PotentialModel::kRadial)
      return std::make_unique<RadialGaussian>(dim);
    return std::make_unique<Gaussian>(dim);
  }
  throw std::invalid_argument("unknown potential '" + name +
                              "' (use pendulum or gaussian)");
}

}  // namespace vivp::bea
