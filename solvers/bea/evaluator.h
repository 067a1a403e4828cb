// Fast numerical evaluation of symbolic results along trajectories.
//
// A polynomial in (x, x', potential symbols) is flattened once into a list
// of monomials (coefficient, variable indices and exponents); evaluation is
// a table of small powers plus one product per monomial -- no GiNaC at run
// time, no compiler, no dlopen. bench/bea_bench measures the rate.
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "solvers/bea/derivation.h"
#include "solvers/bea/potentials.h"

namespace vivp::bea {

class CompiledPolynomial {
 public:
  CompiledPolynomial() = default;
  // Throws std::invalid_argument if e contains a symbol outside `vars` or is
  // not a polynomial with rational coefficients.
  CompiledPolynomial(const GiNaC::ex& e,
                     const std::vector<GiNaC::symbol>& vars);
  // powers[v * stride + k] = value_v^k, k <= max_exponent().
  double Evaluate(const double* powers, int stride) const;
  int max_exponent() const { return max_exponent_; }
  std::size_t terms() const { return coeff_.size(); }

 private:
  std::vector<double> coeff_;
  std::vector<int> start_;                    // per monomial, into factors_
  std::vector<std::pair<int, int>> factors_;  // (variable, exponent)
  int max_exponent_ = 0;
};

// Every modified quantity of a BeaResult, compiled for one concrete
// potential: H_mod, the charge, the symplectic form ω on (x, x') and the
// modified Lagrangian (where the derivation has one), each truncated at
// h^0, h^2, ..., and the modified equation. Parameters left symbolic in the
// derivation must be given numeric values in `parameters`.
class ModifiedQuantities {
 public:
  ModifiedQuantities(const BeaResult& r, const NumericPotential& potential,
                     const GiNaC::exmap& parameters = {});

  int order() const { return order_; }
  int dim() const { return dim_; }
  bool has_charge() const { return !charge_.empty(); }
  // H_0 + h^2 H_2 + ... + h^k H_k (k even <= order).
  double Hamiltonian(int k, double h, const double* x, const double* v) const;
  double Charge(int k, double h, const double* x, const double* v) const;
  // x'' = f(x, x'; h) truncated at h^k.
  void Acceleration(int k, double h, const double* x, const double* v,
                    double* a) const;
  // ω_ij truncated at h^k, row-major into omega[(2d)·(2d)] over the
  // coordinates (x_1..x_d, x'_1..x'_d).
  void SymplecticForm(int k, double h, const double* x, const double* v,
                      double* omega) const;
  // The first-order modified Lagrangian L_mod(x, x') truncated at h^k.
  // Throws std::logic_error if the derivation has none (d > 1 may not), or
  // if it is not a polynomial in the jet and potential symbols.
  bool has_lagrangian() const { return !lagrangian_.empty(); }
  double Lagrangian(int k, double h, const double* x, const double* v) const;

 private:
  double Sum(const std::vector<CompiledPolynomial>& c, int k, double h,
             const double* x, const double* v) const;
  void Powers(const double* x, const double* v) const;

  int order_, dim_;
  const NumericPotential& potential_;
  std::vector<GiNaC::symbol> vars_;
  std::vector<std::vector<int>> potential_index_;  // per potential variable
  std::vector<CompiledPolynomial> hamiltonian_, charge_, lagrangian_;
  std::vector<std::vector<CompiledPolynomial>> f_;      // f_[i][p]
  std::vector<std::vector<CompiledPolynomial>> omega_;  // omega_[i·2d+j][p]
  std::string no_lagrangian_;  // why lagrangian_ is empty
  int stride_ = 1;
  mutable std::vector<double> powers_;
};

}  // namespace vivp::bea
