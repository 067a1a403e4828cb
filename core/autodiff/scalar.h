// Scalar-type plumbing shared by everything that is templated on the scalar:
// double, long double, ceres::Jet and Jets nested to any depth.
//
//   RealOf<T>           the floating-point type at the bottom of T
//   Lift<T>(c)          the constant c as a T (zero derivative parts)
//   AddScaled(acc,c,x)  acc += c * x for a real coefficient c
//   ValueOf(x)          the real value of x, derivative parts dropped
//
// Why not just `c * x`: ceres defines Jet<U,N> * U but not Jet<Jet<U,N>,M> * U,
// so a real constant never meets a nested Jet directly; AddScaled also avoids
// building a temporary Jet for every stencil coefficient.
#pragma once

#include <ceres/jet.h>

#include <type_traits>

namespace vivp::autodiff {

template <class T>
struct RealOfImpl {
  using type = T;
};
template <class U, int N>
struct RealOfImpl<ceres::Jet<U, N>> {
  using type = typename RealOfImpl<U>::type;
};
template <class T>
using RealOf = typename RealOfImpl<T>::type;

template <class T>
struct IsJet : std::false_type {};
template <class U, int N>
struct IsJet<ceres::Jet<U, N>> : std::true_type {};

template <class T>
T Lift(RealOf<T> c) {
  if constexpr (IsJet<T>::value) {
    using Inner = decltype(T{}.a);
    return T(Lift<Inner>(c));
  } else {
    return c;
  }
}

template <class T>
void AddScaled(T& acc, RealOf<T> c, const T& x) {
  if constexpr (IsJet<T>::value) {
    AddScaled(acc.a, c, x.a);
    for (int k = 0; k < acc.v.size(); ++k) AddScaled(acc.v[k], c, x.v[k]);
  } else {
    acc += c * x;
  }
}

template <class T>
T Scaled(RealOf<T> c, const T& x) {
  if constexpr (IsJet<T>::value) {
    T out;
    out.a = Scaled(c, x.a);
    for (int k = 0; k < out.v.size(); ++k) out.v[k] = Scaled(c, x.v[k]);
    return out;
  } else {
    return c * x;
  }
}

template <class T>
RealOf<T> ValueOf(const T& x) {
  if constexpr (IsJet<T>::value) {
    return ValueOf(x.a);
  } else {
    return x;
  }
}

}  // namespace vivp::autodiff
