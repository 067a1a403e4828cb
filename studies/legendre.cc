// InvertMass for every compiled-in dimension (extern in legendre.h).
#include "studies/legendre.h"

namespace vivp::studies::detail {
#define VIVP_INVERT_MASS(D)                                       \
  template bool InvertMass<D>(const Eigen::Matrix<double, D, D>&, \
                              Eigen::Matrix<double, D, D>*);
VIVP_PRECOMPILED_DIMS(VIVP_INVERT_MASS)
#undef VIVP_INVERT_MASS
}  // namespace vivp::studies::detail
