// Blended backward error analysis (McLachlan & Offen 2023, Sections 3 and 5;
// docs/bea.md §3): from a method's discrete Lagrangian to the modified
// equation, the modified Hamiltonian and symplectic form on the 1-jet
// (x, x'), Noether charges and, where it exists, a first-order modified
// Lagrangian.
//
//   auto r = vivp::bea::Derive(vivp::bea::MakeLmm4(ScalarMatrix(alpha, 2)),
//                              {.order = 4});
//   r.f[0]        // x1'' = f_0 + h^2 f_2 + h^4 f_4 (Series)
//   r.hamiltonian // H_0 + h^2 H_2 + h^4 H_4
//   r.omega[a][b] // in the frame (x_1..x_d, x'_1..x'_d); omega z' = grad H
//
// Steps (all truncated at h^order, everything polynomial):
//   1. L_h = sum_p h^p L_p on the jet (lagrangians.h);
//   2. Euler-Lagrange E_p = sum_k (-D_t)^k dL_p/dx^(k); odd p vanish;
//   3. x'' = grad U + sum_{p>=1} h^p E_p, higher derivatives replaced by
//      derivatives of the current x'' = f in fixed-point sweeps, each gaining
//      h^2 (Reduction);
//   4. Ostrogradsky: q_k = x^(k-1), p_k = sum_j (-D_t)^j dL/dx^(k+j),
//      H = sum_k p_k . x^(k) - L, reduced to the 1-jet;
//   5. omega = sum_k dp_k ^ dq_k pulled back to the 1-jet (eq. (3.3));
//   6. Noether charge of a linear symmetry x -> exp(sG) x: sum_k p_k . G q_k;
//   7. if the x'-x' block of omega vanishes (Proposition 6.1: the fibres are
//      Lagrangian) and the x-x block vanishes at x' = 0: the momentum P_i
//      with dP_i/dx'_j = omega[x'_j][x_i], P(x, 0) = 0 (fibre homotopy), and
//      L_mod = P . x' - H. For (4.1) with A = alpha I this holds at every
//      order; for a general symmetric A the x'-x' block is nonzero from h^4 on
//      (at h^2 only the x-x block c J differs).
//
// Self-checks (SelfCheck below) run by default; Derive throws
// std::runtime_error when one fails.
#pragma once

#include <ginac/ginac.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solvers/bea/jet_space.h"
#include "solvers/bea/method.h"
#include "solvers/bea/series.h"

namespace vivp::bea {

struct DeriveOptions {
  int order = 4;  // even, >= 2: truncation h^order
  PotentialModel model = PotentialModel::kGeneric;
  // Generator G (d x d, antisymmetric for rotations) of a linear symmetry
  // whose Noether charge is wanted. The Lagrangian must be invariant.
  std::optional<GiNaC::matrix> symmetry;
  bool self_checks = true;
  bool throw_on_failed_check = true;
};

// The generator of rotations in the (x1, x2) plane, [[0, −1], [1, 0]]: as
// DeriveOptions::symmetry, its Noether charge is the angular momentum.
GiNaC::matrix PlaneRotation();

struct SelfCheck {
  std::string name;
  bool passed = false;
  // Lowest order at which the identity fails (-1 if it holds).
  int failing_order = -1;
};

// Highest order Derive accepts for a method (bounded by run time). It
// falls with the dimension and with the number of free symbols in the
// coefficient matrices: measured at h^8 in d = 2, Störmer–Verlet 10 s, lmm4
// with A = alpha I 48 s, lmm4 with a general symbolic A (a11, a12, a22) more
// than 600 s — so that case stops at h^6 (6 s).
int MaxOrder(const Method& method);
// The number of distinct symbols in the coefficient matrices of a method.
int CoefficientSymbols(const Method& method);

struct BeaResult {
  std::shared_ptr<JetSpace> jet;
  Method method;
  int order = 0;
  std::vector<GiNaC::ex> lagrangian;                   // L_p on the jet
  std::vector<std::vector<GiNaC::ex>> euler_lagrange;  // E_p, per component
  std::vector<Series> f;  // modified equation x_i'' = f_i
  int sweeps = 0;
  Series hamiltonian;
  std::vector<std::vector<Series>> omega;  // 2d x 2d
  std::optional<Series> charge;
  // First-order modified Lagrangian in the original variables, where it
  // exists (step 7).
  std::optional<Series> modified_lagrangian;
  std::vector<SelfCheck> checks;
  double seconds = 0;  // wall time of the derivation (without checks)
  // Wall time per stage (name, seconds), for benchmarks.
  std::vector<std::pair<std::string, double>> stage_seconds;
  double check_seconds = 0;

  // Convenience: the 1-jet coordinates.
  GiNaC::symbol x(int i) const { return jet->X(i, 0); }
  GiNaC::symbol v(int i) const { return jet->X(i, 1); }
};

// Throws std::invalid_argument for an odd order, an order below 2, or one
// above MaxOrder(method) (with the time it would take and how to proceed).
BeaResult Derive(const Method& method, const DeriveOptions& options);

// Derive's self-checks, each on its own (a test shows each one failing on a
// deliberately wrong result):
// the odd orders of the Euler-Lagrange expansion vanish identically;
SelfCheck CheckOddOrdersVanish(const BeaResult& r);
// Hamilton's equations with ω and H reproduce the modified equation;
SelfCheck CheckHamiltonianStructure(BeaResult& r);
// the modified charge (which r must have) is conserved by the modified flow;
SelfCheck CheckChargeConserved(BeaResult& r);
// the Lagrangian L(x, x') (a series) generates the modified equation: its
// Euler-Lagrange equations with x'' = f vanish to the truncation order.
SelfCheck CheckLagrangianGeneratesF(BeaResult& r, const Series& lagrangian);

}  // namespace vivp::bea
