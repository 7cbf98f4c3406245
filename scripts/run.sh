#!/usr/bin/env bash
# Usage: scripts/run.sh [file.prm] [extra args]
# Builds (via setup.sh) and runs build/vefs in the CURRENT working directory.
# Without arguments it runs the default scene, the 2D stiff bouncing ball
# (prm/bouncing_ball_2d_stiff.prm, writes ./output/bouncing_ball_2d_stiff/),
# and then draws its pictures into that directory: the centroid, contact
# force and energies (bounce.png, scripts/plot_bounce.py) and the ball's
# outlines (shapes.png, scripts/render_shapes.py).
# NP=<n> (n>1) runs under mpirun with n ranks.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# Build first; keep the caller's cwd for the run itself.
bash "$ROOT/scripts/setup.sh" >&2

export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism="${OMPI_MCA_btl_vader_single_copy_mechanism:-none}"

NP="${NP:-1}"
LAUNCH=()
if [[ "$NP" -gt 1 ]]; then
  LAUNCH=(mpirun -np "$NP" --oversubscribe)
fi

if [[ $# -gt 0 ]]; then
  exec "${LAUNCH[@]}" "$ROOT/build/vefs" "$@"
fi

SCENE="$ROOT/prm/bouncing_ball_2d_stiff.prm"
"${LAUNCH[@]}" "$ROOT/build/vefs" "$SCENE"

# The scene's output directory (a top-level entry, relative to the cwd).
OUT="$(sed -n 's/^[[:space:]]*set[[:space:]]\+Output directory[[:space:]]*=[[:space:]]*//p' "$SCENE" | tail -n 1)"
OUT="${OUT%"${OUT##*[![:space:]]}"}"
# /usr/bin/python3: the interpreter that python3-matplotlib installs into
# (another python3 may come first on PATH).
/usr/bin/python3 "$ROOT/scripts/plot_bounce.py" "$OUT" "$OUT/bounce.png"
/usr/bin/python3 "$ROOT/scripts/render_shapes.py" "$OUT" --out "$OUT/shapes.png"
