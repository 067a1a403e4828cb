#include "studies/charged_waves.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "solvers/spacetime/charged_march.h"
#include "solvers/variational/resolution.h"

namespace vivp::studies {

using System = action::ChargedFieldSystem<fields::ScalarQed, 1>;

ChargedData ChargedPair(const sbp::SpaceGrid<double>& line, double mass2) {
  constexpr int m = System::m;
  const double length = line.axis(0).dx() * line.points();
  const double k = 0.8, omega = std::sqrt(mass2 + k * k);
  ChargedData d{std::vector<double>(line.points() * m),
                std::vector<double>(line.points() * m)};
  const std::complex<double> I(0, 1);
  for (int j = 0; j < line.points(); ++j) {
    const double x = line.x(j, 0);
    const std::complex<double> wave = std::polar(1.0, k * x);
    const std::complex<double> p1 =
        0.5 * std::exp(-std::pow((x - 7) / 1.5, 2)) * wave;
    const std::complex<double> p2 =
        0.5 * std::exp(-std::pow((x - (length - 7)) / 1.5, 2)) * wave;
    const std::complex<double> phi = p1 + p2,
                               pi = -I * omega * p1 + I * omega * p2;
    d.phi[j * m + System::kRe] = phi.real();
    d.phi[j * m + System::kIm] = phi.imag();
    d.pi[j * m + System::kRe] = pi.real();
    d.pi[j * m + System::kIm] = pi.imag();
  }
  return d;
}

GaussSweep GaussSweepOf(bool quick) {
  if (quick) return {{"sbp42"}, {16}};
  return {{"sbp21", "sbp42", "sbp63"}, {8, 16, 32, 64}};
}

fields::ScalarQed StudyQed() {
  fields::ScalarQed model;
  model.mass2 = 1.0;
  model.coupling = [](double) { return 0.7; };
  return model;
}

ChargedGaussRun RunChargedGauss(const std::string& op, int window,
                                double fraction, int n, double t_end) {
  ChargedGaussRun r{.op = op, .window = window, .n = n, .fraction = fraction};
  const sbp::SpaceGrid<double> g(
      sbp::SpaceDerivative<double>::Periodic(2, n, 0.0, 20.0));
  const auto model = StudyQed();
  const double h = g.axis(0).dx();
  const double omega = std::sqrt(model.mass2 + 4 / (h * h));
  const double limit = fraction * variational::StabilityLimit(op) / omega;
  // Whole windows to t_end at a step no longer than the limit.
  r.windows = std::max(1, int(std::ceil(t_end / (limit * (window - 1)))));
  r.dt = t_end / (double(r.windows) * (window - 1));
  spacetime::ChargedMarchOptions o;
  o.time_operator = op;
  o.window = window;
  o.dt = r.dt;
  o.windows = r.windows;
  const auto data = ChargedPair(g, model.mass2);
  double e0 = NAN;
  const auto start = std::chrono::steady_clock::now();
  spacetime::ChargedMarch march;
  try {
    march = spacetime::MarchCharged<fields::ScalarQed, 1>(
        model, g, data.phi, data.pi, o,
        [&](const System& s, const std::vector<double>&,
            const action::ChargedNodes& nodes,
            const spacetime::ChargedSliceState& handed) {
          r.gauss =
              std::max(r.gauss, *std::max_element(nodes.gauss_action.begin(),
                                                  nodes.gauss_action.end()));
          r.textbook = std::max(r.textbook,
                                *std::max_element(nodes.gauss_textbook.begin(),
                                                  nodes.gauss_textbook.end()));
          r.textbook_absolute =
              std::max(r.textbook_absolute,
                       *std::max_element(nodes.textbook_absolute.begin(),
                                         nodes.textbook_absolute.end()));
          const double e = spacetime::SliceEnergy<1>(
              model, g, s.time_operator().base().t(s.time_points() - 1),
              handed);
          if (std::isnan(e0)) e0 = e;
          r.energy = std::max(r.energy, std::abs(e - e0) / e0);
        });
  } catch (const std::invalid_argument& e) {
    r.failure = e.what();  // a window below the operator's minimum, say
    return r;
  }
  r.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  for (const auto& w : march.windows) {
    r.newton += w.iterations;
    r.retries += w.retries;
  }
  if (!march.ok) r.failure = march.reason;
  return r;
}

}  // namespace vivp::studies
