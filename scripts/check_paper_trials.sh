#!/usr/bin/env bash
# check_paper_trials.sh: rerun the paper benchmark (configs/search/paper.yaml, no pictures) on seeds A-B and
# check that every trial gives the same success, steps, IoU and distance as the committed
# results/search_paper/trials.jsonl.  Run after a change that must not change behaviour (a refactoring).
#   scripts/check_paper_trials.sh [A-B [DIR]]   default 10000-10049 (200 trials, ~3 min on 2 cores); the
#                                                rerun's results stay in DIR if given (emptied first; else a temporary folder)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
build_dir="${TOPONAV_BUILD_DIR:-build}"
if [ -n "${2:-}" ]; then
  work="$2"
else
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
fi
start=$(date +%s)
cmake -DTOPONAV="$build_dir/toponav" -DWORK="$work" -DSOURCE_DIR="$here" -DSEEDS="${1:-10000-10049}" \
  -P tests/experiments/paper_trials_test.cmake
echo "[check] $(( $(date +%s) - start )) s"
