#include "solvers/bea/evaluator.h"

#include <map>
#include <sstream>
#include <stdexcept>

namespace vivp::bea {

CompiledPolynomial::CompiledPolynomial(const GiNaC::ex& e,
                                       const std::vector<GiNaC::symbol>& vars) {
  std::map<GiNaC::ex, int, GiNaC::ex_is_less> index;
  for (std::size_t i = 0; i < vars.size(); ++i)
    index[vars[i]] = static_cast<int>(i);
  const GiNaC::ex ee = GiNaC::expand(e);
  auto monomial = [&](const GiNaC::ex& term) {
    double coeff = 1;
    start_.push_back(static_cast<int>(factors_.size()));
    auto factor = [&](const GiNaC::ex& f) {
      if (GiNaC::is_a<GiNaC::numeric>(f)) {
        const auto& n = GiNaC::ex_to<GiNaC::numeric>(f);
        if (!n.is_rational())
          throw std::invalid_argument("non-rational coefficient in polynomial");
        coeff *= n.to_double();
        return;
      }
      GiNaC::ex base = f;
      int power = 1;
      if (GiNaC::is_a<GiNaC::power>(f)) {
        const auto& n = GiNaC::ex_to<GiNaC::numeric>(f.op(1));
        if (!GiNaC::is_a<GiNaC::numeric>(f.op(1)) || !n.is_pos_integer())
          throw std::invalid_argument("not a polynomial (negative power)");
        base = f.op(0);
        power = n.to_int();
      }
      auto it = index.find(base);
      if (it == index.end()) {
        std::ostringstream msg;
        msg << "symbol " << base
            << " has no numerical value (give every parameter a number)";
        throw std::invalid_argument(msg.str());
      }
      factors_.emplace_back(it->second, power);
      max_exponent_ = std::max(max_exponent_, power);
    };
    if (GiNaC::is_a<GiNaC::mul>(term))
      for (std::size_t j = 0; j < term.nops(); ++j) factor(term.op(j));
    else
      factor(term);
    coeff_.push_back(coeff);
  };
  if (GiNaC::is_a<GiNaC::add>(ee))
    for (std::size_t j = 0; j < ee.nops(); ++j) monomial(ee.op(j));
  else if (!ee.is_zero())
    monomial(ee);
  start_.push_back(static_cast<int>(factors_.size()));
}

double CompiledPolynomial::Evaluate(const double* powers, int stride) const {
  double sum = 0;
  for (std::size_t m = 0; m < coeff_.size(); ++m) {
    double t = coeff_[m];
    for (int f = start_[m]; f < start_[m + 1]; ++f)
      t *= powers[factors_[f].first * stride + factors_[f].second];
    sum += t;
  }
  return sum;
}

ModifiedQuantities::ModifiedQuantities(const BeaResult& r,
                                       const NumericPotential& potential,
                                       const GiNaC::exmap& parameters)
    : order_(r.order), dim_(r.jet->dim()), potential_(potential) {
  if (potential.dim() != dim_ || potential.model() != r.jet->model())
    throw std::invalid_argument(
        "the numerical potential '" + potential.name() +
        "' does not match the derivation's dimension or potential model");
  std::vector<GiNaC::ex> all;
  auto subs = [&](const GiNaC::ex& e) {
    return parameters.empty() ? e : GiNaC::expand(e.subs(parameters));
  };
  const int n2 = 2 * dim_;
  const bool with_omega = static_cast<int>(r.omega.size()) == n2;
  // L_mod is compiled only if it is a polynomial in the variables below;
  // otherwise Lagrangian() reports why.
  const bool with_lagrangian = r.modified_lagrangian.has_value();
  if (!with_lagrangian)
    no_lagrangian_ = "the derivation has no first-order modified Lagrangian";
  for (int p = 0; p <= order_; ++p) {
    all.push_back(subs(r.hamiltonian[p]));
    if (r.charge) all.push_back(subs((*r.charge)[p]));
    for (int i = 0; i < dim_; ++i) all.push_back(subs(r.f[i][p]));
    if (with_omega)
      for (int i = 0; i < n2; ++i)
        for (int j = 0; j < n2; ++j) all.push_back(subs(r.omega[i][j][p]));
    if (with_lagrangian) all.push_back(subs((*r.modified_lagrangian)[p]));
  }
  for (int i = 0; i < dim_; ++i) vars_.push_back(r.jet->X(i, 0));
  for (int i = 0; i < dim_; ++i) vars_.push_back(r.jet->X(i, 1));
  GiNaC::exset seen;
  for (const auto& e : all)
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
      if (!GiNaC::is_a<GiNaC::symbol>(*it) || !seen.insert(*it).second)
        continue;
      const auto& s = GiNaC::ex_to<GiNaC::symbol>(*it);
      auto info = r.jet->Info(s);
      if (!info || info->kind == JetSpace::SymbolInfo::kJet) continue;
      vars_.push_back(s);
      potential_index_.push_back(info->kind ==
                                         JetSpace::SymbolInfo::kGenericPotential
                                     ? info->multi
                                     : std::vector<int>{info->derivative});
    }
  int k = 0;
  auto compile = [&](std::vector<CompiledPolynomial>& out) {
    out.emplace_back(all[k++], vars_);
    stride_ = std::max(stride_, out.back().max_exponent() + 1);
  };
  f_.resize(dim_);
  if (with_omega) omega_.resize(n2 * n2);
  for (int p = 0; p <= order_; ++p) {
    compile(hamiltonian_);
    if (r.charge) compile(charge_);
    for (int i = 0; i < dim_; ++i) compile(f_[i]);
    for (auto& w : omega_) compile(w);
    if (with_lagrangian) {
      // no_lagrangian_ is set once a term failed to compile: skip the rest.
      if (!no_lagrangian_.empty()) {
        ++k;  // this order's L_mod term, not compiled
        continue;
      }
      try {
        compile(lagrangian_);  // consumes all[k] even when it throws
      } catch (const std::invalid_argument& e) {
        lagrangian_.clear();
        no_lagrangian_ = std::string("L_mod is not a polynomial: ") + e.what();
      }
    }
  }
  powers_.resize(vars_.size() * stride_);
}

