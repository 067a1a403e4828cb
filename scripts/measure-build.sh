#!/usr/bin/env bash
# Measures the compile-time figures of docs/development.md from a clean clone
# of one revision, with the packages already installed:
#   1. the `vivp` target from scratch,
#   2. the rest of the Release build (so 1 + 2 = the whole build),
#   3. adding one Lagrangian file, rebuilding `vivp` and running
#      `vivp converge` on it.
# Each compiler invocation's wall time goes to per-file.tsv (seconds, file,
# start, end), slowest first, so that the next cut starts from the biggest
# file; the start and end times show where a core sat idle.
#
#   scripts/measure-build.sh [REVISION] [WORKDIR]     (default HEAD, /tmp/vivp-measure)
set -euo pipefail
repo=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)
rev=${1:-HEAD}
work=${2:-/tmp/vivp-measure}
jobs=${JOBS:-$(nproc)}
cxx=$(command -v clang++ || command -v c++)

rm -rf "$work"
mkdir -p "$work"
git clone -q "$repo" "$work/src"
git -C "$work/src" checkout -q "$rev"

# A launcher that records each compilation's wall time.
cat >"$work/timed" <<'LAUNCH'
#!/usr/bin/env bash
start=$(date +%s.%N)
"$@"
rc=$?
end=$(date +%s.%N)
src=""
for a in "$@"; do case "$a" in *.cc|*.cpp|*.cxx) src=$a ;; esac; done
printf '%.1f\t%s\t%s\t%s\n' "$(echo "$end - $start" | bc)" "${src##*/vivp-measure*/src/}" \
  "$start" "$end" >>"$VIVP_TIMING_LOG"
exit $rc
LAUNCH
chmod +x "$work/timed"
export VIVP_TIMING_LOG="$work/per-file.raw"

cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_COMPILER_LAUNCHER="$work/timed" >/dev/null

t0=$(date +%s.%N)
cmake --build "$work/build" -j "$jobs" --target vivp >/dev/null
t1=$(date +%s.%N)
cmake --build "$work/build" -j "$jobs" >/dev/null
t2=$(date +%s.%N)

# One Lagrangian file, as the README's "Add a Lagrangian" writes it.
cat >"$work/src/lagrangians/trial_spring.cc" <<'CC'
#include "lagrangians/register.h"

struct TrialSpring {
  static constexpr int kDim = 1;
  double k = 2.0;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return 0.5 * v[0] * v[0] - 0.5 * k * x[0] * x[0];
  }
};

namespace {
const bool registered = vivp::Register<TrialSpring>({
    .name = "trial_spring",
    .description = "harmonic spring with k = 2",
    .initial = {{1.0}, {0.0}},
    .parameters = {{"k", &TrialSpring::k}},
});
}  // namespace
CC
t3=$(date +%s.%N)
cmake --build "$work/build" -j "$jobs" --target vivp >/dev/null
"$work/build/apps/vivp" converge --problem trial_spring >"$work/trial.txt"
t4=$(date +%s.%N)

sort -rn "$work/per-file.raw" >"$work/per-file.tsv"
printf 'revision %s (%s), %s jobs, %s\n' "$(git -C "$work/src" rev-parse --short HEAD)" \
  "$rev" "$jobs" "$("$cxx" --version | head -1)"
printf 'vivp target          %6.1f s\n' "$(echo "$t1 - $t0" | bc)"
printf 'whole build          %6.1f s\n' "$(echo "$t2 - $t0" | bc)"
printf 'add Lagrangian→run   %6.1f s\n' "$(echo "$t4 - $t3" | bc)"
printf 'slowest files (of %s, %s s in all):\n' "$(wc -l <"$work/per-file.tsv")" \
  "$(awk '{s += $1} END {print s}' "$work/per-file.tsv")"
head -15 "$work/per-file.tsv" | cut -f1,2
echo "$t0 $t1" >"$work/vivp-window"
