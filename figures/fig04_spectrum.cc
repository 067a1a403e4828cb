// Fig. 4 of Rothkopf & Nordström (2023): eigenvalues of SBP21 D and of the
// regularized D̄ (sigma0 = -1, affine coordinates) at N_t = 32. D̄ has no zero
// modes; the inset shows the pair near zero that the 2x2 Jordan block of D
// leaves in floating point. Usage: fig04_spectrum [OUTPUT_DIR]
#include <iostream>

#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "report/spectrum_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const auto d = vivp::sbp::MakeOperator<double>("sbp21", 32);
  const vivp::sbp::RegularizedOperator<double> dbar(d, -1.0);
  const vivp::linalg::Spectrum sd = vivp::linalg::AnalyzeSpectrum(d.DenseD());
  const vivp::linalg::Spectrum sdbar =
      vivp::linalg::AnalyzeSpectrum(dbar.AffineMatrix(1.0));
  std::cout
      << vivp::report::SpectrumFigure(sd, sdbar, "SBP21", 32, dir).string()
      << "\n";
}
