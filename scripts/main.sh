#!/usr/bin/env bash
# Sets up, builds and runs the main job: the glass-and-cup experiment of thesis 4.3 simulated
# (novelty-sim) and played through the surprise pipeline (novelty-run). Prints where the report is.
# Outputs go to out/ (override with NOVELTY_OUT=DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
out="${NOVELTY_OUT:-out}"
# Outputs of a version before the programs marked their folders (.novelty-output) are refused as
# someone else's: moved aside, never deleted.
for d in "$out/glass_and_cup" "$out/glass_and_cup_run"; do
  if [ -d "$d" ] && [ ! -e "$d/.novelty-output" ]; then
    mv "$d" "$d.before-$(date +%Y%m%d%H%M%S)"
    echo "main: an earlier version's $d moved aside" >&2
  fi
done
build/bin/novelty-sim share/scenarios/glass_and_cup.scn --out "$out/glass_and_cup"
build/bin/novelty-run --rawlog "$out/glass_and_cup/glass_and_cup.rawlog" \
  --groundtruth "$out/glass_and_cup/groundtruth" --config share/novelty_run.ini \
  --compare-views 2,4 --out "$out/glass_and_cup_run"
echo "Report: $(realpath "$out")/glass_and_cup_run/report.html"
