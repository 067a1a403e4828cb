// The methods whose backward error analysis the engine computes, as data:
// each one is a discrete Lagrangian (expanded in h by lagrangians.h).
//
//   kStormerVerlet  L_h = |x(t+h) - x(t)|^2 / (2h^2) + (U(x(t)) + U(x(t+h)))/2
//                   (McLachlan & Offen 2023, Appendix A, with U = -W);
//   kMultistep      eq. (2.6): L_h = (1/2h^2) sum_j (x(t+jh) - x(t))^T A_j
//                   (x(t+jh) - x(t)) + U(x(t)), whose discrete Euler-Lagrange
//                   equations are the symmetric LMM (2.2)
//                   sum_j A_j (x_{n+j} - 2x_n + x_{n-j}) = h^2 grad U(x_n);
//   kMidpoint       L_h = |x(t+h) - x(t)|^2 / (2h^2) + U((x(t) + x(t+h))/2).
//
// MakeMultistep checks the coefficients (symmetric, consistency (2.3)
// sum_j j^2 A_j = I) and throws std::invalid_argument naming the violation.
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace vivp::bea {

enum class MethodKind { kStormerVerlet, kMultistep, kMidpoint };

struct Method {
  MethodKind kind = MethodKind::kStormerVerlet;
  std::string name = "sv";
  int dim = 1;
  // kMultistep: A_1, ..., A_k (d x d, symmetric). Entries may be symbols.
  std::vector<GiNaC::matrix> A;
};

Method MakeStormerVerlet(int dim);
Method MakeMidpoint(int dim);
// Checked: every A_j is dim x dim and symmetric, and sum j^2 A_j = I.
Method MakeMultistep(std::vector<GiNaC::matrix> A, std::string name = "lmm");
// Example (4.1): 1/4 (I - A)(x_{n+2} - 2x_n + x_{n-2}) + A (x_{n+1} - 2x_n +
// x_{n-1}) = h^2 grad U(x_n), i.e. A_1 = A, A_2 = (I - A)/4.
Method MakeLmm4(const GiNaC::matrix& A);
// A = alpha I in dimension dim.
GiNaC::matrix ScalarMatrix(const GiNaC::ex& alpha, int dim);
// A = [[a11, a12], [a12, a22]].
GiNaC::matrix SymmetricMatrix2(const GiNaC::ex& a11, const GiNaC::ex& a12,
                               const GiNaC::ex& a22);

}  // namespace vivp::bea
