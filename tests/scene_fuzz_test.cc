// Mutation test of the scene reader: the shipped scenes (field scenes
// too) and the default scene, mutated at random — bytes deleted, inserted or
// flipped, lines dropped, doubled or swapped, numbers and names replaced by
// extreme or wrong ones — must each be read or rejected with a SceneError; any
// other exception, a crash or a sanitizer report fails. Mutants that read and
// are small are also solved, which must end in a result or a clean exception,
// never a crash.
//
// VIVP_FUZZ_COUNT sets the number of mutants (default 3000, what CI runs);
// the note's full run is VIVP_FUZZ_COUNT=100000 under ASan/UBSan.
#define BOOST_TEST_MODULE scene_fuzz
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>

#include "scene/field_scene.h"
#include "scene/run.h"
#include "scene/scene.h"

using namespace vivp::scene;

namespace {

std::vector<std::string> Seeds() {
  std::vector<std::string> seeds = {std::string(DefaultSceneText())};
  for (const auto& e : std::filesystem::directory_iterator(VIVP_SCENES_DIR)) {
    std::ifstream in(e.path());
    seeds.emplace_back((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
  }
  return seeds;
}

const std::vector<std::string> kValues = {"0",
                                          "-1",
                                          "1",
                                          "1e308",
                                          "-1e308",
                                          "inf",
                                          "-inf",
                                          "nan",
                                          "1e-320",
                                          "9223372036854775807",
                                          "-9223372036854775808",
                                          "99999999999999999999",
                                          "0.0",
                                          "3",
                                          "2.5",
                                          "\"x\"",
                                          "[]",
                                          "[[]]",
                                          "[1.0, 2.0, 3.0]",
                                          "{}",
                                          "true",
                                          "\"\"",
                                          "[[1.0, 0.0], [0.0, 1.0]]",
                                          "1979-05-27",
                                          "4194305",
                                          "1e6",
                                          "100000000000"};
const std::vector<std::string> kNames = {"kinetic",
                                         "gravity",
                                         "spring",
                                         "quartic",
                                         "pendulum",
                                         "central",
                                         "gaussian_well",
                                         "chain",
                                         "damping",
                                         "growth",
                                         "cyclotron",
                                         "breather",
                                         "kink",
                                         "gaussian",
                                         "natural",
                                         "sine_gordon",
                                         "phi4",
                                         "variational",
                                         "rk4",
                                         "midpoint",
                                         "verlet",
                                         "gauss2",
                                         "gauss3",
                                         "triple_jump",
                                         "suzuki",
                                         "triple_jump6",
                                         "discrete_gradient",
                                         "sbp21",
                                         "sbp84",
                                         "ceres-lm",
                                         "full-newton",
                                         "exact",
                                         "ode",
                                         "none",
                                         "energy",
                                         "momentum",
                                         "angular_momentum",
                                         "error",
                                         "",
                                         "kinetic\"",
                                         "x\ny"};

class Mutator {
 public:
  explicit Mutator(unsigned seed) : rng_(seed) {}

  std::string Mutate(std::string s) {
    const int n = 1 + Pick(4);
    for (int k = 0; k < n; ++k) s = Once(std::move(s));
    return s;
  }

 private:
  std::size_t Pick(std::size_t n) {
    return n == 0 ? 0
                  : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
  }

  std::vector<std::string> Lines(const std::string& s) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= s.size()) {
      const std::size_t end = s.find('\n', start);
      out.push_back(s.substr(
          start, end == std::string::npos ? std::string::npos : end - start));
      if (end == std::string::npos) break;
      start = end + 1;
    }
    return out;
  }
  static std::string Join(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
  }

  // Replaces a random token matched by `pattern` with `with`.
  std::string ReplaceToken(const std::string& s, const std::regex& pattern,
                           const std::string& with) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    for (auto it = std::sregex_iterator(s.begin(), s.end(), pattern);
         it != std::sregex_iterator(); ++it)
      spans.push_back({std::size_t(it->position()), std::size_t(it->length())});
    if (spans.empty()) return s;
    const auto [pos, len] = spans[Pick(spans.size())];
    return s.substr(0, pos) + with + s.substr(pos + len);
  }

