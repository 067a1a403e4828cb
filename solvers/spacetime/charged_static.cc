#include "solvers/spacetime/charged_static.h"

#include <ceres/ceres.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/action/charged_terms.h"
#include "solvers/spacetime/assembly.h"

namespace vivp::spacetime {

namespace {

constexpr int kDim = 2;
using Layout = action::ChargedLayout<kDim>;

// U over the unknowns of φ and the links only (χ is not in U): Ceres sees
// (2 + d) numbers per point.
class SlicePotential final : public ceres::FirstOrderFunction {
 public:
  SlicePotential(const fields::ScalarQed& model,
                 const sbp::SpaceGrid<double>& grid, double inv_g2,
                 std::vector<double> full)
      : model_(model),
        grid_(grid),
        inv_g2_(inv_g2),
        full_(std::move(full)),
        grad_(full_.size()) {}
  static constexpr int kPacked = Layout::kChi;  // Re, Im, A_0 … A_{d−1}

  bool Evaluate(const double* p, double* cost, double* g) const override {
    Unpack(p, full_);
    *cost = action::ChargedSlicePotential<kDim>(
        model_, grid_, inv_g2_, full_.data(), g ? grad_.data() : nullptr);
    if (g)
      for (int j = 0; j < grid_.points(); ++j)
        for (int a = 0; a < kPacked; ++a)
          g[j * kPacked + a] = grad_[j * Layout::m + a];
    return std::isfinite(*cost);
  }
  int NumParameters() const override { return grid_.points() * kPacked; }

  void Unpack(const double* p, std::vector<double>& full) const {
    for (int j = 0; j < grid_.points(); ++j)
      for (int a = 0; a < kPacked; ++a)
        full[j * Layout::m + a] = p[j * kPacked + a];
  }
  std::vector<double> Pack(const std::vector<double>& full) const {
    std::vector<double> p(static_cast<std::size_t>(NumParameters()));
    for (int j = 0; j < grid_.points(); ++j)
      for (int a = 0; a < kPacked; ++a)
        p[j * kPacked + a] = full[j * Layout::m + a];
    return p;
  }

