// Fig. 3 of Rothkopf & Nordström (2023): the right and left null vectors of
// the unregularized SBP21 operator at N_t = 32. The left one is the
// oscillating pi-mode (1, -2, 2, ..., 2, -1) that the kinetic term D^T H D
// cannot see. Usage: fig03_null_vectors [OUTPUT_DIR]
#include <iostream>

#include "core/sbp/builder.h"
#include "report/spectrum_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const auto d = vivp::sbp::MakeOperator<double>("sbp21", 32);
  const vivp::linalg::Spectrum s = vivp::linalg::AnalyzeSpectrum(d.DenseD());
  std::cout << vivp::report::NullVectorFigure(s, "SBP21", 32, dir).string()
            << "\n";
}
