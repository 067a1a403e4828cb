#!/usr/bin/env python3
"""Compares two directories written by compare-outputs.sh, number by number.

Text must match exactly. Numbers must match as printed, except where the
line shows a wall time (a column headed seconds/time, or a number followed
by ' s' or 'ms'), or where both are within --tolerance relative of each
other (use it for field outputs, which may change in the last digits when
the linear solver does). Prints every difference with its file and line;
exit status 1 if there is one.

Usage: compare-numbers.py BEFORE_DIR AFTER_DIR [--tolerance REL]
       [--absolute ABS] [--only PREFIX ...]
(a number passes when within REL relative or ABS absolute)
"""
import os
import re
import sys

NUM = re.compile(r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf')


def tokens(line):
    out, last = [], 0
    for m in NUM.finditer(line):
        out.append(('t', line[last:m.start()]))
        out.append(('n', m.group(0)))
        last = m.end()
    out.append(('t', line[last:]))
    return out


def timing_ends(header):
    """End positions of the header words that name a wall time."""
    # In bytes: printf pads to widths in bytes, and headers hold λ, φ, ⁻¹.
    return [len(header[:m.end()].encode())
            for m in re.finditer(r'seconds|\btime\b|\bwall\b', header, re.I)]


def timing_words(header):
    """Indices of the wall-time columns in a '#' header of one-word names."""
    if not header.lstrip().startswith('#'):
        return []
    words = header.lstrip()[1:].split()
    return [i for i, w in enumerate(words)
            if re.fullmatch(r'seconds|time|wall', w, re.I)]


def is_time(line, toks, k, ends, words=()):
    after = toks[k + 1][1] if k + 1 < len(toks) else ''
    if re.match(r'\s?(s|ms|µs)\b', after):
        return True
    if re.search(r'"[a-z_]*(seconds|time)[a-z_]*"\s*:', line):
        return True
    end = sum(len(t[1].encode()) for t in toks[:k + 1])
    if words:
        prefix = ''.join(t[1] for t in toks[:k + 1])
        if len(prefix.split()) - 1 in words:
            return True
    return any(abs(end - e) <= 2 for e in ends)


def close(a, b, tol, absolute):
    try:
        x, y = float(a), float(b)
    except ValueError:
        return a == b
    if x == y:
        return True
    return abs(x - y) <= max(tol * max(abs(x), abs(y)), absolute)


def compare(pa, pb, tol, absolute, report):
    la = open(pa, encoding='utf-8', errors='replace').read().splitlines()
    lb = open(pb, encoding='utf-8', errors='replace').read().splitlines()
    bad = 0
    if len(la) != len(lb):
        report(f'{pb}: {len(la)} lines before, {len(lb)} after')
        bad += 1
    ends, words = [], []
    in_times = False
    for i, (a, b) in enumerate(zip(la, lb)):
        # A table's header: names a wall-time column, holds no decimals.
        if re.search(r'seconds|\btime\b|\bwall\b', a, re.I) and \
                not re.search(r'\d\.\d|\de[-+]\d', a):
            ends = timing_ends(a)
            words = timing_words(a)
        # A JSON object of wall times.
        if re.match(r'\s*"(seconds|timings)": \{', a):
            in_times = True
        elif in_times and re.match(r'\s*\}', a):
            in_times = False
        if in_times:
            continue
        ta, tb = tokens(a), tokens(b)
        if len(ta) != len(tb) or any(
                x[0] == 't' and x[1].split() != y[1].split()
                for x, y in zip(ta, tb)):
            report(f'{pb}:{i+1}: text differs\n  - {a}\n  + {b}')
            bad += 1
            continue
        for k, (x, y) in enumerate(zip(ta, tb)):
            if x[0] != 'n' or x[1] == y[1] or is_time(a, ta, k, ends, words):
                continue
            if close(x[1], y[1], tol, absolute):
                continue
            report(f'{pb}:{i+1}: {x[1]} → {y[1]}\n  - {a}\n  + {b}')
            bad += 1
    return bad


def main():
    args = sys.argv[1:]
    tol = absolute = 0.0
    only = []
    if '--absolute' in args:
        k = args.index('--absolute')
        absolute = float(args[k + 1])
        del args[k:k + 2]
    if '--tolerance' in args:
        k = args.index('--tolerance')
        tol = float(args[k + 1])
        del args[k:k + 2]
    if '--only' in args:
        k = args.index('--only')
        only = args[k + 1:]
        del args[k:]
    before, after = args
    bad = 0
    for name in sorted(os.listdir(before)):
        if only and not any(name.startswith(p) for p in only):
            continue
        pa, pb = os.path.join(before, name), os.path.join(after, name)
        if not os.path.exists(pb):
            print(f'{pb}: missing')
            bad += 1
            continue
        bad += compare(pa, pb, tol, absolute, print)
    print(f'{bad} differences')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
