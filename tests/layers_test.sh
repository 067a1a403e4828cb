#!/usr/bin/env bash
# The layers' includes point one way:
#
#   core ← problems ← solvers ← studies, scene ← lagrangians ← apps, figures,
#   bench;  core ← report ← apps, figures
#
# (report writes files and plots and needs only core). A file may include
# its own layer and the layers below it; tests and examples may include
# anything. The Ceres solver (anything of Ceres but ceres/jet.h, which core
# uses for its Jets) is included only under solvers/, and core/ and
# problems/ neither print nor open files.
#
# Namespaces follow folders: a file in LAYER/SUB/ declares vivp::SUB (core/sbp
# is vivp::sbp, solvers/variational is vivp::variational), a file directly in
# LAYER/ declares vivp::LAYER (studies/ is vivp::studies, apps/ vivp::apps),
# nested namespaces below those allowed. The one exception is
# lagrangians/register.h, the user's entry point, which is vivp itself
# (vivp::Register).
#
# Usage: layers_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"

declare -A allowed=(
  [core]="core"
  [problems]="core problems"
  [solvers]="core problems solvers"
  [studies]="core problems solvers studies"
  [scene]="core problems solvers scene"
  [lagrangians]="core problems solvers studies scene lagrangians"
  [report]="core report"
  [apps]="core problems solvers studies scene report lagrangians apps"
  [figures]="core problems solvers studies report lagrangians figures"
  [bench]="core problems solvers studies lagrangians bench"
)
status=0

for layer in "${!allowed[@]}"; do
  [[ -d $layer ]] || continue
  while IFS=: read -r file line include; do
    target=$(sed -E 's/^#include "([a-z_]+)\/.*/\1/' <<<"$include")
    [[ -n ${allowed[$target]+x} ]] || continue  # not a layer (e.g. gtest)
    if [[ " ${allowed[$layer]} " != *" $target "* ]]; then
      echo "$file:$line: $layer/ may not include $target/ ($include)"
      status=1
    fi
  done < <(grep -rnE '^#include "[a-z_]+/' "$layer" \
             --include='*.h' --include='*.cc' --include='*.in' |
           sed -E 's/^([^:]+):([0-9]+):(.*)$/\1:\2:\3/')
done

# The Ceres solver stays in solvers/.
if hits=$(grep -rnE '#include [<"]ceres/' . --include='*.h' --include='*.cc' \
            --include='*.in' --exclude-dir=build --exclude-dir='build-*' \
            --exclude-dir=.git | grep -v 'ceres/jet\.h' |
          grep -v '^\./solvers/'); then
  echo "the Ceres solver included outside solvers/:"
  echo "$hits"
  status=1
fi

# core/ and problems/: no printing, no files.
if hits=$(grep -rnE '#include <(iostream|fstream|cstdio)>|std::(cout|cerr)|printf' \
            core problems --include='*.h' --include='*.cc'); then
  echo "core/ and problems/ print or open files:"
  echo "$hits"
  status=1
fi

# Namespaces follow folders.
for layer in core problems solvers studies scene report apps figures bench \
             lagrangians; do
  [[ -d $layer ]] || continue
  while IFS= read -r file; do
    rel=${file#"$layer"/}
    if [[ $rel == */* ]]; then expected="vivp::${rel%%/*}"
    else expected="vivp::$layer"; fi
    [[ $file == lagrangians/register.h ]] && expected="vivp"
    while IFS=: read -r line name; do
      if [[ $name != "$expected" && $name != "$expected"::* ]]; then
        echo "$file:$line: namespace $name in a file of $layer/ (expected $expected)"
        status=1
      fi
    done < <(grep -nE '^namespace vivp[a-z_:]* \{' "$file" |
             sed -E 's/^([0-9]+):namespace ([a-z_:]+) \{.*/\1:\2/')
  done < <(find "$layer" -name '*.h' -o -name '*.cc' -o -name '*.in')
done

exit $status
