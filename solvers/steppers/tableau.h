// Butcher tableaus (A, b, c) for the Runge–Kutta engine. Gauss–Legendre
// coefficients are from Hairer, Lubich & Wanner, Table II.1.1 and
// docs/steppers.md §1 (s = 2: a₁₂ = ¼ − √3/6, c = ½ ∓ √3/6).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <string>

namespace vivp::steppers {

struct Tableau {
  std::string name;
  int order = 0;
  Eigen::MatrixXd a;
  Eigen::VectorXd b, c;

  int stages() const { return static_cast<int>(b.size()); }
  // Strictly lower triangular A: stages in order, no solve.
  bool explicit_method() const {
    for (int i = 0; i < stages(); ++i)
      for (int j = i; j < stages(); ++j)
        if (a(i, j) != 0) return false;
    return true;
  }
};

inline Tableau ClassicalRk4() {
  Tableau t{"rk4", 4, Eigen::MatrixXd::Zero(4, 4), Eigen::VectorXd(4),
            Eigen::VectorXd(4)};
  t.a(1, 0) = 0.5;
  t.a(2, 1) = 0.5;
  t.a(3, 2) = 1.0;
  t.b << 1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6;
  t.c << 0, 0.5, 0.5, 1;
  return t;
}

// Implicit midpoint: the one-stage Gauss method.
inline Tableau ImplicitMidpoint() {
  Tableau t{"midpoint", 2, Eigen::MatrixXd::Constant(1, 1, 0.5),
            Eigen::VectorXd::Ones(1), Eigen::VectorXd::Constant(1, 0.5)};
  return t;
}

inline Tableau Gauss2() {
  const double r = std::sqrt(3.0) / 6;
  Tableau t{"gauss2", 4, Eigen::MatrixXd(2, 2), Eigen::VectorXd(2),
            Eigen::VectorXd(2)};
  t.a << 0.25, 0.25 - r, 0.25 + r, 0.25;
  t.b << 0.5, 0.5;
  t.c << 0.5 - r, 0.5 + r;
  return t;
}

inline Tableau Gauss3() {
  const double r = std::sqrt(15.0);
  Tableau t{"gauss3", 6, Eigen::MatrixXd(3, 3), Eigen::VectorXd(3),
            Eigen::VectorXd(3)};
  t.a << 5.0 / 36, 2.0 / 9 - r / 15, 5.0 / 36 - r / 30,  //
      5.0 / 36 + r / 24, 2.0 / 9, 5.0 / 36 - r / 24,     //
      5.0 / 36 + r / 30, 2.0 / 9 + r / 15, 5.0 / 36;
  t.b << 5.0 / 18, 4.0 / 9, 5.0 / 18;
  t.c << 0.5 - r / 10, 0.5, 0.5 + r / 10;
  return t;
}

}  // namespace vivp::steppers
