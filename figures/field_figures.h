// What the field figures (fig_fields_*.cc) share: a run's grid and its key
// in a plot, and line styles under which coinciding curves all stay
// visible.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace vivp::figures {

// nx spatial points and nt time points on [0, t_end].
struct FieldRun {
  int nx;
  long long nt;
  // "200 points, Δt = 0.02"
  std::string Key(double t_end) const {
    char key[64];
    std::snprintf(key, sizeof key, "%d points, Δt = %g", nx,
                  t_end / double(nt - 1));
    return key;
  }
};

// gnuplot "with" clauses, the first curve thickest and each later one
// thinner on top of it: the error of two time steps that agree (a spatial
// error) shows as a thin line inside a thick one.
inline std::vector<std::string> ThickUnderThin(
    const std::string& with = "lines") {
  return {with + " lw 6 lc '#fdae61'", with + " lw 2.5 lc '#1a9641'",
          with + " lw 1.5 lc '#2c7bb6'", with + " lw 2 lc '#7b3294'"};
}

}  // namespace vivp::figures
