#!/usr/bin/env bash
# The project explains itself from its own files: no source, scene, test or
# document points to a document a reader of the repository does not have
# (private notes, extracts of papers cited by number, a tracker), and every
# pointer into docs/ — "docs/method.md §7" in a comment, or a Markdown link
# with an anchor — names a file and a section that exist.
#
# Usage: docs_pointers_test.sh SOURCE_DIR
set -euo pipefail
export LC_ALL=C.UTF-8
cd "$1"

roots=(core problems solvers apps bench figures scenes tests docs examples
       README.md CMakeLists.txt Makefile .ci)
present=()
for r in "${roots[@]}"; do [[ -e $r ]] && present+=("$r"); done
self=tests/docs_pointers_test.sh
status=0

# 1. References to documents outside the repository.
if hits=$(grep -rnIiE 'formulation|seed 0[0-9]|issue [0-9]|\.\./shared' \
            "${present[@]}" | grep -v "^$self:"); then
  echo "references to documents outside the repository (cite the paper or a"
  echo "section of docs/ instead):"
  echo "$hits"
  status=1
fi

# The GitHub anchor of a Markdown heading: lower case, punctuation dropped,
# spaces to hyphens.
anchor() {
  sed -E 's/^#+ +//' <<<"$1" | tr '[:upper:]' '[:lower:]' |
    sed -E 's/[^[:alnum:] _-]//g; s/ /-/g'
}

# 2. "docs/NAME.md §N" pointers: the file exists and has a heading "## N. …".
while IFS= read -r ref; do
  file=${ref%% §*}
  section=${ref##*§}
  if [[ ! -f $file ]]; then
    echo "pointer to a missing document: $ref"
    status=1
  elif ! grep -qE "^## ${section}\. " "$file"; then
    echo "pointer to a missing section: $ref (no heading '## ${section}. ' in $file)"
    status=1
  fi
done < <(grep -rhoIE 'docs/[a-z_]+\.md §[0-9]+' "${present[@]}" | sort -u)

# 3. Markdown links with anchors into docs/: the heading exists.
while IFS= read -r link; do
  file=${link%%#*}
  want=${link#*#}
  [[ $file == docs/* ]] || file=docs/$file
  if [[ ! -f $file ]]; then
    echo "link to a missing document: $link"
    status=1
    continue
  fi
  found=0
  while IFS= read -r heading; do
    [[ $(anchor "$heading") == "$want" ]] && found=1 && break
  done < <(grep -E '^#+ ' "$file")
  if [[ $found == 0 ]]; then
    echo "link to a missing heading: $link"
    status=1
  fi
done < <(grep -rhoIE '\((docs/)?[a-z_]+\.md#[^)]+\)' README.md docs |
           tr -d '()' | sort -u)

exit $status
