#include "solvers/spacetime/mode_solver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vivp::spacetime {

ModeSolver::ModeSolver(const sbp::RegularizedOperator<double>& dt,
                       const sbp::SpaceGrid<double>& grid, int m,
                       const bool dirichlet[2],
                       std::shared_ptr<const GridModes> modes)
    : nt_(dt.points()),
      nx_(grid.points()),
      m_(m),
      dirichlet_{dirichlet[0], dirichlet[1]},
      modes_(std::move(modes)) {
  if ((dirichlet_[0] || dirichlet_[1]) && grid.dim() != 1)
    throw std::invalid_argument(
        "mode solver: Dirichlet ends are eliminated on one spatial axis only");
  const int first = dirichlet_[0] ? 1 : 0;
  const int count = nx_ - first - (dirichlet_[1] ? 1 : 0);
  if (!modes_ || modes_->dim() != grid.dim() || modes_->count() != count ||
      (grid.dim() == 1 && modes_->axis(0).first() != first))
    throw std::invalid_argument(
        "mode solver: the spatial modes must be those of the points without "
        "Dirichlet data");
  const auto& D = dt.base();
  ht_.resize(nt_);
  for (int i = 0; i < nt_; ++i) ht_[i] = D.NormWeight(i);
  hx_.resize(nx_);
  for (int j = 0; j < nx_; ++j) hx_[j] = grid.NormWeight(j);
  const auto row0 = D.row(0), rowN = D.row(nt_ - 1);
  for (double c : row0.coeffs) d_first_.push_back(c * D.inv_dt());
  for (double c : rowN.coeffs) d_last_.push_back(c * D.inv_dt());
  last_first_ = rowN.first;
  // K_t = D̄ᵀHᵗD̄ as the sum over rows l of D̄ of Hᵗ_l w wᵀ, w = row l
  // (row 0 with the penalty of the affine regularization, local_map.h).
  std::vector<std::vector<std::pair<int, double>>> rows(nt_);
  for (int l = 0; l < nt_; ++l) {
    const auto r = D.row(l);
    std::vector<std::pair<int, double>> w;
    for (std::size_t k = 0; k < r.coeffs.size(); ++k)
      w.emplace_back(r.first + int(k), r.coeffs[k] * D.inv_dt());
    if (l == 0) w[0].second += dt.penalty();
    for (const auto& wi : w)
      for (const auto& wk : w) {
        if (wi.second == 0 || wk.second == 0) continue;
        auto& ri = rows[wi.first];
        const double v = ht_[l] * wi.second * wk.second;
        auto at = std::find_if(ri.begin(), ri.end(), [&](const auto& e) {
          return e.first == wk.first;
        });
        if (at == ri.end())
          ri.emplace_back(wk.first, v);
        else
          at->second += v;
      }
  }
  for (int i = 0; i < nt_; ++i)
    for (const auto& [k, v] : rows[i]) kt_.push_back({i, k, v});
  // Modes that share a time system (the cosine and sine of one Fourier
  // mode) are solved together.
  partner_.assign(modes_->count(), -1);
  std::vector<int> seen(modes_->distinct(), -1);
  for (int q = 0; q < modes_->count(); ++q) {
    int& s = seen[modes_->system_of(q)];
    if (s < 0) {
      s = q;
    } else if (partner_[s] < 0) {
      partner_[s] = q;
      partner_[q] = s;
    }
  }
}

int ModeSolver::size() const {
  return nx_ * Block() + (int(dirichlet_[0]) + int(dirichlet_[1])) * nt_ * m_;
}

std::size_t ModeSolver::factor_bytes() const {
  std::size_t bytes = 0;
  for (const auto& a : matrices_)
    bytes += sizeof(double) * std::size_t(a.leading_dimension()) * a.size() +
             sizeof(int) * a.size() * 2;
  return bytes;
}

namespace {

// The time system of one mode (2) with eigenvalue s: rows of the initial
// data first (value, then velocity, per component), then the node rows, so
// that the matrix is banded; columns in the block order φ(i, a), λ3, λ4.
template <class Sink>
void FillTimeSystem(Sink& sink, int nt, int m, double s, const DensityBlocks& b,
                    const auto& kt, const std::vector<double>& ht,
                    const std::vector<double>& d_first,
                    const std::vector<double>& d_last, int last_first) {
  auto node = [&](int i, int a) { return 2 * m + i * m + a; };
  auto phi = [&](int i, int a) { return i * m + a; };
  for (const auto& e : kt)
    for (int a = 0; a < m; ++a)
      for (int c = 0; c < m; ++c)
        sink.Add(node(e.i, a), phi(e.k, c), e.v * b.ltt(a, c));
  for (int i = 0; i < nt; ++i)
    for (int a = 0; a < m; ++a)
      for (int c = 0; c < m; ++c)
        sink.Add(node(i, a), phi(i, c),
                 ht[i] * (b.lpp(a, c) + s * b.lxx(a, c)));
  for (int a = 0; a < m; ++a) {
    sink.Add(node(nt - 1, a), nt * m + a, 1.0);
    for (std::size_t k = 0; k < d_last.size(); ++k)
      sink.Add(node(last_first + int(k), a), (nt + 1) * m + a, d_last[k]);
    sink.Add(a, phi(0, a), 1.0);
    for (std::size_t k = 0; k < d_first.size(); ++k)
      sink.Add(m + a, phi(int(k), a), d_first[k]);
  }
}

}  // namespace

