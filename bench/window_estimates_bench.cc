// How far a window's embedded error estimates can be trusted: for every
// accepted window of a march, the estimates |M⁻¹λ4| (of x_N) and
// |(Dx)_N − M⁻¹(−λ3)| (of (Dx)_N) against the true local errors, measured
// against the exact local flow from the window's own initial state
// (Dormand–Prince at 1e-15, predictor.h); and the true error of the
// handed-off state against the estimate, which the a-posteriori check
// (window_solve.h) and the controller rely on bounding it.
//
// Windows whose true error is below 1e3·ε of the solution's size are left out
// of the ratios (round-off, not truncation). Rows: operator, march (uniform
// grid of 4097 points, or error control at 1e-6 — SBP21 at 1e-4 — or at the
// tolerance given as the only argument), problem; columns: windows, the
// 10/50/90 % quantiles and the extremes of the ratios.
//
// The spectral elements too: on a uniform grid their estimates are those of
// every window (of the end node, of order about n); under error control each
// window is a half of an element solved whole and halved, and its estimate
// that of the halves' hand-off (solvers/variational/element_halves.h), so
// only the last two columns apply.
// Rows "emb": the elements under error control by their own end-node
// estimates (ElementEstimate::kEmbedded), every column applies.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/sbp/builder.h"
#include "core/sbp/lobatto.h"
#include "problems/anharmonic.h"
#include "problems/kepler.h"
#include "problems/pendulum.h"
#include "solvers/variational/march.h"

using namespace vivp;
using namespace vivp::variational;

