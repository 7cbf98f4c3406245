#!/usr/bin/env bash
# A user's first hour, as the README gives it, in a fresh directory: the
# default scene with its pictures (./scripts/run.sh), then the seed's 3D
# ball on 2 ranks and its rendered surfaces (scripts/render_surfaces.py).
# Fails unless every picture is written; prints each command's wall time.
# CI runs it after the test suite (.ci/run), on a fresh machine.
# Usage: scripts/first_hour.sh [work directory, default: a new temporary one]
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORK="${1:-$(mktemp -d)}"
mkdir -p "$WORK"
cd "$WORK"

timed() {
  local start=$SECONDS
  "$@"
  echo "first_hour.sh: '$*' took $((SECONDS - start)) s" >&2
}

expect_files() {
  for file in "$@"; do
    if [[ ! -s "$file" ]]; then
      echo "first_hour.sh: $WORK/$file was not written" >&2
      exit 1
    fi
    echo "first_hour.sh: wrote $WORK/$file" >&2
  done
}

timed bash "$ROOT/scripts/run.sh" > run.log
expect_files output/bouncing_ball_2d_stiff/bounce.png \
  output/bouncing_ball_2d_stiff/shapes.png

timed env NP=2 bash "$ROOT/scripts/run.sh" "$ROOT/prm/bouncing_ball.prm" \
  > run_3d.log
timed /usr/bin/python3 "$ROOT/scripts/render_surfaces.py" \
  output/bouncing_ball --out surfaces.png > render.log
expect_files surfaces.png
