#!/usr/bin/env bash
# `mpirun -np N vivp run SCENE` (docs/distributed.md): a sine-Gordon ring on
# a periodic 32 × 32 grid marched on 1 and 2 ranks gives the same field.h5
# to 1e-12 of the field's size, slice by slice; and every refusal of a run
# across ranks — a grid that does not divide, slabs thinner than the halo, a
# field on one axis, an interval axis, an output directory that exists, a
# point scene, another command —
# exits 2 with one line naming the fix, writing nothing.
# Usage: distributed_cli_test.sh VIVP MPIRUN_SH
set -euo pipefail
vivp=$1
mpirun=(bash "$2")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

scene() {  # scene FILE POINTS BOUNDARY [SPACE]
  local space=${4:-space_order = 4}
  cat > "$1" <<TOML
title = "sine-Gordon ring on a periodic grid"
[field]
domain = [[-8.0, 8.0], [-8.0, 8.0]]
points = $2
boundary = "$3"
$space
[[term]]
type = "kinetic"
[[term]]
type = "gradient"
[[term]]
type = "sine_gordon"
[initial]
profile = "ring"
radius = 3.0
center = [0.0, 0.0]
[time]
end = 1.5
points = 46
[method]
operator = "sbp42"
window_points = 8
[output]
format = "hdf5"
diagnostics = ["energy"]
TOML
}

scene "$tmp/ring.toml" "[32, 32]" periodic
"${mpirun[@]}" -np 1 "$vivp" run "$tmp/ring.toml" --out "$tmp/one" > "$tmp/one.txt"
"${mpirun[@]}" -np 2 "$vivp" run "$tmp/ring.toml" --out "$tmp/two" > "$tmp/two.txt"
grep -q "space on 1 rank" "$tmp/one.txt"
grep -q "space on 2 ranks" "$tmp/two.txt"
for d in one two; do
  h5dump -d /phi -m %.17g -y -w 0 "$tmp/$d/field.h5" |
    sed -n '/DATA {/,/}/p' | tr ',' '\n' | grep -Eo -- '-?[0-9][0-9.e+-]*' \
      > "$tmp/$d.values"
done
python3 - "$tmp/one.values" "$tmp/two.values" <<'PY'
import sys
a = [float(v) for v in open(sys.argv[1])]
b = [float(v) for v in open(sys.argv[2])]
assert len(a) == len(b) and len(a) > 32 * 32, (len(a), len(b))
size = max(1.0, max(abs(v) for v in a))
worst = max(abs(x - y) for x, y in zip(a, b))
print(f"1 rank vs 2 ranks: {len(a)} values, largest difference {worst:.3g} "
      f"(field size {size:.3g})")
assert worst <= 1e-12 * size, worst
PY

# refuse NAME NP EXPECTED ARGS…: exit 2, one line containing EXPECTED, no
# output directory.
refuse() {
  local name=$1 np=$2 expected=$3
  shift 3
  set +e
  "${mpirun[@]}" -np "$np" "$vivp" "$@" > /dev/null 2> "$tmp/$name.err"
  local status=$?
  set -e
  if [[ $status -ne 2 ]] || ! grep -q -- "$expected" "$tmp/$name.err" ||
     [[ -e $tmp/$name ]]; then
    echo "FAIL $name: status $status, expected 2 and '$expected':" >&2
    cat "$tmp/$name.err" >&2
    exit 1
  fi
  echo "ok $name: $(grep -m1 -- "$expected" "$tmp/$name.err")"
}
refuse not_dividing 3 "must divide by the 3 ranks" run "$tmp/ring.toml" \
  --out "$tmp/not_dividing"
scene "$tmp/thin.toml" "[32, 12]" periodic
refuse thin_slabs 4 "use at most 3 ranks" run "$tmp/thin.toml" \
  --out "$tmp/thin_slabs"
scene "$tmp/interval.toml" "[32, 32]" natural 'space_operator = "sbp42"'
refuse interval 2 "every axis must be periodic" run "$tmp/interval.toml" \
  --out "$tmp/interval"
cat > "$tmp/line.toml" <<'TOML'
[field]
domain = [0.0, 6.0]
points = 32
boundary = "natural"
space_operator = "sbp42"
[[term]]
type = "kinetic"
[[term]]
type = "gradient"
[initial]
profile = "gaussian"
[time]
end = 1.0
points = 33
TOML
refuse one_axis 2 "one axis runs on one process" run "$tmp/line.toml" \
  --out "$tmp/one_axis"
refuse point_scene 2 "point-mechanics scene runs on one process" run \
  --out "$tmp/point_scene"
refuse output_exists 2 "--force" run "$tmp/ring.toml" --out "$tmp/one"
refuse other_command 2 "only \`vivp run\` of a field scene" converge \
  --problem harmonic
echo "distributed CLI: all checks passed"
