// Backward error analysis timings (docs/bea.md): wall time of each
// derivation by method, dimension and order, and the rate of numerical
// evaluation of modified quantities along a trajectory. Prints tables only.
#include <cstdio>

#include "bench/timing.h"
#include "solvers/bea/conservation.h"

using namespace vivp::bea;

namespace {

struct Case {
  const char* label;
  Method method;
  int order;
  bool radial;
};

// The derivation-time table: every case derived (median of 3 below h^6, one
// run from h^6 on), with the self-check time shown apart.
void PrintDerivationTimes() {
  GiNaC::symbol alpha("alpha"), a11("a11"), a12("a12"), a22("a22");
  const Case cases[] = {
      {"sv, d=1", MakeStormerVerlet(1), 4, false},
      {"sv, d=2", MakeStormerVerlet(2), 4, false},
      {"midpoint, d=2, radial + I", MakeMidpoint(2), 4, true},
      {"lmm4 A=alpha I, d=1", MakeLmm4(ScalarMatrix(alpha, 1)), 4, false},
      {"lmm4 A=alpha I, d=2", MakeLmm4(ScalarMatrix(alpha, 2)), 4, false},
      {"lmm4 A=alpha I, d=2, radial + I", MakeLmm4(ScalarMatrix(alpha, 2)), 4,
       true},
      {"lmm4 A=[a11 a12; a12 a22], d=2",
       MakeLmm4(SymmetricMatrix2(a11, a12, a22)), 4, false},
      {"sv, d=1", MakeStormerVerlet(1), 6, false},
      {"lmm4 A=alpha I, d=2, radial + I", MakeLmm4(ScalarMatrix(alpha, 2)), 6,
       true},
      {"lmm4 A=[a11 a12; a12 a22], d=2",
       MakeLmm4(SymmetricMatrix2(a11, a12, a22)), 6, false},
      {"sv, d=1", MakeStormerVerlet(1), 8, false},
      {"sv, d=1", MakeStormerVerlet(1), 10, false},
  };
  std::printf("# BEA derivation time (median of 3; self-checks timed apart)\n");
  std::printf("%-36s %5s %12s %12s\n", "method", "order", "derive [s]",
              "checks [s]");
  for (const auto& c : cases) {
    DeriveOptions o;
    o.order = c.order;
    if (c.radial) {
      o.model = PotentialModel::kRadial;
      o.symmetry = PlaneRotation();
    }
    double checks = 0;
    const double t = vivp::bench::MedianSeconds(
        [&] {
          auto r = Derive(c.method, o);
          checks = r.check_seconds;
        },
        c.order >= 6 ? 1 : 3);
    std::printf("%-36s   h^%-2d %12.4f %12.4f\n", c.label, c.order, t - checks,
                checks);
  }
}

// Evaluations per second of f(x, v) over 200000 calls cycling through 1000
// fixed points (x, v) in R^2 x R^2.
template <class F>
double EvaluationRate(F&& f) {
  const int n = 200000;
  std::vector<double> pts(4 * 1000);
  for (std::size_t i = 0; i < pts.size(); ++i)
    pts[i] = std::sin(0.37 * i) * (i % 4 < 2 ? 1.3 : 0.4);
  const double t = vivp::bench::MedianSeconds([&] {
    double sum = 0;
    for (int k = 0; k < n; ++k) {
      const double* p = &pts[4 * (k % 1000)];
      sum += f(p, p + 2);
    }
    vivp::bench::DoNotOptimize(sum);
  });
  return n / t;
}

// The evaluation-rate table: H_mod, I_mod, x'', omega and L_mod to h^4 at
// points of a trajectory.
void PrintEvaluationRates(ModifiedQuantities& q, ModifiedQuantities& qg) {
  std::printf(
      "\n# Evaluation rate (lmm4, A = -0.2 I, d = 2, U = exp(-|x|^2/2))\n");
  std::printf("%-44s %14s\n", "quantity", "evals/s");
  std::printf("%-44s %14.3g\n", "H_mod to h^4 (radial model)",
              EvaluationRate([&](const double* x, const double* v) {
                return q.Hamiltonian(4, 0.15, x, v);
              }));
  std::printf("%-44s %14.3g\n", "I_mod to h^4 (radial model)",
              EvaluationRate([&](const double* x, const double* v) {
                return q.Charge(4, 0.15, x, v);
              }));
  std::printf("%-44s %14.3g\n", "H_mod to h^4 (generic U_a, Hermite)",
              EvaluationRate([&](const double* x, const double* v) {
                return qg.Hamiltonian(4, 0.15, x, v);
              }));
  std::printf("%-44s %14.3g\n", "modified equation x'' to h^4 (generic)",
              EvaluationRate([&](const double* x, const double* v) {
                double a[2];
                qg.Acceleration(4, 0.15, x, v, a);
                return a[0] + a[1];
              }));
  std::printf("%-44s %14.3g\n", "symplectic form omega (4x4) to h^4 (generic)",
              EvaluationRate([&](const double* x, const double* v) {
                double w[16];
                qg.SymplecticForm(4, 0.15, x, v, w);
                return w[1] + w[6];
              }));
  DeriveOptions os;
  os.order = 4;
  os.model = PotentialModel::kGeneric;
  auto rs = Derive(MakeStormerVerlet(1), os);
  Pendulum pendulum;
  ModifiedQuantities qs(rs, pendulum);
  std::printf("%-44s %14.3g\n", "L_mod to h^4 (Stormer-Verlet, pendulum)",
              EvaluationRate([&](const double* x, const double* v) {
                return qs.Lagrangian(4, 0.15, x, v);
              }));
}

}  // namespace

int main() {
  PrintDerivationTimes();

  // Evaluation rate: H_mod to h^4 and I to h^4 at points of a trajectory.
  DeriveOptions o;
  o.order = 4;
  o.model = PotentialModel::kRadial;
  o.symmetry = PlaneRotation();
  auto r = Derive(MakeLmm4(ScalarMatrix(GiNaC::numeric(-1, 5), 2)), o);
  RadialGaussian potential(2);
  ModifiedQuantities q(r, potential);
  Gaussian generic_potential(2);
  o.model = PotentialModel::kGeneric;
  o.symmetry.reset();
  auto rg = Derive(MakeLmm4(ScalarMatrix(GiNaC::numeric(-1, 5), 2)), o);
  ModifiedQuantities qg(rg, generic_potential);
  PrintEvaluationRates(q, qg);

  // One whole sweep point: march + velocities + H and I at every step.
  ConservationSetup s;
  s.x0 = Eigen::Vector2d(1, -1);
  s.v0 = Eigen::Vector2d(0.1, -0.2);
  s.t_end = 1500;
  const double t = vivp::bench::MedianSeconds(
      [&] { Deviations(r, q, potential, s, 0.15); }, 3);
  std::printf("\n# Fig. 1 run (10^4 steps, 6 quantities per step): %.3f s\n",
              t);
}
