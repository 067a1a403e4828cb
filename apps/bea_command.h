// Shared by the files of `vivp bea`: its options, what they make (the
// method, the options of the derivation, lists of numbers; bea_options.cc)
// and `vivp bea verify` (bea_verify.cc). Private to apps/.
#pragma once

#include <string>
#include <vector>

#include "solvers/bea/derivation.h"

namespace vivp::apps {

struct BeaOptions {
  std::string method = "sv";
  std::string alpha;   // number or symbol name
  std::string matrix;  // a11,a12,a22
  int dim = 0;         // 0: 2 with --matrix, else 1
  int order = 4;
  bool radial = false;
  bool in_w = false;
  std::string format = "text";
  // verify
  std::string steps;
  double t_end = 100;
  int differences = 6;
  std::string potential;
  std::string x0, v0;
  std::string json;
  bool force = false;
};

// The method of --method, --alpha, --matrix and --dim; sets o.dim when it
// is 0. Symbols met in the coefficients go into `symbols`.
bea::Method MakeBeaMethod(BeaOptions& o, GiNaC::symtab& symbols);

// The options of bea::Derive for `o`, with the radial model if `radial`.
bea::DeriveOptions BeaDeriveOptions(const BeaOptions& o, bool radial);

// Comma-separated finite numbers; `what` names the option in the error.
std::vector<double> ParseNumberList(const std::string& s,
                                    const std::string& what);

// `vivp bea verify`: the method run over a sweep of step sizes, the
// conservation of H_mod and I_mod measured.
int RunBeaVerify(BeaOptions o);

}  // namespace vivp::apps
