// AccelerationFrom for every compiled-in dimension (extern in the header).
#include "core/action/euler_lagrange.h"

namespace vivp::action {
#define VIVP_ACCELERATION(D)                                  \
  template Eigen::Matrix<double, D, 1> AccelerationFrom<D>(   \
      const Eigen::Matrix<double, D, 1>&,                     \
      const Eigen::Matrix<double, D, 2 * D>&, const double*); \
  template Eigen::Matrix<double, D, 1> AccelerationFrom<D>(   \
      const Diagonal<double, D>&, const double*);
VIVP_PRECOMPILED_DIMS(VIVP_ACCELERATION)
#undef VIVP_ACCELERATION
}  // namespace vivp::action
