#!/usr/bin/env bash
# Strong scaling of the march across ranks (docs/distributed.md §5): the
# periodic sine-Gordon ring (scenes/field2d_ring_periodic.toml) on N × N
# points to t = T, on one process without MPI (the predictor-started march)
# and with `mpirun -np P` for P = 1, 2; the median of RUNS solves of each
# (seconds.solve of summary.json), runs interleaved so that load on the
# machine falls on all alike; the speed-up and efficiency are P = 1's median
# over P's. A table, no pass/fail.
# Usage: distributed_scaling.sh VIVP MPIRUN_SH SCENE [N] [T] [RUNS]
set -euo pipefail
vivp=$1 mpirun=$2 scene=$3 n=${4:-256} t_end=${5:-2.0} runs=${6:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
points=$(python3 -c "print(int(round($t_end * 30)) + 1)")
sed -e "s/^points = \[128, 128\]/points = [$n, $n]/" \
    -e "s/^end = .*/end = $t_end/" -e "s/^points = 361/points = $points/" \
    -e "s/^heat_maps = .*/heat_maps = []/" -e "s/^animation = true/animation = false/" \
    "$scene" > "$tmp/scene.toml"
for r in $(seq "$runs"); do
  "$vivp" run "$tmp/scene.toml" --out "$tmp/serial$r" --quiet > /dev/null
  for p in 1 2; do
    bash "$mpirun" -np "$p" "$vivp" run "$tmp/scene.toml" --out "$tmp/p$p.$r" \
      --quiet > /dev/null
  done
done
python3 - "$tmp" "$runs" "$n" "$t_end" <<'PY'
import json, statistics, sys
tmp, runs, n, t_end = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
def load(name):
    return [json.load(open(f"{tmp}/{name}{r}/summary.json")) for r in range(1, runs + 1)]
rows = [("one process (predictor)", load("serial")), ("mpirun -np 1", load("p1.")),
        ("mpirun -np 2", load("p2."))]
print(f"ring on {n}² to t = {t_end}, SBP42 windows of 16; median of {runs} runs")
print("| run | solve s | Newton steps | residuals s | factor s | solves s | hand-off s | speed-up | efficiency |")
print("|---|---|---|---|---|---|---|---|---|")
base = statistics.median(s["seconds"]["solve"] for s in rows[1][1])
for name, ss in rows:
    med = lambda k: statistics.median(s["seconds"][k] for s in ss)
    ranks = max(1, ss[0]["solver"].get("ranks", 0))
    solve = med("solve")
    up = base / solve
    eff = f"{up / ranks:.2f}" if name.startswith("mpirun") else "—"
    print(f"| {name} | {solve:.2f} | {ss[0]['solver']['corrections']} | "
          f"{med('residuals'):.2f} | {med('factorizations'):.2f} | "
          f"{med('linear_solves'):.2f} | {med('handoff'):.2f} | "
          f"{up:.2f} | {eff} |")
PY