void ModifiedQuantities::Powers(const double* x, const double* v) const {
  const int n = static_cast<int>(vars_.size());
  for (int j = 0; j < n; ++j) {
    double value;
    if (j < dim_)
      value = x[j];
    else if (j < 2 * dim_)
      value = v[j - dim_];
    else
      value = potential_.Derivative(potential_index_[j - 2 * dim_], x);
    double* p = &powers_[j * stride_];
    p[0] = 1;
    for (int e = 1; e < stride_; ++e) p[e] = p[e - 1] * value;
  }
}

double ModifiedQuantities::Sum(const std::vector<CompiledPolynomial>& c, int k,
                               double h, const double* x,
                               const double* v) const {
  if (k > order_ || k < 0)
    throw std::invalid_argument("truncation order beyond the derivation");
  Powers(x, v);
  double sum = 0, hp = 1;
  for (int p = 0; p <= k; ++p, hp *= h)
    sum += hp * c[p].Evaluate(powers_.data(), stride_);
  return sum;
}

double ModifiedQuantities::Hamiltonian(int k, double h, const double* x,
                                       const double* v) const {
  return Sum(hamiltonian_, k, h, x, v);
}

double ModifiedQuantities::Charge(int k, double h, const double* x,
                                  const double* v) const {
  if (charge_.empty())
    throw std::logic_error("the derivation computed no Noether charge");
  return Sum(charge_, k, h, x, v);
}

void ModifiedQuantities::Acceleration(int k, double h, const double* x,
                                      const double* v, double* a) const {
  for (int i = 0; i < dim_; ++i) a[i] = Sum(f_[i], k, h, x, v);
}

void ModifiedQuantities::SymplecticForm(int k, double h, const double* x,
                                        const double* v, double* omega) const {
  if (omega_.empty())
    throw std::logic_error("the derivation computed no symplectic form");
  for (std::size_t e = 0; e < omega_.size(); ++e)
    omega[e] = Sum(omega_[e], k, h, x, v);
}

double ModifiedQuantities::Lagrangian(int k, double h, const double* x,
                                      const double* v) const {
  if (lagrangian_.empty()) throw std::logic_error(no_lagrangian_);
  return Sum(lagrangian_, k, h, x, v);
}

}  // namespace vivp::bea
