#!/usr/bin/env bash
# Usage: scripts/run.sh [file.prm] [extra args]
# Builds (via setup.sh) and runs build/vefs in the CURRENT working directory.
# Without arguments it runs the default scene, the 2D stiff bouncing ball
# (prm/bouncing_ball_2d_stiff.prm, writes ./output/bouncing_ball_2d_stiff/).
# NP=<n> (n>1) runs under mpirun with n ranks.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# Build first; keep the caller's cwd for the run itself.
bash "$ROOT/scripts/setup.sh" >&2

export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism="${OMPI_MCA_btl_vader_single_copy_mechanism:-none}"

if [[ $# -eq 0 ]]; then
  set -- "$ROOT/prm/bouncing_ball_2d_stiff.prm"
fi

NP="${NP:-1}"
if [[ "$NP" -gt 1 ]]; then
  exec mpirun -np "$NP" --oversubscribe "$ROOT/build/vefs" "$@"
else
  exec "$ROOT/build/vefs" "$@"
fi
