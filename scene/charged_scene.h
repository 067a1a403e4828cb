// A field scene with charged matter: the terms 'maxwell' + 'scalar_qed'
// (+ 'abelian_higgs'), solved as the lattice action of a charged field and
// its U(1) gauge field (core/action/charged_field.h) and marched window by
// window (solvers/spacetime/charged_march.h). The potentials and the phase
// of φ depend on the gauge, so what a run keeps and writes per point is
// gauge invariant: |φ|, E along each axis and the action's charge density ρ
// (docs/field_scenes.md §8). Private to scene/ and apps/.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "problems/fields/charged.h"
#include "scene/field_run.h"
#include "scene/field_scene.h"

namespace vivp::scene {

// The model of the scene's terms: m² of 'scalar_qed', λ and v² of
// 'abelian_higgs', e(t) = e(1 + a sin ωt).
fields::ScalarQed ChargedModel(const FieldScene& s);

// The values written per point: abs_phi, E_x [, E_y], rho, and the labels
// of their plots.
std::vector<std::string> ChargedValueNames(int d);
std::vector<std::string> ChargedValueLabels(int d);

// The fastest frequency of the lattice under the scene's data: the links'
// √(Σ_b 4/h_b²), the potential's radial curvature and the photon's mass
// 2e²|φ|² at the data's largest |φ|, e at its largest over [0, T].
double ChargedOmegaMax(const FieldScene& s);

// s.phi0 and s.phi_t0 in charged_field.h's layout (χ = 0 after A_b).
void ChargedSystemData(const FieldScene& s, std::vector<double>& phi,
                       std::vector<double>& pi);

// A vortex profile's start (s.phi0, s.phi_t0): the ansatz relaxed to a
// static critical point (solvers/spacetime/vortex_data.h); returns the
// relaxation's residual. Throws a SceneError at s.where_initial when the
// relaxation moved a vortex by more than a spacing or annihilated one, or
// when the moving data carry a net charge.
double PrepareVortexStart(FieldScene& s);

// The march of the scene (a vortex profile's start relaxed first); an
// under-resolved grid or a window that fails its Newton solve or its Gauss
// check returns solution.status.converged = false with the reason.
FieldRun RunChargedScene(
    const FieldScene& s,
    const std::function<void(int, int, double)>& on_window);

}  // namespace vivp::scene
