// The start of a vortex scene (charged_scene.h): relaxed here, when the run
// begins, rather than by the reader, so that reading or checking a scene
// costs no minimisation.
#include "core/action/charged_field.h"
#include "scene/charged_scene.h"
#include "scene/scene.h"
#include "scene/text.h"
#include "solvers/spacetime/charged_march.h"
#include "solvers/spacetime/vortex_data.h"

namespace vivp::scene {

double PrepareVortexStart(FieldScene& s) {
  const auto model = ChargedModel(s);
  const auto grid = s.Grid();
  const bool pair = s.initial.profile == "vortex_pair";
  const auto& p = s.initial.parameters;
  const auto d =
      pair ? spacetime::VortexPairData(model, grid, p.at("separation"))
           : spacetime::VortexCollisionData(model, grid, p.at("offset"),
                                            p.at("speed"), p.at("transition"));
  // A relaxation that moved a vortex by more than a spacing, or
  // annihilated one, is not the start the scene asked for.
  if (!(d.moved <= grid.axis(0).dx()))
    throw SceneError(
        s.where_initial + "relaxing the static start moved a vortex by " +
        detail::FormatNumber(d.moved) + " (" + std::to_string(d.found) +
        " zeros of φ left): the vortices attract, or annihilated; expected "
        "vortices farther apart, or critical coupling λ = e² (where like "
        "vortices exert no force)");
  constexpr int given = 2 + 2, m = 5;
  s.phi0.assign(std::size_t(grid.points()) * given, 0.0);
  s.phi_t0.assign(s.phi0.size(), 0.0);
  for (int j = 0; j < grid.points(); ++j)
    for (int a = 0; a < given; ++a) {
      s.phi0[std::size_t(j) * given + a] = d.x[std::size_t(j) * m + a];
      s.phi_t0[std::size_t(j) * given + a] = d.pi[std::size_t(j) * m + a];
    }
  std::vector<double> phi, pi;
  ChargedSystemData(s, phi, pi);
  const std::string why = spacetime::NetChargeReason<
      action::ChargedFieldSystem<fields::ScalarQed, 2>>(grid, phi, pi);
  if (!why.empty())
    throw SceneError(s.where_initial + why +
                     "; expected a smaller speed (the moving data's charge "
                     "cancels between the two vortices)");
  return d.relax.residual;
}

}  // namespace vivp::scene