namespace {

struct Quantiles {
  double lo = NAN, p10 = NAN, p50 = NAN, p90 = NAN, hi = NAN;
};

Quantiles Of(std::vector<double> v) {
  Quantiles q;
  if (v.empty()) return q;
  std::sort(v.begin(), v.end());
  auto at = [&](double f) { return v[std::size_t(f * double(v.size() - 1))]; };
  q.lo = v.front();
  q.p10 = at(0.1);
  q.p50 = at(0.5);
  q.p90 = at(0.9);
  q.hi = v.back();
  return q;
}

// The tolerance of the march under error control: 1e-6, and 1e-4 for an
// operator whose last node has a first-order velocity (SBP21): its step
// scales like the tolerance, and 1e-6 would take 10^8 nodes here.
// A tolerance given on the command line replaces it for every operator.
double given_level = 0;
double Level(const std::string& op) {
  if (given_level > 0) return given_level;
  return vivp::sbp::Table(op).boundary_order == 1 ? 1e-4 : 1e-6;
}

struct Ratios {
  std::vector<double> x, v, handoff_x, handoff_v;
  long long windows = 0;
};

template <class P>
void Collect(const P& problem, const vivp::variational::InitialData& init,
             double t_end, const std::string& op, bool tolerance, bool embedded,
             Ratios& r) {
  constexpr int d = P::kDim;
  Predictor<P> exact(problem, 2);
  vivp::variational::MarchOptions o;
  o.keep_trajectory = false;
  o.stabilize = false;
  const double level = Level(op);
  if (tolerance) o.tolerance = {level, level};
  o.element_estimate = embedded ? vivp::variational::ElementEstimate::kEmbedded
                                : vivp::variational::ElementEstimate::kHalves;
  o.window_observer = [&](const vivp::variational::WindowSample& s) {
    std::vector<double> tau(s.points), xs(s.points * d), vs(s.points * d);
    for (int i = 0; i < s.points; ++i) tau[i] = s.dt * double(i);
    exact.Run(s.x0, s.v0, tau.data(), s.points, 1e-15, 1e-15, xs.data(),
              vs.data());
    const double* xe = &xs[(s.points - 1) * d];
    const double* ve = &vs[(s.points - 1) * d];
    double scale_x = 0, scale_v = 0;
    for (int c = 0; c < d; ++c) {
      scale_x = std::max(scale_x, std::abs(xe[c]));
      scale_v = std::max(scale_v, std::abs(ve[c]));
    }
    const double floor_x = 1e3 * 2.2e-16 * scale_x;
    const double floor_v = 1e3 * 2.2e-16 * scale_v;
    double ex = 0, ev = 0, hx = 0, hv = 0, est_x = 0, est_v = 0;
    for (int c = 0; c < d; ++c) {
      ex = std::max(ex, std::abs(s.x_end[c] - xe[c]));
      ev = std::max(ev, std::abs(s.v_end[c] - ve[c]));
      hx = std::max(hx, std::abs(s.handoff_x[c] - xe[c]));
      hv = std::max(hv, std::abs(s.handoff_v[c] - ve[c]));
      est_x = std::max(est_x, s.est_x[c]);
      est_v = std::max(est_v, s.est_v[c]);
    }
    ++r.windows;
    if (ex > floor_x) r.x.push_back(est_x / ex);
    if (ev > floor_v) r.v.push_back(est_v / ev);
    if (est_x > floor_x) r.handoff_x.push_back(hx / est_x);
    if (est_v > floor_v) r.handoff_v.push_back(hv / est_v);
  };
  // A spectral element's uniform grid: whole elements of n − 1 steps.
  const long long per = std::max(sbp::Table(op).max_points - 1, 1);
  Grid g{.op = op, .points = (4096 + per - 1) / per * per + 1, .t_end = t_end};
  const vivp::variational::MarchResult m = MarchIvp(problem, init, g, o);
  if (!m.status.converged)
    std::printf("# %s, %s: %s\n", op.c_str(),
                tolerance ? "tolerance" : "uniform", m.status.reason.c_str());
}

void Row(const char* op, const char* march, const char* what, const Ratios& r) {
  auto cell = [](const Quantiles& q) {
    std::printf(" | %8.2g %8.2g %8.2g %8.2g %8.2g", q.lo, q.p10, q.p50, q.p90,
                q.hi);
  };
  std::printf("%-6s %-9s %-10s %7lld", op, march, what, r.windows);
  cell(Of(r.x));
  cell(Of(r.v));
  std::printf(" | %8.2g %8.2g\n", Of(r.handoff_x).hi, Of(r.handoff_v).hi);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) {
    given_level = std::atof(argv[1]);
    if (!(given_level > 0) || argc > 2) {
      std::fprintf(stderr,
                   "usage: window_estimates_bench [tolerance > 0], got '%s'\n",
                   argv[1]);
      return 2;
    }
  }
  std::printf(
      "# estimate / true local error of x_N and (Dx)_N: min 10%% 50%% 90%% "
      "max; then the largest true error of the hand-off over the estimate "
      "(position, velocity)\n");
  std::printf("%-6s %-9s %-10s %7s | %44s | %44s | %17s\n", "op", "march",
              "problem", "windows", "|M^-1 l4| / err x_N",
              "|(Dx)_N + M^-1 l3| / err (Dx)_N", "hand-off / est.");
  problems::Kepler e06, e09;
  e09.e = 0.9;
  std::vector<std::string> ops = vivp::sbp::OperatorNames();
  for (const vivp::sbp::Coefficients* e : vivp::sbp::ElementOperators())
    ops.emplace_back(e->name);
  for (const std::string& name : ops) {
    const char* op = name.c_str();
    // A spectral element also under error control by its own end-node
    // estimates (ElementEstimate::kEmbedded), where every column applies.
    const int kinds = vivp::sbp::IsElement(name) ? 3 : 2;
    for (int kind = 0; kind < kinds; ++kind) {
      const bool tolerance = kind > 0, embedded = kind == 2;
      const std::string march =
          !tolerance
              ? "uniform"
              : (embedded ? "emb 1e-" : "tol 1e-") +
                    std::to_string(std::lround(-std::log10(Level(name))));
      Ratios a, p, k6, k9, all;
      Collect(problems::Anharmonic{}, {{1.0}, {0.3}}, 10.0, op, tolerance,
              embedded, a);
      Collect(problems::Pendulum{}, {{0.0}, {1.0}}, 20.0, op, tolerance,
              embedded, p);
      Collect(e06, {{0.4, 0.0}, {0.0, 2.0}}, 10 * M_PI, op, tolerance, embedded,
              k6);
      Collect(e09, {{0.1, 0.0}, {0.0, std::sqrt(19.0)}}, 2 * M_PI, op,
              tolerance, embedded, k9);
      Row(op, march.c_str(), "anharmonic", a);
      Row(op, march.c_str(), "pendulum", p);
      Row(op, march.c_str(), "kepler 0.6", k6);
      Row(op, march.c_str(), "kepler 0.9", k9);
      std::fflush(stdout);
    }
  }
}
