// `vivp spectrum`: eigenvalues, singular values and the Jordan structure of the
// zero eigenvalue of an SBP operator D, and the same for the regularized D̄.
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "core/linalg/spectrum.h"
#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "report/spectrum_figures.h"

namespace vivp::apps {
namespace {

struct SpectrumOptions {
  std::string op = "sbp21";
  long long points = 32;
  double sigma0 = -1.0;
  double t_end = 1.0;
  std::string json;
  std::string plot;
  bool force = false;
};

nlohmann::json ComplexList(const std::vector<std::complex<double>>& z) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : z) out.push_back({v.real(), v.imag()});
  return out;
}

std::vector<double> ToStd(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

nlohmann::json SpectrumJson(const linalg::Spectrum& s) {
  return {{"eigenvalues", ComplexList(s.eigenvalues)},
          {"singular_values", ToStd(s.singular_values)},
          {"zero_modes", s.zero.algebraic_multiplicity},
          {"geometric_multiplicity", s.zero.geometric_multiplicity},
          {"kernel_dimensions", s.zero.kernel_dimensions},
          {"zero_tolerance", s.zero.tolerance},
          {"right_null_vector", ToStd(s.right_null_vector)},
          {"left_null_vector", ToStd(s.left_null_vector)},
          {"min_abs_eigenvalue", s.min_abs_eigenvalue},
          {"min_real_part", s.min_real_part},
          {"real_eigenvalues", s.real_eigenvalues}};
}

// The first few entries of v scaled so that its first entry is 1.
std::string Pattern(const Eigen::VectorXd& v) {
  std::ostringstream out;
  out << "(";
  const Eigen::Index n = v.size();
  auto put = [&](Eigen::Index i) {
    out << std::setprecision(3) << v[i] / v[0];
  };
  for (Eigen::Index i = 0; i < std::min<Eigen::Index>(n, 4); ++i) {
    if (i) out << ", ";
    put(i);
  }
  if (n > 6) out << ", ...";
  for (Eigen::Index i = std::max<Eigen::Index>(4, n - 2); i < n; ++i) {
    out << ", ";
    put(i);
  }
  out << ")";
  return out.str();
}

void PrintSummary(std::ostream& out, const SpectrumOptions& o,
                  const sbp::Operator<double>& d, const linalg::Spectrum& sd,
                  const linalg::Spectrum& sdbar) {
  out << std::setprecision(4) << d.name() << " at N = " << d.points()
      << " on [0, " << o.t_end << "], dt = " << d.dt()
      << ", sigma0 = " << o.sigma0 << "\n";
  out << "  D : zero eigenvalue of algebraic multiplicity "
      << sd.zero.algebraic_multiplicity << ", geometric multiplicity "
      << sd.zero.geometric_multiplicity << " (dim ker D^k =";
  for (int k : sd.zero.kernel_dimensions) out << " " << k;
  out << "; zero tolerance " << sd.zero.tolerance << ")\n";
  out << "      eigensolver leaves the split zero at |nu| <= ";
  double cluster = 0;
  for (int i = 0; i < sd.zero.algebraic_multiplicity; ++i)
    cluster = std::max(cluster, std::abs(sd.eigenvalues[i]));
  out << cluster << " (1/dt = " << 1 / d.dt() << ")\n";
  if (sd.right_null_vector.size() > 0) {
    out << "      right null vector ~ " << Pattern(sd.right_null_vector)
        << "\n";
    out << "      left null vector  ~ " << Pattern(sd.left_null_vector) << "\n";
  }
  out << "  D̄ : " << sdbar.zero.algebraic_multiplicity
      << " zero modes, min |nu| = " << sdbar.min_abs_eigenvalue
      << ", min Re nu = " << sdbar.min_real_part << ", real eigenvalues:";
  for (double r : sdbar.real_eigenvalues) out << " " << r;
  out << "\n";
}

int RunSpectrum(const SpectrumOptions& o) {
  if (!o.json.empty() && o.json != "-") CheckOutputFile(o.json, o.force);
  if (!o.plot.empty()) CheckOutputDirectory(o.plot, o.force);
  if (o.points > 4000)
    throw UsageError("--points " + std::to_string(o.points) +
                     " is too large for a dense spectrum analysis; use at most "
                     "4000");

  const auto d = sbp::MakeOperator<double>(o.op, o.points, 0.0, o.t_end);
  const sbp::RegularizedOperator<double> dbar(d, o.sigma0);
  const linalg::Spectrum sd = linalg::AnalyzeSpectrum(d.DenseD());
  // The shift column does not change the spectrum; x_i = 1 for definiteness.
  const linalg::Spectrum sdbar =
      linalg::AnalyzeSpectrum(dbar.AffineMatrix(1.0));

  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  PrintSummary(human, o, d, sd, sdbar);

  if (!o.json.empty()) {
    const nlohmann::json j = {{"operator", std::string(d.name())},
                              {"citation", std::string(d.citation())},
                              {"points", d.points()},
                              {"t_start", 0.0},
                              {"t_end", o.t_end},
                              {"sigma0", o.sigma0},
                              {"D", SpectrumJson(sd)},
                              {"Dbar", SpectrumJson(sdbar)}};
    WriteJson(o.json, j);
    if (o.json != "-") human << "  wrote " << o.json << "\n";
  }
  if (!o.plot.empty()) {
    const std::string label = std::string(d.name());
    human
        << "  wrote "
        << report::NullVectorFigure(sd, label, d.points(), o.plot).string()
        << "\n  wrote "
        << report::SpectrumFigure(sd, sdbar, label, d.points(), o.plot).string()
        << "\n";
  }
  return 0;
}

}  // namespace

Runner AddSpectrumCommand(CLI::App& app) {
  auto o = std::make_shared<SpectrumOptions>();
  CLI::App* cmd = app.add_subcommand(
      "spectrum",
      "Spectrum of an SBP operator D and of its regularization D̄ "
      "(zero modes by ranks of D, D^2, ...; paper Figs. 3-4)");
  cmd->add_option("--operator", o->op, "SBP operator")
      ->check(CLI::IsMember(sbp::OperatorNames()))
      ->capture_default_str();
  // "2, 8, 12, 16" and "sbp21 2, sbp42 8, sbp63 12, sbp84 16".
  std::string minima, named_minima;
  for (const sbp::Coefficients* c : sbp::Operators()) {
    const std::string n = std::to_string(c->min_points);
    minima += (minima.empty() ? "" : ", ") + n;
    named_minima +=
        (named_minima.empty() ? "" : ", ") + std::string(c->name) + " " + n;
  }
  cmd->add_option("--points", o->points,
                  "number of time points N (at least " + minima + " for " +
                      sbp::OperatorNameList() + ")")
      ->check(WholeNumberAtLeast(
          1,
          ">= 1 (time points; the operator's minimum: " + named_minima + ")"))
      ->capture_default_str();
  cmd->add_option("--sigma0", o->sigma0,
                  "SAT penalty parameter of D̄ (the paper uses -1)")
      ->check(FiniteNumber())
      ->capture_default_str();
  cmd->add_option("--t-end", o->t_end, "end of the time interval [0, T]")
      ->check(FiniteNumber())
      ->capture_default_str();
  cmd->add_option("--json", o->json,
                  "write the analysis as JSON (- for stdout)");
  cmd->add_option("--plot", o->plot,
                  "write Figs. 3-4 (PNG, data, gnuplot script) into this "
                  "directory");
  cmd->add_flag("--force", o->force, "overwrite existing output");
  return [o] { return RunSpectrum(*o); };
}

}  // namespace vivp::apps
