#!/usr/bin/env bash
# Prints what vivp's commands print for a fixed set of runs — point
# mechanics (converge, run, bench at fixed steps, bea verify) and fields
# (converge --field, the field scenes) — into DIR, one file per run, so that
# two builds can be compared number by number (scripts/compare-numbers.py).
# Wall times differ from run to run; everything else must not.
#
# Usage: compare-outputs.sh VIVP_BINARY DIR
set -uo pipefail
vivp=$(realpath "$1")
out=$2
mkdir -p "$out"
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

run() {  # NAME ARGS...
  local name=$1
  shift
  (cd "$tmp" && "$vivp" "$@") >"$out/$name.txt" 2>&1
  echo "exit $?" >>"$out/$name.txt"
}

for p in anharmonic coupled cyclotron damped exponential freefall kepler \
         pendulum; do
  for op in sbp21 sbp42 sbp63 sbp84; do
    run "converge-$p-$op" converge --problem "$p" --operator "$op"
  done
  run "converge-$p-sbp42-march" converge --problem "$p" --slab-points 48 \
    --points 64,128,256,512,1024 --t-end 4
done
run converge-kepler_e09-tol converge --problem kepler_e09 --tolerance \
  1e-4,1e-6,1e-8 --t-end 6.283185307179586
run converge-anharmonic-tol-sbp84 converge --problem anharmonic --operator \
  sbp84 --tolerance 1e-6,1e-9 --t-end 10
run converge-anharmonic-lm converge --problem anharmonic --solver ceres-lm
run converge-anharmonic-full converge --problem anharmonic --solver full-newton
for scene in "$src"/scenes/*.toml; do
  name=$(basename "$scene" .toml)
  run "run-$name" run "$scene" --out "$name" --force
  [[ -f $tmp/$name/summary.json ]] && cp "$tmp/$name/summary.json" \
    "$out/run-$name.summary.json"
done
run bench-kepler_e09 bench --problem kepler_e09 --methods \
  variational_sbp42,variational_sbp84,gauss2,verlet --steps \
  2000,4000 --repeats 5
run bench-anharmonic bench --problem anharmonic --steps 256,512 --repeats 5
run bea-verify-sv bea verify --steps 0.2,0.1 --t-end 20 --potential pendulum --x0 1 --v0 0
run bea-verify-lmm4 bea verify --method lmm4 --alpha -0.2 --dim 2 --steps 0.15,0.1 \
  --t-end 20 --potential gaussian --x0 1,-1 --v0 0.1,-0.2
for f in klein_gordon sine_gordon_breather sine_gordon_kink wave_gaussian; do
  for op in sbp21 sbp42; do
    run "converge-field-$f-$op" converge --field "$f" --operator "$op" \
      --slab-points 16
  done
done
run converge-field-breather-space converge --field sine_gordon_breather \
  --points 65 --space-points 40,80,160 --slab-points 16
