#!/usr/bin/env bash
# Files over 400 lines and functions over 80 lines in the sources, the
# project's limits (coefficient tables excepted: core/sbp/*19*.h and
# core/sbp/*20*.h hold published numbers, not code). Prints one line per
# offender and exits 1 if there is any; `scripts/sizes.sh --all` lists every
# function over 40 lines as well, for planning.
#
# A function is what starts on a line ending in ") {" or ") const {" (after
# optional qualifiers) at namespace or class indentation (0 or 2 spaces) and
# ends at the next "}" at the same indentation; lambdas and local classes
# count towards the function they are in.
set -euo pipefail
cd "$(dirname "$0")/.."
report=80
[[ ${1:-} == --all ]] && report=40

status=0
files=$(git ls-files --cached --others --exclude-standard \
          'core/*' 'problems/*' 'solvers/*' 'studies/*' 'lagrangians/*' \
          'scene/*' 'report/*' 'apps/*' 'figures/*' 'bench/*' 'tests/*' \
          'examples/*' | grep -E '\.(h|cc|in)$' |
        grep -vE '^core/sbp/[a-z_]*(19|20)[0-9]{2}\.h$')

for f in $files; do
  n=$(wc -l <"$f")
  if ((n > 400)); then
    echo "$f: $n lines (limit 400)"
    status=1
  fi
done

for f in $files; do
  awk -v file="$f" -v report="$report" '
    function indent(s) { match(s, /^ */); return RLENGTH }
    start == 0 && indent($0) <= 2 &&
        /^ *[A-Za-z_~].*\)( const)?( noexcept)?( override)?( -> [^{]*)? \{$/ &&
        !/^ *(if|for|while|switch|else|do|return|namespace|struct|class|enum)[ (]/ {
      start = NR; ind = indent($0); name = $0; next
    }
    start > 0 && indent($0) == ind && /^ *\};?$/ {
      len = NR - start + 1
      if (len > report) {
        sub(/^ +/, "", name); sub(/ *\{$/, "", name)
        if (length(name) > 70) name = substr(name, 1, 67) "..."
        printf "%s:%d: function of %d lines (limit 80): %s\n", file, start, len, name
        if (len > 80) bad = 1
      }
      start = 0
    }
    END { exit bad }
  ' "$f" || status=1
done
exit $status
