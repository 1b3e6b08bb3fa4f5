#!/usr/bin/env bash
# run.sh: set up (install missing packages, configure, build) and run the main job.  Until the search
# benchmark exists, the main job generates one world of each kind and writes their pictures and JSON
# under results/worlds/.  Extra arguments go to `toponav demo` (e.g. --out DIR).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
bash scripts/setup.sh
build_dir="${TOPONAV_BUILD_DIR:-build}"
"$build_dir/toponav" demo --config configs/demo.yaml "$@"
