#!/usr/bin/env python3
"""Runs every shipped field scene with two vivp binaries, keeping every slice
(stride = 1), and compares the fields slice by slice: the largest difference
of φ and φ_t relative to the largest |φ| and |φ_t|, apart for the slices
where two windows meet and for all the others (a change of the junction
convention shows in the first, a change of the solve in both).

Usage: compare-field-slices.py BEFORE_VIVP AFTER_VIVP
Prints one markdown row per scene.
"""
import os
import re
import subprocess
import sys
import tempfile

src = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
scenes = sorted(f for f in os.listdir(os.path.join(src, 'scenes'))
                if f.startswith('field_') and f.endswith('.toml'))
if len(sys.argv) != 3:
    sys.exit(__doc__)
binaries = [os.path.abspath(b) for b in sys.argv[1:]]


def load(path):
    with open(path) as f:
        next(f)
        return [[float(x) for x in line.split(',')] for line in f if line.strip()]


print('| scene | slices × points | other slices: φ | φ_t | window junctions '
      '| junctions: φ | φ_t |')
print('|---|---|---|---|---|---|---|')
with tempfile.TemporaryDirectory() as tmp:
    for scene in scenes:
        text = open(os.path.join(src, 'scenes', scene)).read()
        text = re.sub(r'(?m)^stride = .*$', 'stride = 1', text)
        w = re.search(r'(?m)^window_points = (\d+)', text)
        window = int(w.group(1)) if w else 0
        toml = os.path.join(tmp, scene)
        open(toml, 'w').write(text)
        fields = []
        for i, vivp in enumerate(binaries):
            out = os.path.join(tmp, f'{scene}.{i}')
            subprocess.run([vivp, 'run', '--quiet', toml, '--out', out],
                           check=True, stdout=subprocess.DEVNULL)
            fields.append(load(os.path.join(out, 'field.csv')))
        before, after = fields
        if len(before) != len(after):
            print(f'| {scene} | different sizes: {len(before)} and '
                  f'{len(after)} rows | | | | | |')
            continue
        nt = len({r[0] for r in before})
        nx = len(before) // nt
        junction = {k for k in range(1, nt - 1)
                    if window > 1 and k % (window - 1) == 0}
        sp = max(abs(r[2]) for r in before) or 1
        sv = max(abs(r[3]) for r in before) or 1
        worst = {True: [0.0, 0.0], False: [0.0, 0.0]}
        for i, (b, a) in enumerate(zip(before, after)):
            w = worst[i // nx in junction]
            w[0] = max(w[0], abs(b[2] - a[2]) / sp)
            w[1] = max(w[1], abs(b[3] - a[3]) / sv)
        print(f'| {scene[:-5]} | {nt} × {nx} | {worst[False][0]:.1e} | '
              f'{worst[False][1]:.1e} | {len(junction)} | '
              f'{worst[True][0]:.1e} | {worst[True][1]:.1e} |')