  std::string Once(std::string s) {
    static const std::regex number(R"(-?\d+(\.\d+)?([eE][-+]?\d+)?)");
    static const std::regex name(R"("[a-z_0-9-]*")");
    switch (Pick(9)) {
      case 0:  // delete a byte range
        if (!s.empty()) {
          const std::size_t p = Pick(s.size());
          s.erase(p, 1 + Pick(8));
        }
        return s;
      case 1: {  // insert random bytes
        std::string junk;
        for (std::size_t k = 0, n = 1 + Pick(6); k < n; ++k)
          junk += char(Pick(256));
        s.insert(Pick(s.size() + 1), junk);
        return s;
      }
      case 2:  // flip a byte
        if (!s.empty()) s[Pick(s.size())] ^= char(1 << Pick(8));
        return s;
      case 3: {  // drop a line
        auto l = Lines(s);
        l.erase(l.begin() + long(Pick(l.size())));
        return Join(l);
      }
      case 4: {  // double a line
        auto l = Lines(s);
        const std::size_t i = Pick(l.size());
        l.insert(l.begin() + long(Pick(l.size() + 1)), l[i]);
        return Join(l);
      }
      case 5: {  // swap two lines
        auto l = Lines(s);
        std::swap(l[Pick(l.size())], l[Pick(l.size())]);
        return Join(l);
      }
      case 6:
        return ReplaceToken(s, number, kValues[Pick(kValues.size())]);
      case 7:
        return ReplaceToken(s, name, "\"" + kNames[Pick(kNames.size())] + "\"");
      default:  // truncate
        return s.substr(0, Pick(s.size() + 1));
    }
  }

  std::mt19937 rng_;
};

class NullSink : public RunSink {
 public:
  void Begin(const RunLayout&) override {}
  void Node(double, const double*, const double*, const double*) override {}
};

long Count() {
  const char* env = std::getenv("VIVP_FUZZ_COUNT");
  return env ? std::atol(env) : 3000;
}

}  // namespace

BOOST_AUTO_TEST_CASE(MutatedScenes_AreReadOrRejectedCleanly) {
  const auto seeds = Seeds();
  Mutator mutate(20261123);
  const std::regex form(R"(^.+:\d+:\d+: [^\n]+; expected [^\n]+$)");
  long read = 0, rejected = 0, solved = 0, failed_cleanly = 0;
  const long count = Count();
  for (long i = 0; i < count; ++i) {
    const std::string text =
        mutate.Mutate(seeds[std::size_t(i) % seeds.size()]);
    AnyScene any;
    try {
      any = ParseAnyScene(text, "mutant.toml");
      ++read;
    } catch (const SceneError& e) {
      ++rejected;
      if (!std::regex_match(e.what(), form))
        BOOST_ERROR(
            "message not of the form FILE:LINE:COL: ...; expected "
            "...: "
            << e.what() << "\n--- input ---\n"
            << text);
      continue;
    } catch (const std::exception& e) {
      BOOST_ERROR("not a SceneError: " << e.what() << "\n--- input ---\n"
                                       << text);
      continue;
    }
    // Field scenes: the reader only (their solves are field_cli_test's).
    if (!std::holds_alternative<Scene>(any)) continue;
    Scene scene = std::get<Scene>(std::move(any));
    // Solve the small ones (the reference is the reader's business only).
    // Under error control the march chooses the nodes: a short span only
    // (the shipped Kepler e = 0.9 scene takes 97518 nodes over ten orbits).
    if (scene.points > 400 || scene.t_end - scene.t_start > 1e4) continue;
    if (scene.method.tolerance.enabled() && scene.t_end - scene.t_start > 2)
      continue;
    scene.output.reference = "none";
    scene.output.diagnostics.erase(
        std::remove(scene.output.diagnostics.begin(),
                    scene.output.diagnostics.end(), "error"),
        scene.output.diagnostics.end());
    try {
      NullSink sink;
      RunScene(scene, sink);
      ++solved;
    } catch (const std::exception&) {
      ++failed_cleanly;  // e.g. a non-finite state the solver refused
    }
  }
  BOOST_TEST_MESSAGE(count << " mutants: " << read << " read, " << rejected
                           << " rejected; of the read ones " << solved
                           << " solved, " << failed_cleanly
                           << " ended in an exception");
  BOOST_TEST(read + rejected == count);
  BOOST_TEST(rejected > 0);
  BOOST_TEST(read > 0);
}