bool ModeSolver::Factor(const DensityBlocks& blocks,
                        const std::vector<char>* needed) {
  for (const auto* b : {&blocks.ltt, &blocks.lxx, &blocks.lpp})
    if (b->rows() != m_ || b->cols() != m_ || !b->allFinite())
      throw std::invalid_argument(
          "mode solver: the density's Hessian blocks must be finite " +
          std::to_string(m_) + " × " + std::to_string(m_) + " matrices");
  blocks_ = blocks;
  const int n = Block();
  if (matrices_.empty()) {
    // The pattern of full blocks, so that any later blocks fit the band.
    const Eigen::MatrixXd ones = Eigen::MatrixXd::Ones(m_, m_);
    linalg::BandwidthProbe probe;
    FillTimeSystem(probe, nt_, m_, 1.0, DensityBlocks{ones, ones, ones}, kt_,
                   ht_, d_first_, d_last_, last_first_);
    kl_ = probe.kl;
    ku_ = probe.ku;
    matrices_.resize(modes_->distinct());
    lu_.clear();
    for (int k = 0; k < modes_->distinct(); ++k)
      lu_.push_back(std::make_unique<variational::BandedLu<double>>());
  }
  // The eigenvalue of each distinct system.
  std::vector<double> s(modes_->distinct(), 0.0);
  for (int q = 0; q < modes_->count(); ++q)
    s[modes_->system_of(q)] = modes_->eigenvalue(q);
  for (int k = 0; k < modes_->distinct(); ++k) {
    if (needed && !(*needed)[k]) continue;
    matrices_[k] = linalg::BandedMatrix<double>(n, kl_, ku_);
    FillTimeSystem(matrices_[k], nt_, m_, s[k], blocks_, kt_, ht_, d_first_,
                   d_last_, last_first_);
    ++factorizations_;
    if (!lu_[k]->Factor(matrices_[k])) {
      message_ = "the time system of spatial mode " + std::to_string(k) +
                 " (eigenvalue " + std::to_string(s[k]) + ") is singular";
      return false;
    }
  }
  message_.clear();
  return true;
}

void ModeSolver::Solve(double* b) const {
  const int B = Block(), nm = nt_ * m_;
  const bool eliminate = dirichlet_[0] || dirichlet_[1];
  if (eliminate) EliminatedRhs(b);
  const int count = modes_->count();
  // The initial-data rows of (1) carry Hˣ_j like the node rows.
  for (int q = 0; q < count; ++q) {
    const int j = modes_->point_of(q);
    for (int r = nm; r < B; ++r) b[std::size_t(j) * B + r] *= hx_[j];
  }
  modes_->Forward(b, B, B);
  // The data rows first, as in the factored matrix.
  auto gather = [&](const double* blk, double* w) {
    std::copy(blk + nm, blk + B, w);
    std::copy(blk, blk + nm, w + 2 * m_);
  };
  work_.resize(2 * std::size_t(B));
  for (int q = 0; q < count; ++q) {
    const int k = modes_->system_of(q);
    const int other = partner_[q];
    if (other >= 0 && other < q) continue;  // solved with its partner
    double* blk = b + std::size_t(modes_->point_of(q)) * B;
    gather(blk, work_.data());
    if (other < 0) {
      lu_[k]->Solve(work_.data());
      std::copy(work_.begin(), work_.begin() + B, blk);
      continue;
    }
    double* blk2 = b + std::size_t(modes_->point_of(other)) * B;
    gather(blk2, work_.data() + B);
    lu_[k]->SolvePair(work_.data(), work_.data() + B);
    std::copy(work_.begin(), work_.begin() + B, blk);
    std::copy(work_.begin() + B, work_.end(), blk2);
  }
  modes_->Inverse(b, B, B);
  if (eliminate) Multipliers(b);
}

void ModeSolver::SolveMode(int q, double* block) const {
  const int B = Block(), nm = nt_ * m_;
  work_.resize(2 * std::size_t(B));
  std::copy(block + nm, block + B, work_.begin());
  std::copy(block, block + nm, work_.begin() + 2 * m_);
  lu_[modes_->system_of(q)]->Solve(work_.data());
  std::copy(work_.begin(), work_.begin() + B, block);
}

