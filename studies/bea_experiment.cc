#include "studies/bea_experiment.h"

namespace vivp::studies {

namespace {

bea::DeriveOptions Options() {
  bea::DeriveOptions o;
  o.order = 4;
  o.model = bea::PotentialModel::kRadial;
  o.symmetry = bea::PlaneRotation();
  return o;
}

}  // namespace

GaussianWellExperiment::GaussianWellExperiment()
    : derivation(bea::Derive(
          bea::MakeLmm4(bea::ScalarMatrix(GiNaC::numeric(-1, 5), 2)),
          Options())),
      quantities(derivation, potential) {}

bea::ConservationSetup GaussianWellExperiment::Setup(
    double t_end, int difference_order) const {
  bea::ConservationSetup s;
  s.x0 = Eigen::Vector2d(1, -1);
  s.v0 = Eigen::Vector2d(0.1, -0.2);
  s.t_end = t_end;
  s.difference_order = difference_order;
  return s;
}

}  // namespace vivp::studies
