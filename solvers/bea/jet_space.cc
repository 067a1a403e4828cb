#include "solvers/bea/jet_space.h"

#include <stdexcept>

namespace vivp::bea {
namespace {

std::string MultiName(const std::vector<int>& a) {
  std::string s;
  for (int ai : a) s += std::to_string(ai);
  return s;
}

// Symbols occurring in e.
std::vector<GiNaC::symbol> SymbolsOf(const GiNaC::ex& e) {
  GiNaC::exset seen;
  std::vector<GiNaC::symbol> out;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (GiNaC::is_a<GiNaC::symbol>(*it) && seen.insert(*it).second)
      out.push_back(GiNaC::ex_to<GiNaC::symbol>(*it));
  return out;
}

}  // namespace

JetSpace::JetSpace(int dim, PotentialModel model) : dim_(dim), model_(model) {
  if (dim < 1) throw std::invalid_argument("dimension must be at least 1");
  if (model == PotentialModel::kRadial && dim < 2)
    throw std::invalid_argument(
        "the radial potential model needs dimension >= 2 (use the generic "
        "model in d = 1)");
}

GiNaC::symbol JetSpace::X(int i, int k) {
  auto it = jet_.find({i, k});
  if (it != jet_.end()) return it->second;
  const std::string n = std::to_string(i + 1);
  std::string name, tex;
  if (k == 0) {
    name = "x" + n;
    tex = "x_{" + n + "}";
  } else if (k == 1) {
    name = "v" + n;
    tex = "\\dot x_{" + n + "}";
  } else {
    name = "x" + n + "_" + std::to_string(k);
    tex = "x_{" + n + "}^{(" + std::to_string(k) + ")}";
  }
  GiNaC::symbol s(name, tex);
  jet_.emplace(std::make_pair(i, k), s);
  info_[s] = SymbolInfo{SymbolInfo::kJet, i, k, {}};
  return s;
}

GiNaC::ex JetSpace::Potential() {
  if (model_ == PotentialModel::kRadial) return V(0) / 2;
  return U(std::vector<int>(dim_, 0));
}

GiNaC::symbol JetSpace::U(const std::vector<int>& a) {
  if (model_ != PotentialModel::kGeneric)
    throw std::logic_error("U_a symbols belong to the generic potential model");
  auto it = generic_.find(a);
  if (it != generic_.end()) return it->second;
  int order = 0;
  for (int ai : a) order += ai;
  std::string name = "U", tex = "U";
  if (order > 0) {
    name += '_';
    name += MultiName(a);
    tex += "_{";
    for (int i = 0; i < dim_; ++i)
      for (int r = 0; r < a[i]; ++r) tex += std::to_string(i + 1);
    tex += "}";
  }
  GiNaC::symbol s(name, tex);
  generic_.emplace(a, s);
  info_[s] = SymbolInfo{SymbolInfo::kGenericPotential, 0, order, a};
  return s;
}

GiNaC::symbol JetSpace::V(int k) {
  if (model_ != PotentialModel::kRadial)
    throw std::logic_error("V_k symbols belong to the radial potential model");
  auto it = radial_.find(k);
  if (it != radial_.end()) return it->second;
  // Built by appending: GCC 12 reports a false -Wrestrict for
  // "literal" + std::string here (GCC bug 105329).
  std::string name = "V", tex = "V";
  name += std::to_string(k);
  if (k > 0) {
    tex += "^{(";
    tex += std::to_string(k);
    tex += ")}";
  }
  GiNaC::symbol s(name, tex);
  radial_.emplace(k, s);
  info_[s] = SymbolInfo{SymbolInfo::kRadialPotential, 0, k, {}};
  return s;
}

std::optional<JetSpace::SymbolInfo> JetSpace::Info(
    const GiNaC::symbol& s) const {
  auto it = info_.find(s);
  if (it == info_.end()) return std::nullopt;
  return it->second;
}

GiNaC::ex JetSpace::PotentialPartial(const SymbolInfo& info, int i) {
  if (info.kind == SymbolInfo::kGenericPotential) {
    auto a = info.multi;
    ++a[i];
    return U(a);
  }
  return 2 * X(i, 0) * V(info.derivative + 1);
}

GiNaC::ex JetSpace::Partial(const GiNaC::ex& e, int i, int k) {
  GiNaC::ex out = e.diff(X(i, k));
  if (k == 0) {
    for (const auto& s : SymbolsOf(e)) {
      auto info = Info(s);
      if (info && info->kind != SymbolInfo::kJet)
        out += e.diff(s) * PotentialPartial(*info, i);
    }
  }
  return GiNaC::expand(out);
}

GiNaC::ex JetSpace::TotalDerivative(const GiNaC::ex& e) {
  GiNaC::ex out = 0;
  for (const auto& s : SymbolsOf(e)) {
    auto info = Info(s);
    if (!info) continue;
    const GiNaC::ex ds = e.diff(s);
    if (info->kind == SymbolInfo::kJet) {
      out += ds * X(info->component, info->derivative + 1);
    } else {
      GiNaC::ex chain = 0;
      for (int i = 0; i < dim_; ++i)
        chain += PotentialPartial(*info, i) * X(i, 1);
      out += ds * chain;
    }
  }
  return GiNaC::expand(out);
}

int JetSpace::JetOrder(const GiNaC::ex& e) const {
  int order = -1;
  for (const auto& s : SymbolsOf(e)) {
    auto info = Info(s);
    if (info && info->kind == SymbolInfo::kJet)
      order = std::max(order, info->derivative);
  }
  return order;
}

int JetSpace::PotentialOrder(const GiNaC::ex& e) const {
  int order = -1;
  for (const auto& s : SymbolsOf(e)) {
    auto info = Info(s);
    if (info && info->kind != SymbolInfo::kJet)
      order = std::max(order, info->derivative);
  }
  return order;
}

void RequireOrders(const JetSpace& jet, const GiNaC::ex& e, int order,
                   std::vector<int>& kept) {
  for (const auto& s : SymbolsOf(e)) {
    auto info = jet.Info(s);
    if (!info || info->kind != JetSpace::SymbolInfo::kJet ||
        info->derivative < 2)
      continue;
    const int k = info->derivative;
    if (static_cast<int>(kept.size()) <= k) kept.resize(k + 1, -1);
    kept[k] = std::max(kept[k], order);
  }
}

Reduction::Reduction(JetSpace& jet, const std::vector<Series>& f,
                     std::vector<int> kept)
    : jet_(jet), order_(f.at(0).order()), f_(f), kept_(std::move(kept)) {
  const int d = jet.dim();
  // x^(k) = D_f x^(k-1) needs x^(k-1) to the same order.
  if (kept_.size() < 3) kept_.resize(3, -1);
  for (int k = static_cast<int>(kept_.size()) - 1; k > 2; --k)
    kept_[k - 1] = std::max(kept_[k - 1], kept_[k]);
  for (auto& o : kept_) o = std::min(o, order_);
  kept_[2] = order_;
  x_.resize(kept_.size());
  for (int i = 0; i < d; ++i) {
    x_[0].emplace_back(order_, jet.X(i, 0));
    x_[1].emplace_back(order_, jet.X(i, 1));
    x_[2].push_back(f[i]);
  }
  for (int k = 3; k < static_cast<int>(kept_.size()); ++k)
    for (int i = 0; i < d; ++i)
      x_[k].push_back(
          kept_[k] < 0
              ? Series(0)
              : Derivative(x_[k - 1][i].Truncated(kept_[k]), kept_[k]));
}

Series Reduction::Derivative(const Series& g, int order) {
  const int d = jet_.dim();
  Series out(order);
  for (int q = 0; q <= std::min(order, g.order()); ++q) {
    if (g[q].is_zero()) continue;
    GiNaC::ex pos = 0;
    for (int i = 0; i < d; ++i) pos += jet_.Partial(g[q], i, 0) * jet_.X(i, 1);
    out[q] += pos;
    for (int i = 0; i < d; ++i) {
      const GiNaC::ex dv = jet_.Partial(g[q], i, 1);
      if (dv.is_zero()) continue;
      for (int r = 0; q + r <= order && r <= f_[i].order(); ++r)
        if (!f_[i][r].is_zero()) out[q + r] += dv * f_[i][r];
    }
  }
  for (int q = 0; q <= order; ++q) out[q] = GiNaC::expand(out[q]);
  return out;
}

const Series& Reduction::Power(int i, int k, int n) {
  auto key = std::make_tuple(i, k, n);
  auto it = powers_.find(key);
  if (it != powers_.end()) return it->second;
  Series p = n == 1 ? x_[k][i] : Power(i, k, n - 1) * x_[k][i];
  return powers_.emplace(key, std::move(p)).first->second;
}

Series Reduction::Substitute(const GiNaC::ex& e, int order) {
  Series out(order);
  if (order < 0) return out;
  const GiNaC::ex ee = GiNaC::expand(e);
  auto term_of = [&](const GiNaC::ex& term) {
    GiNaC::ex scalar = 1;
    std::vector<const Series*> factors;
    auto factor_of = [&](const GiNaC::ex& f) {
      GiNaC::ex base = f;
      int n = 1;
      if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) &&
          GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_pos_integer()) {
        base = f.op(0);
        n = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int();
      }
      if (GiNaC::is_a<GiNaC::symbol>(base)) {
        auto info = jet_.Info(GiNaC::ex_to<GiNaC::symbol>(base));
        if (info && info->kind == JetSpace::SymbolInfo::kJet &&
            info->derivative >= 2) {
          if (info->derivative > max_k())
            throw std::logic_error("Reduction: x^(" +
                                   std::to_string(info->derivative) +
                                   ") beyond the reduction's jet order");
          if (kept_[info->derivative] < order)
            throw std::logic_error("Reduction: substitution needs x^(" +
                                   std::to_string(info->derivative) +
                                   ") beyond its kept order");
          factors.push_back(&Power(info->component, info->derivative, n));
          return;
        }
      }
      scalar *= f;
    };
    if (GiNaC::is_a<GiNaC::mul>(term))
      for (std::size_t j = 0; j < term.nops(); ++j) factor_of(term.op(j));
    else
      factor_of(term);
    Series prod(order, scalar);
    for (const Series* f : factors) prod = prod * f->Truncated(order);
    for (int p = 0; p <= order; ++p) out[p] += prod[p];
  };
  if (GiNaC::is_a<GiNaC::add>(ee))
    for (std::size_t j = 0; j < ee.nops(); ++j) term_of(ee.op(j));
  else if (!ee.is_zero())
    term_of(ee);
  for (int p = 0; p <= order; ++p) out[p] = GiNaC::expand(out[p]);
  return out;
}

Series ReduceSeries(Reduction& red, const std::vector<GiNaC::ex>& c,
                    int order) {
  Series out(order);
  for (int p = 0; p < static_cast<int>(c.size()) && p <= order; ++p)
    if (!c[p].is_zero()) AddShifted(out, red.Substitute(c[p], order - p), p);
  return out;
}

}  // namespace vivp::bea