// Before the modes: the Dirichlet columns are the μ rows of b (φ(t_i, x_b)
// = g_i), their λ3, λ4 the rows λ3 = λ4 = 0; their coupling through S moves
// to the right-hand side of the other points. The boundary blocks and μ rows
// are kept in saved_ for Multipliers.
void ModeSolver::EliminatedRhs(double* b) const {
  const int B = Block(), nm = nt_ * m_;
  const auto& line = modes_->axis(0);
  const auto& S = line.stiffness();
  saved_.assign(std::size_t(2) * (B + nm), 0.0);
  int slot = 0;
  for (int side = 0; side < 2; ++side) {
    if (!dirichlet_[side]) continue;
    const int jb = side == 0 ? 0 : nx_ - 1;
    double* keep = saved_.data() + std::size_t(side) * (B + nm);
    const double* mu = b + std::size_t(nx_) * B + std::size_t(slot++) * nm;
    std::copy(b + std::size_t(jb) * B, b + std::size_t(jb + 1) * B, keep);
    std::copy(mu, mu + nm, keep + B);
    const double* col = keep + B;  // δφ(i, j_b, a)
    for (int j = line.first(); j < line.first() + line.count(); ++j) {
      const double sj = S(j, jb);
      if (sj == 0) continue;
      double* blk = b + std::size_t(j) * B;
      for (int i = 0; i < nt_; ++i)
        for (int a = 0; a < m_; ++a) {
          double acc = 0;
          for (int c = 0; c < m_; ++c)
            acc += blocks_.lxx(a, c) * col[i * m_ + c];
          blk[Phi(i, a)] -= ht_[i] * sj * acc;
        }
    }
  }
}

// After the modes: the Dirichlet columns and their λ3, λ4 from the saved
// rows, then μ_i from the boundary point's node rows, whose only unknown
// left is Hᵗ_i μ_i (field_boundary.h).
void ModeSolver::Multipliers(double* b) const {
  const int B = Block(), nm = nt_ * m_;
  const auto& S = modes_->axis(0).stiffness();
  for (int side = 0; side < 2; ++side) {
    if (!dirichlet_[side]) continue;
    const int jb = side == 0 ? 0 : nx_ - 1;
    const double* keep = saved_.data() + std::size_t(side) * (B + nm);
    double* blk = b + std::size_t(jb) * B;
    std::copy(keep + B, keep + B + nm, blk);   // φ(i, j_b)
    std::copy(keep + nm, keep + B, blk + nm);  // λ3, λ4 = their rows
  }
  int slot = 0;
  std::vector<double> r(nm);
  for (int side = 0; side < 2; ++side) {
    if (!dirichlet_[side]) continue;
    const int jb = side == 0 ? 0 : nx_ - 1;
    const double* keep = saved_.data() + std::size_t(side) * (B + nm);
    const double* blk = b + std::size_t(jb) * B;
    // The node rows of j_b without μ: Hˣ_b (K_t L_tt φ + Hᵗ L_φφ φ + λ3 e_N
    // + λ4 D_N) + Hᵗ L_xx (S φ)(j_b).
    std::fill(r.begin(), r.end(), 0.0);
    for (const auto& e : kt_)
      for (int a = 0; a < m_; ++a)
        for (int c = 0; c < m_; ++c)
          r[Phi(e.i, a)] += e.v * blocks_.ltt(a, c) * blk[Phi(e.k, c)];
    for (int i = 0; i < nt_; ++i)
      for (int a = 0; a < m_; ++a)
        for (int c = 0; c < m_; ++c)
          r[Phi(i, a)] += ht_[i] * blocks_.lpp(a, c) * blk[Phi(i, c)];
    for (int a = 0; a < m_; ++a) {
      r[Phi(nt_ - 1, a)] += blk[nm + a];
      for (std::size_t k = 0; k < d_last_.size(); ++k)
        r[Phi(last_first_ + int(k), a)] += d_last_[k] * blk[nm + m_ + a];
    }
    for (double& v : r) v *= hx_[jb];
    for (int l = 0; l < nx_; ++l) {
      const double s = S(jb, l);
      if (s == 0) continue;
      const double* other = b + std::size_t(l) * B;
      for (int i = 0; i < nt_; ++i)
        for (int a = 0; a < m_; ++a)
          for (int c = 0; c < m_; ++c)
            r[Phi(i, a)] += ht_[i] * s * blocks_.lxx(a, c) * other[Phi(i, c)];
    }
    double* mu = b + std::size_t(nx_) * B + std::size_t(slot++) * nm;
    for (int i = 0; i < nt_; ++i)
      for (int a = 0; a < m_; ++a)
        mu[Phi(i, a)] = (keep[Phi(i, a)] - r[Phi(i, a)]) / ht_[i];
  }
}

}  // namespace vivp::spacetime
