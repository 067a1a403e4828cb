#include "studies/vortex_scattering.h"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "core/action/vortex_tracks.h"
#include "solvers/spacetime/charged_march.h"
#include "solvers/spacetime/charged_static.h"
#include "solvers/spacetime/vortex_data.h"
#include "studies/vortex.h"

namespace vivp::studies {

namespace {

using System = action::ChargedFieldSystem<fields::ScalarQed, 2>;
using Supernodal = spacetime::NormalEquationsSolverOf<
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>>;

// The vortices of node i of a window.
void Track(const System& sys, const std::vector<double>& y, int i, double t,
           std::vector<TrackSample>& out) {
  const int nx = sys.space_points();
  std::vector<double> slice(std::size_t(nx) * System::m);
  for (int j = 0; j < nx; ++j)
    for (int a = 0; a < System::m; ++a)
      slice[std::size_t(j) * System::m + a] = y[sys.Phi(i, j, a)];
  for (const auto& v : action::FindVortices(sys.space_grid(), slice.data()))
    out.push_back({t, v.x, v.y, v.winding});
}

// The direction of a straight line through the samples (least squares in
// t), as the angle from the x axis in [0°, 90°].
double LineAngle(const std::vector<TrackSample>& s) {
  double st = 0, sx = 0, sy = 0, stt = 0, stx = 0, sty = 0;
  const double k = double(s.size());
  for (const auto& p : s) {
    st += p.t;
    sx += p.x;
    sy += p.y;
    stt += p.t * p.t;
    stx += p.t * p.x;
    sty += p.t * p.y;
  }
  const double den = k * stt - st * st;
  const double vx = (k * stx - st * sx) / den, vy = (k * sty - st * sy) / den;
  return std::atan2(std::abs(vy), std::abs(vx)) * 180 / std::numbers::pi;
}

// The collision (the least distance of the two vortices) and the outgoing
// directions, fitted on the last 40 % of the time after it, one line per
// half plane y > 0 and y < 0.
void Measure(ScatteringRun& r, double t_end) {
  std::vector<double> times;
  for (const auto& p : r.tracks)
    if (times.empty() || p.t != times.back()) times.push_back(p.t);
  r.closest = INFINITY;
  for (double t : times) {
    std::vector<const TrackSample*> v;
    for (const auto& p : r.tracks)
      if (p.t == t && p.winding > 0) v.push_back(&p);
    if (v.size() != 2) continue;
    const double d = std::hypot(v[0]->x - v[1]->x, v[0]->y - v[1]->y);
    if (d < r.closest) {
      r.closest = d;
      r.collision_time = t;
    }
  }
  const double from = r.collision_time + 0.6 * (t_end - r.collision_time);
  for (const int side : {1, -1}) {
    std::vector<TrackSample> out;
    for (const auto& p : r.tracks)
      if (p.winding > 0 && p.t >= from && side * p.y > 0) out.push_back(p);
    if (out.size() >= 3) r.outgoing.push_back(LineAngle(out));
  }
  for (double a : r.outgoing) r.angle += a / double(r.outgoing.size());
}

}  // namespace

ScatteringRun ScatterVortices(const ScatteringSetup& s) {
  ScatteringRun r;
  const auto start = std::chrono::steady_clock::now();
  const auto grid = VortexSquare(s.n, s.length);
  const auto model = CriticalHiggs();
  const double l = s.length;
  std::vector<double> x = spacetime::VortexAnsatz(grid, 1.0,
                                                  {{s.offset, 0, 1},
                                                   {-s.offset, 0, 1},
                                                   {l / 2, 3 * l / 8, -1},
                                                   {l / 2, -3 * l / 8, -1}});
  // The profiles relax in a few tens of L-BFGS iterations (the residual
  // falls from 0.9 to 1e-3 on 32²); past them L-BFGS moves the vortices
  // along their flat directions (at critical coupling like vortices exert
  // no force), and after 150 they meet the antivortices: the relaxation
  // stops early, the positions kept.
  spacetime::StaticOptions so;
  so.residual = 1e-3;
  so.max_iterations = 30;
  so.newton_steps = 0;
  const auto relaxed = spacetime::RelaxChargedSlice2(model, grid, 0, x, so);
  r.relax_residual = relaxed.residual;
  // Velocity −u tanh(x/w) along x near the vortices, none near the
  // antivortices (r > 5.5 from the centre).
  const double u = s.speed, w = s.transition;
  const std::vector<double> pi =
      spacetime::MovingSliceVelocities(grid, x, [u, w](double px, double py) {
        const double r2 = (px * px + py * py) / (5.5 * 5.5);
        return std::array<double, 2>{
            -u * std::tanh(px / w) * std::exp(-std::pow(r2, 4)), 0.0};
      });
  spacetime::ChargedMarchOptions o;
  o.time_operator = s.op;
  o.window = s.window;
  o.dt = s.dt;
  o.windows = std::max(1, int(std::lround(s.t_end / (s.dt * (s.window - 1)))));
  double e0 = NAN;
  const auto march = spacetime::MarchCharged<fields::ScalarQed, 2, Supernodal>(
      model, grid, x, pi, o,
      [&](const System& sys, const std::vector<double>& y,
          const action::ChargedNodes& nodes,
          const spacetime::ChargedSliceState& handed) {
        const auto& D = sys.time_operator().base();
        for (int i = r.windows == 0 ? 0 : 1; i < s.window; ++i)
          Track(sys, y, i, D.t(i), r.tracks);
        for (double g : nodes.gauss_action) r.gauss = std::max(r.gauss, g);
        const double e =
            spacetime::SliceEnergy<2>(model, grid, D.t(s.window - 1), handed);
        if (std::isnan(e0)) e0 = e;
        r.energy_drift = std::max(r.energy_drift, std::abs(e - e0) / e0);
        ++r.windows;
      });
  r.ok = march.ok;
  r.reason = march.reason;
  for (const auto& rep : march.windows) r.newton += rep.iterations;
  if (r.ok) Measure(r, o.dt * (s.window - 1) * o.windows);
  r.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  return r;
}

}  // namespace vivp::studies
