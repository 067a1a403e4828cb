#!/usr/bin/env bash
# mpirun for the tests: any rank count on a machine of fewer cores
# (--oversubscribe), and as root, which OpenMPI refuses unless told
# (--allow-run-as-root; CI runs as root).
set -euo pipefail
flags=(--oversubscribe)
[[ $(id -u) -eq 0 ]] && flags+=(--allow-run-as-root)
exec mpirun "${flags[@]}" "$@"
