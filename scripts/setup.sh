#!/usr/bin/env bash
# setup.sh: install the Debian 12 packages toponav needs (only those missing), then configure and build
# into build/ (Release, all cores). Idempotent: a second run installs nothing and rebuilds only what changed.
#
#   scripts/setup.sh                 install + configure + build
#   TOPONAV_SKIP_INSTALL=1 ...       skip the apt step (you manage packages yourself)
#   TOPONAV_BUILD_DIR=dir ...        build somewhere else than build/
#   TOPONAV_BUILD_TYPE=Debug ...     another CMake build type
#   Torch_DIR=/path/to/libtorch/share/cmake/Torch ...   use a user-built (e.g. CUDA) LibTorch
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

packages=(
  build-essential cmake pkg-config git ccache
  libeigen3-dev
  libbox2d-dev
  libembree-dev libtbb-dev
  libosmesa6-dev
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libtorch-dev libopenblas0-openmp libjemalloc-dev
  libopencv-dev
  libyaml-cpp-dev
  libgtest-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libspdlog-dev
)

log() { printf '[setup] %s\n' "$*"; }

if [ "${TOPONAV_SKIP_INSTALL:-0}" != "1" ]; then
  missing=()
  for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
      missing+=("$p")
    fi
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    if [ "$(id -u)" -eq 0 ]; then sudo_cmd=(); elif command -v sudo >/dev/null; then sudo_cmd=(sudo); else
      echo "setup.sh: need root or sudo to install: ${missing[*]}" >&2; exit 1; fi
    log "installing ${#missing[@]} missing packages: ${missing[*]}"
    apt_log="$(mktemp)"
    if ! { "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq &&
           "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
             "${missing[@]}"; } >"$apt_log" 2>&1; then
      tail -n 30 "$apt_log" >&2
      echo "setup.sh: installing packages failed (full log: $apt_log)" >&2
      exit 1
    fi
    rm -f "$apt_log"
    log "packages installed"
  else
    log "all ${#packages[@]} packages already installed"
  fi
fi

build_dir="${TOPONAV_BUILD_DIR:-build}"
build_type="${TOPONAV_BUILD_TYPE:-Release}"
jobs="$(nproc)"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
torch_args=()
if [ -n "${Torch_DIR:-}" ]; then torch_args=(-DTorch_DIR="$Torch_DIR"); fi

log "configuring $build_dir ($build_type)"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type" "${launcher[@]}" "${torch_args[@]}" >/dev/null
log "building with $jobs jobs"
start=$(date +%s)
cmake --build "$build_dir" -j"$jobs"
log "build done in $(( $(date +%s) - start )) s"
