// The Hamiltonian of a conservative composition of effects (composed.h),
// for the steppers of solvers/steppers:
//   H(q, p) = ½ pᵀM⁻¹p + V(q),  V = −Σ (the effects' Lagrangian terms at q),
// M the sum of the kinetic effects' masses. Separable, so Störmer–Verlet
// applies. For the discrete gradient (LeMesurier 2012, §5.2;
// docs/steppers.md §3), H is written through
//   ŷ = (½pᵀM⁻¹p, |q|², q₀, …, q_{D−1}):
// potentials of r² (spring without centre, quartic, central, Gaussian well)
// through ŷ₁, the others (gravity, pendulum, chain, spring with centre)
// through the coordinates (affine invariants, as for the pendulum). Only the
// invariants some effect uses are active, so a purely radial potential keeps
// the rotation symmetry and the discrete gradient conserves the angular
// momentum too.
#pragma once

#include <Eigen/Dense>
#include <stdexcept>
#include <vector>

#include "problems/composed.h"

namespace vivp::problems {

template <int D>
class ComposedHamiltonian {
 public:
  static constexpr int kDim = D;
  static constexpr bool kSeparable = true;
  static constexpr int kInvariantCount = D + 2;

  // Throws std::invalid_argument for a dissipative effect or no kinetic one.
  explicit ComposedHamiltonian(const std::vector<Effect>& effects) {
    Eigen::Matrix<double, D, D> mass = Eigen::Matrix<double, D, D>::Zero();
    bool kinetic = false;
    for (const Effect& e : effects) {
      if (IsDissipative(e))
        throw std::invalid_argument("a dissipative effect has no Hamiltonian");
      if (const auto* k = std::get_if<effects::Kinetic>(&e)) {
        kinetic = true;
        if (k->matrix.empty())
          mass += k->mass * Eigen::Matrix<double, D, D>::Identity();
        else
          mass +=
              Eigen::Map<const Eigen::Matrix<double, D, D, Eigen::RowMajor>>(
                  k->matrix.data());
        continue;
      }
      potentials_.push_back(e);
      const bool radial = std::visit(
          [](const auto& t) {
            if constexpr (requires { t.radial(); })
              return t.radial();
            else
              return false;
          },
          e);
      (radial ? uses_radius_ : uses_coordinates_) = true;
    }
    if (!kinetic)
      throw std::invalid_argument("no kinetic effect: no Hamiltonian H(q, p)");
    inverse_mass_ = mass.inverse();
    mass_ = mass;
  }

  const Eigen::Matrix<double, D, D>& mass() const { return mass_; }
  const Eigen::Matrix<double, D, D>& inverse_mass() const {
    return inverse_mass_;
  }

  template <class T>
  T Hamiltonian(const T* q, const T* p) const {
    T h = KineticEnergy(p);
    const T* none = nullptr;
    for (const Effect& e : potentials_)
      std::visit(
          [&](const auto& t) {
            if constexpr (HasLagrangian<decltype(t)>)
              h -= t.template Lagrangian<D>(q, none);
          },
          e);
    return h;
  }

  template <class T>
  void QuadraticInvariants(const T* q, const T* p, T* y) const {
    y[0] = KineticEnergy(p);
    y[1] = q[0] * q[0];
    for (int c = 1; c < D; ++c) y[1] += q[c] * q[c];
    for (int c = 0; c < D; ++c) y[2 + c] = q[c];
  }

  template <class T>
  T HamiltonianOfInvariants(const T* y) const {
    T h = y[0];
    const T* none = nullptr;
    for (const Effect& e : potentials_)
      std::visit(
          [&](const auto& t) {
            if constexpr (requires { t.RadialLagrangian(y[1]); }) {
              if (t.radial()) {
                h -= t.RadialLagrangian(y[1]);
                return;
              }
            }
            if constexpr (HasLagrangian<decltype(t)>)
              h -= t.template Lagrangian<D>(y + 2, none);
          },
          e);
    return h;
  }

  // Whether Ĥ depends on ŷ_k (the discrete gradient corrects only those).
  bool InvariantActive(int k) const {
    return k == 0 || (k == 1 ? uses_radius_ : uses_coordinates_);
  }

 private:
  template <class T>
  T KineticEnergy(const T* p) const {
    T k = T(0.0);
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c)
        if (inverse_mass_(r, c) != 0)
          k += T(0.5 * inverse_mass_(r, c)) * p[r] * p[c];
    return k;
  }

  std::vector<Effect> potentials_;
  Eigen::Matrix<double, D, D> mass_, inverse_mass_;
  bool uses_radius_ = false, uses_coordinates_ = false;
};

}  // namespace vivp::problems
