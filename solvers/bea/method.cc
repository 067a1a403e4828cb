#include "solvers/bea/method.h"

#include <sstream>
#include <stdexcept>

namespace vivp::bea {

Method MakeStormerVerlet(int dim) {
  if (dim < 1) throw std::invalid_argument("dimension must be at least 1");
  return {MethodKind::kStormerVerlet, "sv", dim, {}};
}

Method MakeMidpoint(int dim) {
  if (dim < 1) throw std::invalid_argument("dimension must be at least 1");
  return {MethodKind::kMidpoint, "midpoint", dim, {}};
}

Method MakeMultistep(std::vector<GiNaC::matrix> A, std::string name) {
  if (A.empty())
    throw std::invalid_argument(
        "a multistep method needs coefficients A_1..A_k");
  const unsigned d = A[0].rows();
  GiNaC::matrix sum(d, d);
  for (std::size_t j = 0; j < A.size(); ++j) {
    const auto& a = A[j];
    if (a.rows() != d || a.cols() != d)
      throw std::invalid_argument("coefficient A_" + std::to_string(j + 1) +
                                  " is not " + std::to_string(d) + "x" +
                                  std::to_string(d));
    for (unsigned r = 0; r < d; ++r)
      for (unsigned c = r + 1; c < d; ++c)
        if (!GiNaC::expand(a(r, c) - a(c, r)).is_zero()) {
          std::ostringstream msg;
          msg << "coefficient matrix A_" << j + 1
              << " is not symmetric (entry (" << r + 1 << "," << c + 1
              << ") = " << a(r, c) << " but (" << c + 1 << "," << r + 1
              << ") = " << a(c, r)
              << "); the variational structure (2.6) needs symmetric A_j";
          throw std::invalid_argument(msg.str());
        }
    sum = sum.add(a.mul_scalar(GiNaC::numeric((j + 1) * (j + 1))));
  }
  for (unsigned r = 0; r < d; ++r)
    for (unsigned c = 0; c < d; ++c)
      if (!GiNaC::expand(sum(r, c) - (r == c ? 1 : 0)).is_zero()) {
        std::ostringstream msg;
        msg << "coefficients violate consistency (2.3): sum_j j^2 A_j has "
               "entry ("
            << r + 1 << "," << c + 1 << ") = " << GiNaC::expand(sum(r, c))
            << ", expected " << (r == c ? 1 : 0)
            << "; rescale the coefficients so that sum_j j^2 A_j = I";
        throw std::invalid_argument(msg.str());
      }
  return {MethodKind::kMultistep, std::move(name), static_cast<int>(d),
          std::move(A)};
}

GiNaC::matrix ScalarMatrix(const GiNaC::ex& alpha, int dim) {
  GiNaC::matrix a(dim, dim);
  for (int i = 0; i < dim; ++i) a(i, i) = alpha;
  return a;
}

GiNaC::matrix SymmetricMatrix2(const GiNaC::ex& a11, const GiNaC::ex& a12,
                               const GiNaC::ex& a22) {
  GiNaC::matrix a(2, 2);
  a(0, 0) = a11;
  a(0, 1) = a(1, 0) = a12;
  a(1, 1) = a22;
  return a;
}

Method MakeLmm4(const GiNaC::matrix& A) {
  const int d = static_cast<int>(A.rows());
  if (A.cols() != A.rows())
    throw std::invalid_argument("the coefficient matrix A must be square");
  const GiNaC::matrix identity = ScalarMatrix(1, d);
  const GiNaC::matrix a2 = identity.sub(A).mul_scalar(GiNaC::numeric(1, 4));
  return MakeMultistep({A, a2}, "lmm4");
}

}  // namespace vivp::bea
