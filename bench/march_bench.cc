// Time-slab marching at scale (docs/method.md §8):
//  1. window length: points per second and end error against W at Nt = 2^18,
//     the measurement behind MarchOptions' default window;
//  2. throughput: points per second of the marched solve (output streamed to
//     an observer, nothing kept) and of one global reduced solve, Nt = 2^10 …
//     2^22, with the peak resident memory of each run.
// Δt is fixed per problem (damped 0.0125, the late-time resolution of
// Rothkopf & Nordström 2023, Fig. 14; anharmonic 0.0024), so a larger Nt is a
// longer horizon. A global Newton solve of the anharmonic problem over a long
// horizon does not converge from the linear initial guess; those rows say so.
//
// Every measurement runs in a forked child: its peak RSS (getrusage) is then
// that run's own, and a run that exhausts memory cannot take the table down.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "bench/timing.h"
#include "solvers/variational/solver_choice.h"
#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;

namespace {

struct Sample {
  double seconds = 0;
  double error = 0;  // |x(T) − exact|, handed-off (corrected) state if marched
  long rss_kb = 0;
  int factorizations = 0;
  int fallbacks = 0;
  bool converged = false;
};

// Runs `measure` in a child process and returns its Sample with the child's
// peak resident set size; a child that dies is reported as not converged.
template <class F>
Sample InChild(F&& measure) {
  int fd[2];
  if (pipe(fd) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    Sample s = measure();
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    s.rss_kb = u.ru_maxrss;
    const ssize_t w = write(fd[1], &s, sizeof s);
    _exit(w == sizeof s ? 0 : 1);
  }
  close(fd[1]);
  Sample s;
  const ssize_t r = read(fd[0], &s, sizeof s);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (r != sizeof s) s = {};
  return s;
}

Grid FixedStep(long long points, double dt) {
  Grid g;
  g.op = "sbp42";
  g.points = points;
  g.t_end = dt * double(points - 1);
  return g;
}

Sample March(const vivp::studies::NamedProblem& p, const Grid& g,
             long long window, int repeats) {
  MarchOptions o;
  o.window_points = window;
  o.keep_trajectory = false;
  double sink = 0;
  const NodeObserver observer = [&sink](double, const double* x,
                                        const double*) { sink += x[0]; };
  MarchResult m;
  Sample s;
  s.seconds =
      bench::MedianSeconds([&] { m = p.march(g, o, observer); }, repeats);
  bench::DoNotOptimize(sink);
  s.converged = m.status.converged;
  s.error = std::abs(m.end_position[0] - p.exact(g.t_end).x[0]);
  s.factorizations = m.iterations;
  s.fallbacks = m.fallbacks;
  return s;
}

Sample Global(const vivp::studies::NamedProblem& p, const Grid& g,
              int repeats) {
  SolveOptions o;
  o.newton.max_iterations = 20;
  IvpSolution<double> sol;
  Sample s;
  s.seconds = bench::MedianSeconds([&] { sol = p.solve(g, o); }, repeats);
  s.converged = sol.status.converged;
  s.error = std::abs(sol.corrected.position[0] - p.exact(g.t_end).x[0]);
  s.factorizations = sol.iterations;
  return s;
}

struct Case {
  const char* name;
  double dt;
};
constexpr Case kCases[] = {{"damped", 0.0125}, {"anharmonic", 0.0024}};

void WindowTable() {
  const long long n = 1 << 18;
  std::printf(
      "# marching, SBP42, Nt = 2^18: window length (median of 3 runs)\n");
  std::printf("%-10s %6s %12s %10s %6s %9s\n", "problem", "W", "points/s",
              "err x(T)", "fact.", "fallbacks");
  for (const Case& c : kCases) {
    const vivp::studies::NamedProblem& p = vivp::studies::FindProblem(c.name);
    for (long long w : {16, 24, 32, 48, 64, 128, 256}) {
      const Sample s =
          InChild([&] { return March(p, FixedStep(n, c.dt), w, 3); });
      std::printf("%-10s %6lld %12.3e %10.2e %6d %9d%s\n", c.name, w,
                  double(n) / s.seconds, s.error, s.factorizations, s.fallbacks,
                  s.converged ? "" : "  NOT CONVERGED");
    }
  }
}

void ThroughputTable() {
  std::printf(
      "\n# throughput, SBP42, default window (%lld points), streamed output;\n"
      "# global = one reduced Newton solve of all points (max 20 iterations)\n",
      DefaultWindowPoints(Path::kReducedNewton, "sbp42"));
  std::printf("%-10s %9s %10s | %12s %10s %9s | %12s %10s %9s\n", "problem",
              "Nt", "T", "march pts/s", "err x(T)", "peak MB", "global pts/s",
              "err x(T)", "peak MB");
  for (const Case& c : kCases) {
    const vivp::studies::NamedProblem& p = vivp::studies::FindProblem(c.name);
    const bool linear = std::string(c.name) == "damped";
    for (long long n = 1 << 10; n <= (1 << 22); n *= 4) {
      const Grid g = FixedStep(n, c.dt);
      const int repeats = n <= (1 << 16) ? 5 : 3;
      const Sample m = InChild([&] {
        return March(p, g, DefaultWindowPoints(Path::kReducedNewton, "sbp42"),
                     repeats);
      });
      std::printf("%-10s %9lld %10.1f | %12.3e %10.2e %9.1f | ", c.name, n,
                  g.t_end, double(n) / m.seconds, m.error, m.rss_kb / 1024.0);
      // The global solve holds every point: up to 2^20 for the linear
      // problem (≈ 210 MB); the nonlinear one stops once it fails.
      const long long limit = linear ? (1 << 20) : (1 << 16);
      if (n > limit) {
        std::printf("%12s\n", "-");
        std::fflush(stdout);
        continue;
      }
      const Sample s =
          InChild([&] { return Global(p, g, n <= (1 << 16) ? 3 : 1); });
      std::printf("%12.3e %10.2e %9.1f%s\n", double(n) / s.seconds, s.error,
                  s.rss_kb / 1024.0, s.converged ? "" : "  NOT CONVERGED");
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main() {
  WindowTable();
  ThroughputTable();
}
