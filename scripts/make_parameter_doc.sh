#!/usr/bin/env bash
# Usage: scripts/make_parameter_doc.sh [--no-build] [OUTPUT]
# Regenerates doc/parameters.prm (or OUTPUT): every parameter of vefs with
# its default value and documentation, as printed by
# `build/vefs --print-parameters`. Builds first via scripts/setup.sh unless
# --no-build is given. Works from any cwd.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

BUILD=1
if [[ "${1:-}" == "--no-build" ]]; then
  BUILD=0
  shift
fi
OUT="${1:-$ROOT/doc/parameters.prm}"

if ((BUILD)); then
  bash "$ROOT/scripts/setup.sh" >&2
fi

mkdir -p "$(dirname "$OUT")"
# write to a temporary file first so that a failing run leaves OUT intact
TMP="$(mktemp "${OUT}.XXXXXX")"
trap 'rm -f "$TMP"' EXIT
"$ROOT/build/vefs" --print-parameters >"$TMP"
if [[ ! -s "$TMP" ]]; then
  echo "make_parameter_doc.sh: build/vefs --print-parameters printed nothing" >&2
  exit 1
fi
chmod 644 "$TMP"
mv "$TMP" "$OUT"
trap - EXIT
echo "wrote $OUT ($(grep -c '^ *set ' "$OUT") entries)"
