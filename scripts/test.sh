#!/usr/bin/env bash
# test.sh: set up (install missing packages, configure, build) and run the whole test suite with ctest.
# Exits non-zero on any failure.  Extra arguments go to ctest (e.g. scripts/test.sh -R sim_tests).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
start=$(date +%s)
bash scripts/setup.sh
build_dir="${TOPONAV_BUILD_DIR:-build}"
echo "[test] running the test suite"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" "$@"
echo "[test] set-up, build and tests took $(( $(date +%s) - start )) s"
