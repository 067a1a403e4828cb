// Text for the scene reader's messages (scene.h: "FILE:LINE:COL: what is
// wrong; what is expected") and for `vivp run --help`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vivp::scene::detail {

// "a, b, c".
std::string Join(const std::vector<std::string>& names);

// " (did you mean 'x'?)" when a valid name is close to the given one.
std::string Suggest(const std::string& given,
                    const std::vector<std::string>& valid);

// Messages are one line: control characters from the file are shown escaped.
std::string OneLine(std::string_view s);

// The text in single quotes, on one line.
std::string Quote(const std::string& s);

// "1 finite number", "3 finite numbers".
std::string FiniteNumbers(int n);

// The number as a stream writes it (six significant digits).
std::string FormatNumber(double v);

}  // namespace vivp::scene::detail
