// The largest window in which Ceres Levenberg–Marquardt keeps the Newton
// march's accuracy and iteration count, per operator: the measurement behind
// Measured::lm_window_points (core/sbp; DefaultWindowPoints in
// solvers/variational/solver_choice.h) and the table of docs/method.md §8.
//
// LM minimises |∇S|² through the normal equations JᵀJ, whose condition
// number is the square of the Jacobian's, so from some window on LM stops
// short of the critical point Newton reaches, or needs many more iterations
// (globally, from the linear guess, it stalls from Nt = 2048). Each row
// marches one problem in windows of W points twice — reduced Newton and
// Ceres LM, both started from the same Dormand–Prince predictor — and prints
// the end error of the handed-off (corrected) state against the exact
// solution, the iterations per window (LM: its iterations; Newton: Jacobian
// factorizations and corrections) and the time (median of 3 runs). LM keeps
// Newton's
//   accuracy    when |e_LM − e_Newton| ≤ 5 % of e_Newton + 1e-12,
//   iterations  when its iterations per window are at most 1.5 times
//               Newton's corrections per window.
// The default window of an operator is the largest W that keeps both on the
// anharmonic oscillator (Rothkopf & Nordström 2023, eq. 33) to T = 10 at
// Δt = 10/1024 and on Kepler e = 0.6 over three orbits (4097 points); it is
// then checked on the anharmonic oscillator at Δt = 10/4096.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/timing.h"
#include "problems/anharmonic.h"
#include "problems/kepler.h"
#include "solvers/variational/solve.h"

using namespace vivp;
using namespace vivp::variational;

namespace {

struct Sample {
  bool converged = false;
  double error = 0;  // max over components of |x(T) − exact|, corrected state
  double iterations = 0, corrections = 0;  // per window
  int fallbacks = 0;
  double seconds = 0;
  std::string reason;
};

template <class P>
Sample March(const P& problem, const vivp::variational::InitialData& initial,
             const Grid& grid, const std::vector<double>& exact_x,
             long long window, Path path) {
  vivp::variational::MarchOptions o;
  o.window_points = window;
  o.keep_trajectory = false;
  o.stabilize = false;
  o.solve.path = path;
  vivp::variational::MarchResult m;
  Sample s;
  s.seconds =
      bench::MedianSeconds([&] { m = Solve(problem, initial, grid, o); }, 3);
  s.converged = m.status.converged;
  s.reason = m.status.reason;
  for (std::size_t c = 0; c < exact_x.size(); ++c)
    s.error = std::max(s.error, std::abs(m.end_position[c] - exact_x[c]));
  const double w = double(std::max<long long>(m.window_count, 1));
  s.iterations = m.iterations / w;
  s.corrections = m.corrections / w;
  s.fallbacks = m.fallbacks;
  return s;
}

struct Row {
  std::string op;
  long long window = 0;
  Sample lm, newton;
  bool accurate = false, iterations = false;
};

void PrintHeader() {
  std::printf("%-6s %5s %11s %11s %8s %8s %8s %8s %8s  %s\n", "op", "W",
              "LM err", "Newton err", "LM it/w", "N fact/w", "N corr/w", "LM s",
              "Newton s", "keeps accuracy, iterations");
}

Row Compare(const std::string& op, long long w, const Sample& l,
            const Sample& n) {
  Row r{op, w, l, n};
  r.accurate = l.converged && n.converged &&
               std::abs(l.error - n.error) <= 0.05 * n.error + 1e-12;
  r.iterations = l.converged && l.iterations <= 1.5 * n.corrections;
  std::printf("%-6s %5lld %11.3e %11.3e %8.2f %8.2f %8.2f %8.3f %8.3f  %s, %s",
              op.c_str(), w, l.error, n.error, l.iterations, n.iterations,
              n.corrections, l.seconds, n.seconds, r.accurate ? "yes" : "no",
              r.iterations ? "yes" : "no");
  if (!l.converged) std::printf(" (LM: %s)", l.reason.c_str());
  if (!n.converged) std::printf(" (Newton: %s)", n.reason.c_str());
  std::printf("\n");
  std::fflush(stdout);
  return r;
}

const problems::Anharmonic kAnharmonic;
const problems::Kepler kKepler;

// One sweep over W: the anharmonic oscillator to T = 10 on `points` nodes,
// or Kepler over three orbits (W up to 256); every operator and window, or
// only the operator `only_op` in the window `only_w`.
std::vector<Row> Sweep(bool kepler, long long points,
                       const std::string& only_op = "", long long only_w = 0) {
  const std::vector<double> y = kKepler.Initial();
  const std::vector<double> k_end = kKepler.Exact(6 * M_PI);
  const vivp::variational::InitialData start =
      kepler ? InitialData{{y[0], y[1]}, {y[2], y[3]}}
             : InitialData{{kAnharmonic.x0}, {kAnharmonic.v0}};
  const std::vector<double> exact =
      kepler ? std::vector<double>{k_end[0], k_end[1]}
             : std::vector<double>{kAnharmonic.Exact(10.0).x};
  const double t_end = kepler ? 6 * M_PI : 10.0;
  std::vector<Row> rows;
  for (const std::string& name : sbp::OperatorNames()) {
    const char* op = name.c_str();
    const Grid grid{.op = op, .points = points, .t_end = t_end};
    for (long long w : {16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512}) {
      if (w < sbp::Table(op).min_points || (kepler && w > 256)) continue;
      if (!only_op.empty() && (op != only_op || w != only_w)) continue;
      auto run = [&](Path path) {
        return kepler ? March(kKepler, start, grid, exact, w, path)
                      : March(kAnharmonic, start, grid, exact, w, path);
      };
      const Sample n = run(Path::kReducedNewton);
      rows.push_back(Compare(op, w, run(Path::kCeresLm), n));
    }
  }
  return rows;
}

bool Keeps(const std::vector<Row>& rows, const std::string& op, long long w) {
  for (const Row& r : rows)
    if (r.op == op && r.window == w) return r.accurate && r.iterations;
  return false;
}

}  // namespace

int main() {
  std::printf("# anharmonic oscillator to T = 10, 1025 points\n");
  PrintHeader();
  const std::vector<Row> anharmonic = Sweep(false, 1025);
  std::printf("\n# Kepler e = 0.6, three orbits, 4097 points\n");
  PrintHeader();
  const std::vector<Row> kepler = Sweep(true, 4097);
  std::printf(
      "\n# the largest window that keeps both on both, checked on the "
      "anharmonic oscillator at 4097 points\n");
  PrintHeader();
  for (const std::string& name : sbp::OperatorNames()) {
    const char* op = name.c_str();
    long long best = 0;
    for (const Row& r : kepler)
      if (r.op == op && Keeps(kepler, op, r.window) &&
          Keeps(anharmonic, op, r.window))
        best = r.window;
    if (best == 0)
      std::printf("%-6s  none\n", op);
    else
      Sweep(false, 4097, op, best);
  }
  return 0;
}
