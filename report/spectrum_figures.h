// Figures of the spectrum analysis (Rothkopf & Nordström 2023, Figs. 3-4),
// shared by the figure programs and `vivp spectrum --plot`.
#pragma once

#include <filesystem>
#include <string>

#include "core/linalg/spectrum.h"

namespace vivp::report {

// Fig. 3: right (constant) and left (pi-mode) null vectors of D against the
// node index. Returns the PNG path.
std::filesystem::path NullVectorFigure(const linalg::Spectrum& d,
                                       const std::string& op_name, int points,
                                       const std::filesystem::path& dir);

// Fig. 4: eigenvalues of D and D̄ in the complex plane, with an inset zoomed on
// the cluster that the Jordan block of the zero eigenvalue of D leaves behind.
std::filesystem::path SpectrumFigure(const linalg::Spectrum& d,
                                     const linalg::Spectrum& dbar,
                                     const std::string& op_name, int points,
                                     const std::filesystem::path& dir);

}  // namespace vivp::report
