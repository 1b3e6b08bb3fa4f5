#!/usr/bin/env bash
# run.sh: set up (install missing packages, configure, build) and run the main job: the quick search
# benchmark (configs/search/quick.yaml), which prints its Table I and writes a picture per trial under
# results/search_quick/.  Extra arguments go to `toponav bench` (e.g. --workers 1, --out DIR).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
bash scripts/setup.sh
build_dir="${TOPONAV_BUILD_DIR:-build}"
# --fresh: a rebuilt program must not resume the trials an older build left there.
"$build_dir/toponav" bench --config configs/search/quick.yaml --fresh "$@"
echo "pictures: results/search_quick/pictures/ (or under --out)"
