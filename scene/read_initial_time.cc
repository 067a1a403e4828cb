// [initial] and [time]: the initial data and the grid of the initial value
// problem.
#include "core/sbp/builder.h"
#include "scene/sections.h"
#include "scene/text.h"

namespace vivp::scene::detail {

namespace {

// Global solves hold every node (and a banded LU) at once; beyond this a
// typo such as points = 1e9 would exhaust memory instead of failing.
constexpr long long kMaxGlobalPoints = 1LL << 22;
// Marching and steppers stream, but at ~10^7 points/s more than this is a
// run of hours: most likely a mistake.
constexpr long long kMaxPoints = 1LL << 28;

}  // namespace

void ReadInitial(const TomlReader& r, const toml::table& root, Scene& s) {
  const toml::table& t = r.Table(root, "initial", true);
  r.CheckKeys(t, "[initial]", {"x", "v"});
  const std::string n = std::to_string(s.dof);
  const std::string array =
      "an array of " + FiniteNumbers(s.dof) + " (dof = " + n + ")";
  s.x0 = r.Numbers(
      r.Require(t, "initial", "x", "x = [...], " + n + " initial positions"),
      "x", std::size_t(s.dof), array);
  const toml::node* v = t.get("v");
  if (s.order == 2) {
    if (!v) {
      const auto& pos = t.source().begin;
      r.Fail(int(pos.line), int(pos.column),
             "[initial] has no velocity 'v' but the system is second order "
             "(it has kinetic energy)",
             "expected v = [...] with " + FiniteNumbers(s.dof));
    }
    s.v0 = r.Numbers(*v, "v", std::size_t(s.dof), array);
  } else if (v) {
    r.Fail(*v,
           "[initial] gives a velocity but the system is first order (no "
           "kinetic energy: the initial position fixes the solution)",
           "expected no 'v' in [initial]");
  }
}

void ReadTime(const TomlReader& r, const toml::table& root, Scene& s) {
  const toml::table& t = r.Table(root, "time", true);
  r.CheckKeys(t, "[time]", {"start", "end", "points"});
  if (const toml::node* n = t.get("start"))
    s.t_start = r.Number(*n, "start", "a finite start time");
  const toml::node& end =
      r.Require(t, "time", "end", "end = T, the final time");
  s.t_end = r.Number(end, "end", "a finite end time after start");
  if (!(s.t_end > s.t_start))
    r.Fail(end,
           "end = " + FormatNumber(s.t_end) +
               " is not after start = " + FormatNumber(s.t_start),
           "expected end > start");
  const long long minimum =
      s.variational() ? sbp::Table(s.method.op).min_points : 2;
  const std::string at_least =
      "at least " + std::to_string(minimum) +
      (s.variational() ? " for " + s.method.op : std::string(""));
  if (s.method.tolerance.enabled()) {
    // The march chooses the nodes.
    if (const toml::node* p = t.get("points"))
      r.Fail(*p,
             "points and [method] tolerance exclude each other: the "
             "tolerance chooses the grid",
             "expected no points (error control), or no tolerance (a uniform "
             "grid of that many points)");
    return;
  }
  const toml::node& points =
      r.Require(t, "time", "points",
                "points = N, the number of grid nodes (or [method] tolerance)");
  s.points = r.Whole(points, "points", 0, "a whole number, " + at_least);
  if (s.points < minimum)
    r.Fail(points,
           "points = " + std::to_string(s.points) + " is below the minimum",
           "expected " + at_least);
  const bool global = s.variational() && s.method.slab_points == 0;
  const long long maximum = global ? kMaxGlobalPoints : kMaxPoints;
  if (s.points > maximum)
    r.Fail(points,
           "points = " + std::to_string(s.points) + " is too many" +
               (global ? " for one global solve" : ""),
           "expected at most " + std::to_string(maximum) +
               (global ? " (or march: [method] slab_points = 48)" : ""));
  if (s.method.slab_points > s.points) {
    const toml::table* method = root["method"].as_table();
    const toml::node* slab = method ? method->get("slab_points") : nullptr;
    // A default window (ceres-lm's) longer than the grid: one window.
    if (!slab) {
      s.method.slab_points = s.points;
      return;
    }
    r.Fail(*slab,
           "slab_points = " + std::to_string(s.method.slab_points) +
               " exceeds points = " + std::to_string(s.points),
           "expected slab_points <= points");
  }
}

}  // namespace vivp::scene::detail
