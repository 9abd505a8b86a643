#!/usr/bin/env bash
# Installs, with apt-get, the Debian 12 packages this project needs and that are missing.
# Idempotent: does nothing (and needs no network) when everything is already there.
# Works as root, or as a user with sudo.
set -euo pipefail

PACKAGES=(
  g++ cmake make ninja-build ccache pkg-config   # (Ninja builds the named targets of a build in parallel)
  clang libclang-rt-14-dev   # the sanitizer stage of scripts/test.sh (clang++ compiles it in about 0.77 of g++'s time)
  libcgal-dev        # CGAL 5.5 (header-only), pulls Boost
  libcgal-demo       # ships data/meshes/*.off used by tests and the demo
  libeigen3-dev      # sparse linear algebra
  libboost-dev
  libgmp-dev libmpfr-dev   # exact arithmetic behind the filtered predicates
  libtbb-dev         # parallel collections
  libsuitesparse-dev # CHOLMOD: supernodal sparse Cholesky for the solver (optional at build time)
  libopenblas0-pthread # an optimised BLAS for CHOLMOD (Debian's default, the reference BLAS, is 2-3x slower)
  doxygen            # the reference manual
  librsvg2-bin       # rsvg-convert: SVG -> PNG for looking at pictures
  libjs-mathjax      # MathJax for the manual's formulas, offline (no CDN)
  python3-dev pybind11-dev python3-numpy   # the Python module (python/)
  python3-dask python3-distributed          # collections on a Dask cluster
  python3-pytest     # the Python tests
  python3-mypy       # the type stubs checked against the examples (python/tests/test_stubs_and_errors.py)
  libjs-three        # three.js (r111), copied into every folder the view job writes (offline, no CDN)
  chromium           # headless Chromium: the view tests open the page and run its WebGL self-test (label viewer)
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "install-deps: missing packages (${missing[*]}) and not root, no sudo" >&2; exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
