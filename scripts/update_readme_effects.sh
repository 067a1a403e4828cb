#!/usr/bin/env bash
# Rewrites the effect table of README.md (between its "effects table"
# markers) from the effects' own parameter tables, as `vivp scene effects`
# prints them. Usage: scripts/update_readme_effects.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
vivp=${1:-build}/apps/vivp
table=$("$vivp" scene effects)
awk -v table="$table" '
  /^<!-- effects table:/ { print; print table; skip = 1; next }
  /^<!-- end of effects table -->/ { skip = 0 }
  !skip { print }
' README.md >README.md.new
mv README.md.new README.md
