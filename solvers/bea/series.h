// Truncated power series in the step size h with GiNaC coefficients.
//
// Backward error analysis works order by order in h, so every quantity is a
// list c[0], c[1], ..., c[N] of polynomial coefficients (of h^0 ... h^N) and
// products are truncated at N. GiNaC's own series() is not used: at h^10 it
// needs minutes and gigabytes, while truncated coefficient lists stay
// polynomial and cheap.
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace vivp::bea {

class Series {
 public:
  Series() = default;
  // Zero series truncated at order `order` (coefficients of h^0..h^order).
  explicit Series(int order) : c_(order + 1, GiNaC::ex(0)) {}
  // The constant `value` (an h^0 term) truncated at `order`.
  Series(int order, const GiNaC::ex& value) : Series(order) { c_[0] = value; }

  int order() const { return static_cast<int>(c_.size()) - 1; }
  const GiNaC::ex& operator[](int p) const { return c_[p]; }
  GiNaC::ex& operator[](int p) { return c_[p]; }

  // The same series cut (or zero-padded) to `order`.
  Series Truncated(int order) const;
  // Sum of h^p c[p] as one expression in the symbol h (for printing).
  GiNaC::ex ToEx(const GiNaC::symbol& h) const;
  // True if every coefficient expands to zero.
  bool IsZero() const;

  Series& operator+=(const Series& other);
  Series& operator-=(const Series& other);
  Series& operator*=(const GiNaC::ex& scalar);

 private:
  std::vector<GiNaC::ex> c_;
};

Series operator+(Series a, const Series& b);
Series operator-(Series a, const Series& b);
Series operator*(Series a, const GiNaC::ex& scalar);
// Product truncated at min(a.order(), b.order()); each coefficient expanded.
Series operator*(const Series& a, const Series& b);
// h^shift * a, truncated at a.order().
Series ShiftUp(const Series& a, int shift);
// out += h^shift * s (s truncated so that the sum stays at out.order()).
void AddShifted(Series& out, const Series& s, int shift);
// Applies `op` (a linear map on polynomials, e.g. a partial derivative) to
// every coefficient.
template <class Op>
Series Map(const Series& a, Op&& op) {
  Series out(a.order());
  for (int p = 0; p <= a.order(); ++p)
    if (!a[p].is_zero()) out[p] = op(a[p]);
  return out;
}

}  // namespace vivp::bea
