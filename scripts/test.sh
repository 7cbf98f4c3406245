#!/usr/bin/env bash
# Build (via setup.sh) and run the test suite with ctest.
# Extra arguments are passed on to ctest (e.g. -R name, -V).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$ROOT/scripts/setup.sh"

export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism="${OMPI_MCA_btl_vader_single_copy_mechanism:-none}"

cd "$ROOT"
status=0
ctest --test-dir build --output-on-failure -j2 "$@" || status=$?
exit "$status"
