// The non-local discrete NLS of LeMesurier 2012, eq. (6), on a periodic
// chain of kSites sites (z_{n+kSites} = z_n):
//   i ż_n + κ(z_{n+1} + z_{n−1}) + (½|z_{n−1}|² + |z_n|² + ½|z_{n+1}|²) z_n =
//   0.
// Convention (docs/steppers.md §4): (6) as printed is ż = i ∂H/∂z* for
//   H = κ Σ σ_n + ½ Σ ρ_n(ρ_n + ρ_{n+1}),  ρ_n = |z_n|², σ_n = z_n* z_{n+1} +
//   c.c.,
// i.e. eq. (12) with κ → −κ. With z_n = (q_n − i p_n)/√2 this is Hamilton's
// q̇ = ∂H/∂p, ṗ = −∂H/∂q, with ρ_n = ½(q_n² + p_n²), σ_n = q_n q_{n+1} + p_n
// p_{n+1}. Initial data: the NLS soliton A sech(A(n − n₀)) e^{−ivn/2} at double
// height (LeMesurier 2012, §6), centred at n₀ = kSites/2. Default A = 0.5
// (height 1, about four sites wide); A = 2 is the large-amplitude case of
// LeMesurier 2012.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace vivp::problems {

template <int kSites = 32>
struct NldnlsChain {
  static constexpr int kDim = kSites;
  static constexpr bool kSeparable = false;
  double kappa = 1.0;
  double amplitude = 0.5;  // A of the sech profile (height is 2A)
  double velocity = 0.0;   // v of the sech profile

  // H as above in real canonical coordinates.
  template <class T>
  T Hamiltonian(const T* q, const T* p) const {
    T yhat[2 * kSites];
    QuadraticInvariants(q, p, yhat);
    return HamiltonianOfInvariants(yhat);
  }

  // ŷ = (ρ_0..ρ_{N−1}, σ_0..σ_{N−1}): the quadratic invariants of §5.2.
  static constexpr int kInvariantCount = 2 * kSites;
  template <class T>
  void QuadraticInvariants(const T* q, const T* p, T* y) const {
    for (int n = 0; n < kSites; ++n) {
      const int m = (n + 1) % kSites;
      y[n] = T(0.5) * (q[n] * q[n] + p[n] * p[n]);
      y[kSites + n] = q[n] * q[m] + p[n] * p[m];
    }
  }
  // Ĥ = κ Σ σ_n + ½ Σ ρ_n(ρ_n + ρ_{n+1}): quadratic in ŷ, so the discrete
  // gradient of Ĥ is its gradient at the midpoint (the product rule of (90)).
  template <class T>
  T HamiltonianOfInvariants(const T* y) const {
    T h = T(0.0);
    for (int n = 0; n < kSites; ++n)
      h += T(kappa) * y[kSites + n] +
           T(0.5) * y[n] * (y[n] + y[(n + 1) % kSites]);
    return h;
  }

  // The charge Σ|z_n|² (conserved by the phase symmetry z → e^{iα}z).
  static std::vector<std::string> InvariantNames() { return {"charge"}; }
  std::vector<double> Invariants(const double* q, const double* p) const {
    double c = 0;
    for (int n = 0; n < kSites; ++n) c += 0.5 * (q[n] * q[n] + p[n] * p[n]);
    return {c};
  }

  // (q, p) of the initial data.
  std::vector<double> Initial() const {
    std::vector<double> y(2 * kSites);
    for (int n = 0; n < kSites; ++n) {
      const double x = n - kSites / 2;
      const double r = 2 * amplitude / std::cosh(amplitude * x);
      const double phase = -0.5 * velocity * x;
      // z = r e^{iφ} = (q − ip)/√2
      y[n] = std::sqrt(2.0) * r * std::cos(phase);
      y[kSites + n] = -std::sqrt(2.0) * r * std::sin(phase);
    }
    return y;
  }

  // |z_n| from (q, p).
  static double Modulus(const double* q, const double* p, int n) {
    return std::sqrt(0.5 * (q[n] * q[n] + p[n] * p[n]));
  }
};

using Nldnls = NldnlsChain<>;

}  // namespace vivp::problems
