// Concrete potentials for numerical evaluation: the values of the symbols a
// symbolic result contains (U_a = d^a U for the generic model, V_k = V^(k)(r)
// for the radial one) and grad U for the stepper. U is minus the potential
// energy (x'' = grad U).
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "solvers/bea/jet_space.h"

namespace vivp::bea {

class NumericPotential {
 public:
  virtual ~NumericPotential() = default;
  virtual std::string name() const = 0;
  virtual int dim() const = 0;
  virtual PotentialModel model() const = 0;
  // Generic model: d^a U(x) for the multi-index a (size dim). Radial model:
  // V^(a[0])(|x|^2).
  virtual double Derivative(const std::vector<int>& a,
                            const double* x) const = 0;
  virtual void Gradient(const double* x, double* g) const = 0;
};

// Pendulum in the convention of McLachlan & Offen 2023 (docs/bea.md §1):
// U(x) = cos x (W = -cos x, x'' = -sin x).
class Pendulum : public NumericPotential {
 public:
  std::string name() const override { return "pendulum"; }
  int dim() const override { return 1; }
  PotentialModel model() const override { return PotentialModel::kGeneric; }
  double Derivative(const std::vector<int>& a, const double* x) const override {
    // d^k cos x = cos(x + k pi/2).
    switch (a[0] % 4) {
      case 0:
        return std::cos(x[0]);
      case 1:
        return -std::sin(x[0]);
      case 2:
        return -std::cos(x[0]);
      default:
        return std::sin(x[0]);
    }
  }
  void Gradient(const double* x, double* g) const override {
    g[0] = -std::sin(x[0]);
  }
};

// U(x) = exp(-|x|^2/2) (McLachlan & Offen 2023, Figs. 1-2) in the generic
// model: d^a U = prod_i (-1)^{a_i} He_{a_i}(x_i) exp(-|x|^2/2), He the
// probabilists' Hermite polynomials.
class Gaussian : public NumericPotential {
 public:
  explicit Gaussian(int dim) : dim_(dim) {}
  std::string name() const override { return "gaussian"; }
  int dim() const override { return dim_; }
  PotentialModel model() const override { return PotentialModel::kGeneric; }
  double Derivative(const std::vector<int>& a, const double* x) const override {
    double r = 0, prod = 1;
    for (int i = 0; i < dim_; ++i) {
      r += x[i] * x[i];
      // He_{n+1} = x He_n - n He_{n-1}.
      double he0 = 1, he1 = x[i];
      for (int n = 1; n < a[i]; ++n) {
        const double he2 = x[i] * he1 - n * he0;
        he0 = he1;
        he1 = he2;
      }
      prod *= (a[i] == 0 ? 1.0 : he1) * (a[i] % 2 ? -1.0 : 1.0);
    }
    return prod * std::exp(-r / 2);
  }
  void Gradient(const double* x, double* g) const override {
    double r = 0;
    for (int i = 0; i < dim_; ++i) r += x[i] * x[i];
    const double e = std::exp(-r / 2);
    for (int i = 0; i < dim_; ++i) g[i] = -x[i] * e;
  }

 private:
  int dim_;
};

// The same U = exp(-|x|^2/2) = V(|x|^2)/2 in the radial model:
// V(r) = 2 exp(-r/2), V^(k) = 2 (-1/2)^k exp(-r/2).
class RadialGaussian : public NumericPotential {
 public:
  explicit RadialGaussian(int dim) : dim_(dim) {}
  std::string name() const override { return "gaussian"; }
  int dim() const override { return dim_; }
  PotentialModel model() const override { return PotentialModel::kRadial; }
  double Derivative(const std::vector<int>& a, const double* x) const override {
    double r = 0;
    for (int i = 0; i < dim_; ++i) r += x[i] * x[i];
    return 2 * std::pow(-0.5, a[0]) * std::exp(-r / 2);
  }
  void Gradient(const double* x, double* g) const override {
    Gaussian(dim_).Gradient(x, g);
  }

 private:
  int dim_;
};

// By name: "pendulum" (d = 1), "gaussian" (any d; radial model if asked).
std::unique_ptr<NumericPotential> MakePotential(const std::string& name,
                                                int dim, PotentialModel model);

}  // namespace vivp::bea
