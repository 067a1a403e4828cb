#include "studies/vortex_scattering.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "core/action/vortex_tracks.h"
#include "solvers/spacetime/charged_march_2d.h"
#include "solvers/spacetime/vortex_data.h"
#include "studies/vortex.h"

namespace vivp::studies {

namespace {

using System = spacetime::ChargedSystem2;

// The vortices of node i of a window.
void Track(const System& sys, const std::vector<double>& y, int i, double t,
           std::vector<TrackSample>& out) {
  for (const auto& v : action::FindVorticesAtNode(sys, y.data(), i))
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
// half plane y > cy and y < cy (cy: the centre of the collision).
void Measure(ScatteringRun& r, double t_end, double cy) {
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
      if (p.winding > 0 && p.t >= from && side * (p.y - cy) > 0)
        out.push_back(p);
    if (out.size() >= 3) r.outgoing.push_back(LineAngle(out));
  }
  for (double a : r.outgoing) r.angle += a / double(r.outgoing.size());
}

}  // namespace

ScatteringRun ScatterVortices(const ScatteringSetup& s) {
  ScatteringRun r;
  const auto start = std::chrono::steady_clock::now();
  auto axis = [&] {
    return sbp::SpaceDerivative<double>::Periodic(2, s.n, -s.length / 2,
                                                  s.length);
  };
  const sbp::SpaceGrid<double> grid({axis(), axis()});
  const auto model = CriticalHiggs();
  const auto data = spacetime::VortexCollisionData(model, grid, s.offset,
                                                   s.speed, s.transition);
  r.relax_residual = data.relax.residual;
  spacetime::ChargedMarchOptions o;
  o.time_operator = s.op;
  o.window = s.window;
  o.dt = s.dt;
  o.windows = std::max(1, int(std::lround(s.t_end / (s.dt * (s.window - 1)))));
  double e0 = NAN;
  const auto march = spacetime::MarchChargedSupernodal(
      model, grid, data.x, data.pi, o,
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
  if (r.ok)
    Measure(r, o.dt * (s.window - 1) * o.windows,
            0.5 * (data.seeds[0].y + data.seeds[1].y));
  r.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  return r;
}

}  // namespace vivp::studies
