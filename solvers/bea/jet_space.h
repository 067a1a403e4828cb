// The jet space (x, x', x'', ...) of a curve x(t) in R^d, with a potential
// whose derivatives are symbols that depend on x implicitly.
//
// Conventions of McLachlan & Offen 2023 and their code (docs/bea.md §1):
// x'' = grad U(x), L = |x'|^2/2 + U, so U is minus the potential energy (for
// Stormer-Verlet's W, U = -W).
//
// Two potential models:
//   kGeneric  U_a = d^a U / dx^a for every multi-index a, with dU_a/dx_i =
//             U_{a+e_i};
//   kRadial   U = V(|x|^2)/2, symbols V_k = V^(k)(r), dV_k/dx_i = 2 x_i V_{k+1}
//             (rotation invariant, for Noether charges of rotations).
// A concrete potential enters only numerically (potentials.h): the symbolic
// results stay polynomial in jet coordinates and potential symbols.
//
// Warning: never differentiate with GiNaC::diff alone with respect to x_i;
// the potential symbols depend on x. Use Partial(), which applies the chain
// rule (the "odd orders vanish" self-check catches this mistake).
#pragma once

#include <ginac/ginac.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "solvers/bea/series.h"

namespace vivp::bea {

enum class PotentialModel { kGeneric, kRadial };

class JetSpace {
 public:
  JetSpace(int dim, PotentialModel model);

  int dim() const { return dim_; }
  PotentialModel model() const { return model_; }

  // x_i^(k): position (k = 0), velocity (k = 1), higher derivatives. i < dim.
  GiNaC::symbol X(int i, int k);
  // U itself (a symbol, or V_0/2 for the radial model).
  GiNaC::ex Potential();
  // Generic model: U_a for the multi-index a (size dim).
  GiNaC::symbol U(const std::vector<int>& a);
  // Radial model: V_k = V^(k)(|x|^2).
  GiNaC::symbol V(int k);

  // Partial derivative with respect to x_i^(k); for k = 0 it includes the
  // chain rule through the potential symbols. Result expanded.
  GiNaC::ex Partial(const GiNaC::ex& e, int i, int k);
  // Total time derivative on the jet space: sum x_i^(k+1) d/dx_i^(k).
  GiNaC::ex TotalDerivative(const GiNaC::ex& e);

  // What a symbol stands for.
  struct SymbolInfo {
    enum Kind { kJet, kGenericPotential, kRadialPotential } kind;
    int component = 0;            // kJet: i
    int derivative = 0;           // kJet: k; kRadialPotential: k
    std::vector<int> multi = {};  // kGenericPotential: a
  };
  std::optional<SymbolInfo> Info(const GiNaC::symbol& s) const;
  // Highest k with x_i^(k) in e (-1 if none).
  int JetOrder(const GiNaC::ex& e) const;
  // Highest total derivative order of the potential in e (generic |a|, radial
  // k), used by numerical evaluation to size its tables.
  int PotentialOrder(const GiNaC::ex& e) const;

 private:
  GiNaC::ex PotentialPartial(const SymbolInfo& info, int i);

  int dim_;
  PotentialModel model_;
  std::map<std::pair<int, int>, GiNaC::symbol> jet_;
  std::map<std::vector<int>, GiNaC::symbol> generic_;
  std::map<int, GiNaC::symbol> radial_;
  std::map<GiNaC::ex, SymbolInfo, GiNaC::ex_is_less> info_;
};

// Maps each jet coordinate x_i^(k), k >= 2, to a truncated series on the
// 1-jet (x, x') -- derivatives of the modified equation x'' = f(x, x'; h).
class Reduction {
 public:
  // Builds x^(2) = f and x^(k+1) = D_f x^(k); x^(k) is kept to order
  // kept[k] (k >= 2; see RequireOrders), at most f's order.
  Reduction(JetSpace& jet, const std::vector<Series>& f, std::vector<int> kept);

  int order() const { return order_; }
  // x_i^(k) as a series (x_i, x'_i for k < 2).
  const Series& Of(int i, int k) const { return x_[k][i]; }
  int max_k() const { return static_cast<int>(x_.size()) - 1; }

  // Replaces every x^(k), k >= 2, in e by its series, term by term, truncated
  // at `order`. Jet coordinates above max_k() are an error.
  Series Substitute(const GiNaC::ex& e, int order);
  // Total derivative along the modified vector field (x', f) of a series on
  // the 1-jet.
  Series Derivative(const Series& g, int order);

 private:
  const Series& Power(int i, int k, int n);

  JetSpace& jet_;
  int order_;
  std::vector<Series> f_;
  std::vector<int> kept_;
  std::vector<std::vector<Series>> x_;  // x_[k][i]
  std::map<std::tuple<int, int, int>, Series> powers_;
};

// sum_p h^p reduce(c_p): a jet polynomial series reduced to the 1-jet, each
// c_p substituted to order - p.
Series ReduceSeries(Reduction& red, const std::vector<GiNaC::ex>& c, int order);

// Records in kept[k] that x^(k) (k >= 2) must be known to order `order`
// wherever it occurs in e. Only what the expressions actually contain is
// built: expanded Euler-Lagrange expressions of an order-p Lagrangian reach
// x^(p+2), far below the 2p+2 their derivation passes through.
void RequireOrders(const JetSpace& jet, const GiNaC::ex& e, int order,
                   std::vector<int>& kept);

}  // namespace vivp::bea
