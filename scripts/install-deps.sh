#!/usr/bin/env bash
# Installs the Debian packages tailor builds with. Idempotent; silent when all are present.
#   scripts/install-deps.sh          the build, tests and benchmarks (g++)
#   scripts/install-deps.sh --fuzz   also clang++ and its runtimes (libFuzzer, ASan, UBSan)
#                                    for `make fuzz`
set -euo pipefail

# The viewer's node packages (web/package-lock.json); needs no root.
"$(dirname "$0")/install-web-deps.sh"

packages=(
  g++ cmake make ninja-build pkg-config
  libeigen3-dev libtbb-dev libfmt-dev libspdlog-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libgmp-dev
  libpng-dev
  ffmpeg  # the rendered runs' animation.mp4 (src/tailor/render/animation.hpp)
  doxygen  # the API reference and its warning check (make docs, scripts/check-docs.sh)
  # CHOLMOD orders the cloth systems (AMD / METIS) and factorises them on request
  # (ClothSolver::supernodal); OpenBLAS becomes the libblas.so.3 it calls there
  libsuitesparse-dev libopenblas0
  chromium  # the headless browser of tailor view's browser test (tests/view)
  pybind11-dev python3-dev python3-numpy python3-pytest
  python3-dask python3-distributed python3-pandas  # tailor.batch (python/tailor/batch)
)
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang libclang-rt-14-dev)
elif [ $# -gt 0 ]; then
  echo "install-deps: unknown option '$1' (expected --fuzz or nothing)" >&2
  exit 2
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq >&2
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
