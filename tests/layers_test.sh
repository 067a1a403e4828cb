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
# solvers/ and core/ spell no option of a front end: no command-line option
# and no scene key assignment in their string literals (below).
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

# solvers/ and core/ name no front end's option: a refusal there is data in
# the library's own names (solvers/variational/solver_choice.h, Refusal), and
# apps/ (the command line) and scene/ (scene files) word it. So no string
# literal under solvers/ or core/ holds a command-line option (`--` and a
# letter: "--slab-points") or a scene key assignment: a key that the scene
# reader accepts followed by " = " ("slab_points = 0"), or a literal that
# starts with " = " for a key to be joined to. The keys are those of the
# reader's CheckKeys lists in scene/, less the ones of one to three letters
# (x, v, end, dof), which are the mathematics' names too ("at x = 0.5").
scene_keys=$(perl -0777 -ne '
  while (/CheckKeys\((.*?)\);/sg) {
    my $args = $1;
    while ($args =~ /\{([^{}]*)\}/g) {
      my $list = $1;
      print "$1\n" while $list =~ /"([a-z_]+)"/g;
    }
  }' scene/*.cc | awk 'length($0) > 3' | sort -u | paste -sd'|' -)
if [[ $scene_keys != *slab_points* ]]; then
  echo "the scene keys were not found in scene/*.cc (CheckKeys lists)"
  status=1
fi
# FILE:LINE: "literal" for each string literal that matches $PATTERN
# (comments and character literals are skipped).
hits=$(find solvers core \( -name '*.h' -o -name '*.cc' -o -name '*.in' \) |
       sort |
       PATTERN="--[A-Za-z]|(^|[^A-Za-z0-9_])($scene_keys) = |^ = " \
       xargs perl -ne '
  my $comment = $in_comment;
  pos($_) = 0;
  while (pos($_) < length($_)) {
    if ($comment) { /\G.*?\*\//gc ? ($comment = 0) : last; next }
    last if /\G\/\//gc;
    if (/\G\/\*/gc) { $comment = 1; next }
    if (/\G"((?:[^"\\]|\\.)*)"/gc) {
      my $s = $1;
      print "$ARGV:$.: \"$s\"\n" if $s =~ /$ENV{PATTERN}/;
      next;
    }
    next if /\G\x27(?:[^\x27\\]|\\.)*\x27/gc;
    /\G./gcs;
  }
  $in_comment = $comment;
  if (eof) { close ARGV; $in_comment = 0 }')
if [[ -n $hits ]]; then
  echo "solvers/ or core/ spell a command-line option or a scene key (return"
  echo "the refusal as data and let apps/ or scene/ word it):"
  echo "$hits"
  status=1
fi

exit $status