 private:
  const fields::ScalarQed& model_;
  const sbp::SpaceGrid<double>& grid_;
  double inv_g2_;
  mutable std::vector<double> full_, grad_;
};

// max_k |g_k| / Hˣ over φ and the links.
double StaticResidualOf(const sbp::SpaceGrid<double>& grid,
                        const std::vector<double>& g) {
  double worst = 0;
  for (int j = 0; j < grid.points(); ++j)
    for (int a = 0; a < Layout::kChi; ++a)
      worst =
          std::max(worst, std::abs(g[j * Layout::m + a]) / grid.NormWeight(j));
  return worst;
}

// Newton on U from x: (H + μ I) δ = −∇U with H the sparse Hessian of U
// (the slice's terms, charged_terms.h), factored by a sparse LDLᵀ. H is
// singular along the gauge directions and ∇U is orthogonal to them
// (Noether), so the small damping μ = 1e-9 max diag H moves the step's
// physical part only along eigenvalues of H near μ, which the next step
// corrects (with 1e-12 the 96² pair took 4 steps to 7e-12, with 1e-9 one
// step to 3e-14: the gauge directions' round-off is damped harder).
int NewtonPolish(const fields::ScalarQed& model,
                 const sbp::SpaceGrid<double>& grid, double inv_g2, double tol,
                 int steps, std::vector<double>& x) {
  const int n = int(x.size());
  std::vector<double> g(x.size());
  PatternedMatrix hessian;
  // LDLᵀ, not Cholesky: CHOLMOD's supernodal LLᵀ refused H + μI as not
  // positive definite at the vortex pair of studies/vortex.h (48² and 96²
  // points; a negative eigenvalue or round-off along the gauge directions).
  // CHOLMOD's simplicial LDLᵀ rather than Eigen's: the same factorization,
  // from a library the sanitizer build does not instrument (there Eigen's
  // took most of the vortex test's 8 minutes).
  Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  int k = 0;
  for (; k < steps; ++k) {
    action::ChargedSlicePotential<kDim>(model, grid, inv_g2, x.data(),
                                        g.data());
    if (StaticResidualOf(grid, g) <= tol) break;
    hessian.Assemble(n, [&](auto& sink) {
      action::ForEachSliceTerm<kDim>(model, grid, inv_g2, x.data(),
                                     [&](const action::LocalReal& t, double w) {
                                       action::AddTerm(t, w, nullptr, &sink);
                                     });
      // χ is not in U: its diagonal keeps the matrix regular.
      for (int j = 0; j < grid.points(); ++j)
        sink.Add(j * Layout::m + Layout::kChi, j * Layout::m + Layout::kChi,
                 0.0);
    });
    Eigen::SparseMatrix<double> a = hessian.matrix();
    const double mu = 1e-9 * a.diagonal().cwiseAbs().maxCoeff();
    for (int c = 0; c < n; ++c) a.coeffRef(c, c) += mu;
    const Eigen::Map<const Eigen::VectorXd> rhs(g.data(), n);
    if (k == 0) ldlt.analyzePattern(a);
    ldlt.factorize(a);
    if (ldlt.info() != Eigen::Success) break;
    const Eigen::VectorXd step = ldlt.solve(-rhs);
    for (int c = 0; c < n; ++c)
      if (c % Layout::m != Layout::kChi) x[c] += step[c];
  }
  return k;
}

}  // namespace

double StaticResidual2(const fields::ScalarQed& model,
                       const sbp::SpaceGrid<double>& grid, double t,
                       const std::vector<double>& x) {
  std::vector<double> g(x.size());
  action::ChargedSlicePotential<kDim>(
      model, grid, action::CheckedInverseCouplingSquared(model, t), x.data(),
      g.data());
  return StaticResidualOf(grid, g);
}

StaticReport RelaxChargedSlice2(const fields::ScalarQed& model,
                                const sbp::SpaceGrid<double>& grid, double t,
                                std::vector<double>& x,
                                const StaticOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  StaticReport r;
  r.start_residual = StaticResidual2(model, grid, t, x);
  const double inv_g2 = action::CheckedInverseCouplingSquared(model, t);
  auto* f = new SlicePotential(model, grid, inv_g2, x);
  std::vector<double> p = f->Pack(x);
  const ceres::GradientProblem problem(f);  // owns f
  ceres::GradientProblemSolver::Options o;
  o.line_search_direction_type = ceres::LBFGS;
  // Quiet: a line search that stops at round-off is the expected end
  // (the Newton steps below take over), not a warning for the user.
  o.logging_type = ceres::SILENT;
  o.max_lbfgs_rank = options.memory;
  o.max_num_iterations = options.max_iterations;
  // Ceres' test is max |g| with g the gradient of U, which carries Hˣ.
  double h_min = grid.NormWeight(0);
  for (int j = 1; j < grid.points(); ++j)
    h_min = std::min(h_min, grid.NormWeight(j));
  o.gradient_tolerance = options.residual * h_min;
  o.function_tolerance = 1e-30;  // U's changes fall below round-off first
  o.parameter_tolerance = 1e-30;
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(o, problem, p.data(), &summary);
  f->Unpack(p.data(), x);
  r.iterations = int(summary.iterations.size()) - 1;
  r.lbfgs_residual = StaticResidual2(model, grid, t, x);
  r.lbfgs_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  r.newton = NewtonPolish(model, grid, inv_g2, options.residual,
                          options.newton_steps, x);
  r.energy = action::ChargedSlicePotential<kDim>(model, grid, inv_g2, x.data(),
                                                 nullptr);
  r.residual = StaticResidual2(model, grid, t, x);
  r.converged = r.residual <= options.residual;
  r.message = summary.message;
  r.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  return r;
}

}  // namespace vivp::spacetime
