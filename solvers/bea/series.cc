#include "solvers/bea/series.h"

#include <algorithm>

namespace vivp::bea {

Series Series::Truncated(int order) const {
  Series out(order);
  for (int p = 0; p <= std::min(order, this->order()); ++p) out[p] = c_[p];
  return out;
}

GiNaC::ex Series::ToEx(const GiNaC::symbol& h) const {
  GiNaC::ex sum = 0;
  for (int p = 0; p <= order(); ++p) sum += c_[p] * GiNaC::pow(h, p);
  return sum;
}

bool Series::IsZero() const {
  return std::all_of(c_.begin(), c_.end(), [](const GiNaC::ex& e) {
    return GiNaC::expand(e).is_zero();
  });
}

Series& Series::operator+=(const Series& other) {
  for (int p = 0; p <= std::min(order(), other.order()); ++p)
    if (!other[p].is_zero()) c_[p] = GiNaC::expand(c_[p] + other[p]);
  return *this;
}

Series& Series::operator-=(const Series& other) {
  for (int p = 0; p <= std::min(order(), other.order()); ++p)
    if (!other[p].is_zero()) c_[p] = GiNaC::expand(c_[p] - other[p]);
  return *this;
}

Series& Series::operator*=(const GiNaC::ex& scalar) {
  for (auto& c : c_)
    if (!c.is_zero()) c = GiNaC::expand(c * scalar);
  return *this;
}

Series operator+(Series a, const Series& b) { return a += b; }
Series operator-(Series a, const Series& b) { return a -= b; }
Series operator*(Series a, const GiNaC::ex& scalar) { return a *= scalar; }

Series operator*(const Series& a, const Series& b) {
  const int n = std::min(a.order(), b.order());
  Series out(n);
  for (int p = 0; p <= n; ++p) {
    if (a[p].is_zero()) continue;
    for (int q = 0; p + q <= n; ++q) {
      if (b[q].is_zero()) continue;
      out[p + q] += GiNaC::expand(a[p] * b[q]);
    }
  }
  for (int p = 0; p <= n; ++p) out[p] = GiNaC::expand(out[p]);
  return out;
}

Series ShiftUp(const Series& a, int shift) {
  Series out(a.order());
  for (int p = 0; p + shift <= a.order(); ++p) out[p + shift] = a[p];
  return out;
}

void AddShifted(Series& out, const Series& s, int shift) {
  for (int p = 0; p + shift <= out.order() && p <= s.order(); ++p)
    if (!s[p].is_zero()) out[p + shift] = GiNaC::expand(out[p + shift] + s[p]);
}

}  // namespace vivp::bea
