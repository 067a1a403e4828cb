#include "solvers/bea/conservation.h"

#include <cmath>
#include <stdexcept>

namespace vivp::bea {
namespace {

// "H4", "I2": appended, not "H" + std::string (GCC 12 false -Wrestrict,
// bug 105329).
std::string Name(char c, int p) {
  std::string s(1, c);
  s += std::to_string(p);
  return s;
}

}  // namespace

DeviationSeries Deviations(const BeaResult& r, const ModifiedQuantities& q,
                           const NumericPotential& potential,
                           const ConservationSetup& setup, double h) {
  const int N = r.order;
  DeviationSeries s;
  for (int p = 0; p <= N; p += 2) s.names.push_back(Name('H', p));
  if (q.has_charge())
    for (int p = 0; p <= N; p += 2) s.names.push_back(Name('I', p));
  MultistepOptions o;
  o.h = h;
  o.steps = static_cast<int>(std::lround(setup.t_end / h));
  o.difference_order = setup.difference_order;
  o.start_order = setup.start_order < 0 ? N : setup.start_order;
  o.rk_substeps = setup.rk_substeps;
  s.run = RunMultistep(NumericCoefficients(r.method), potential, q, setup.x0,
                       setup.v0, o);
  const int first = s.run.first_velocity, last = s.run.last_velocity;
  const int rows = last - first + 1;
  const int cols = static_cast<int>(s.names.size());
  std::vector<double> reference;
  for (int p = 0; p <= N; p += 2)
    reference.push_back(q.Hamiltonian(p, h, setup.x0.data(), setup.v0.data()));
  if (q.has_charge())
    for (int p = 0; p <= N; p += 2)
      reference.push_back(q.Charge(p, h, setup.x0.data(), setup.v0.data()));
  s.t.resize(rows);
  s.deviation.resize(rows, cols);
  const int d = q.dim();
  Eigen::VectorXd x(d), v(d);
  for (int n = first; n <= last; ++n) {
    x = s.run.x.row(n).transpose();
    v = s.run.v.row(n).transpose();
    s.t(n - first) = n * h;
    int c = 0;
    for (int p = 0; p <= N; p += 2, ++c)
      s.deviation(n - first, c) =
          q.Hamiltonian(p, h, x.data(), v.data()) - reference[c];
    if (q.has_charge())
      for (int p = 0; p <= N; p += 2, ++c)
        s.deviation(n - first, c) =
            q.Charge(p, h, x.data(), v.data()) - reference[c];
  }
  return s;
}

double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 2 || y.size() != n)
    throw std::invalid_argument("a slope needs at least two points");
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += std::log(x[i]) / n;
    my += std::log(y[i]) / n;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

Sweep ConservationSweep(const BeaResult& r, const ModifiedQuantities& q,
                        const NumericPotential& potential,
                        const ConservationSetup& setup,
                        const std::vector<double>& steps) {
  Sweep sweep;
  for (double h : steps) {
    auto s = Deviations(r, q, potential, setup, h);
    sweep.names = s.names;
    SweepRow row{h, static_cast<int>(s.run.x.rows()) - 1, {}};
    for (int c = 0; c < s.deviation.cols(); ++c)
      row.max_deviation.push_back(s.deviation.col(c).cwiseAbs().maxCoeff());
    sweep.rows.push_back(row);
  }
  std::vector<double> hs;
  for (const auto& row : sweep.rows) hs.push_back(row.h);
  for (std::size_t c = 0; c < sweep.names.size() && hs.size() >= 2; ++c) {
    std::vector<double> y;
    for (const auto& row : sweep.rows) y.push_back(row.max_deviation[c]);
    sweep.slopes.push_back(LogLogSlope(hs, y));
  }
  return sweep;
}

}  // namespace vivp::bea
