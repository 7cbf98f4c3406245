#!/usr/bin/env bash
# Install missing Debian packages, configure build/ (once) and build vefs.
# Idempotent and quick when nothing changed. Works from any cwd.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

# python3-numpy and python3-matplotlib: the plotting and rendering scripts
# (scripts/plot_*.py, scripts/render_shapes.py, the benchmarks' plots), run
# with /usr/bin/python3, the interpreter these packages install into.
PACKAGES=(libdeal.ii-dev numdiff openmpi-bin cmake g++ make python3
          python3-numpy python3-matplotlib)

missing=()
for p in "${PACKAGES[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)"
  if [[ "$status" != "install ok installed" ]]; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} > 0)); then
  echo "setup.sh: installing missing packages: ${missing[*]}"
  SUDO=()
  if [[ "$(id -u)" -ne 0 ]]; then
    if command -v sudo >/dev/null 2>&1; then
      SUDO=(sudo)
    else
      echo "setup.sh: not root and sudo not available; cannot install ${missing[*]}" >&2
      exit 1
    fi
  fi
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update </dev/null
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}" </dev/null
fi

# Allow mpirun as root (CI runs as root).
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Avoid "Read -1, expected ..., errno = 1" noise in containers without CMA.
export OMPI_MCA_btl_vader_single_copy_mechanism="${OMPI_MCA_btl_vader_single_copy_mechanism:-none}"

if [[ ! -f build/CMakeCache.txt ]]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi

JOBS="$(nproc 2>/dev/null || echo 2)"
cmake --build build -j"$JOBS"
