#!/usr/bin/env bash
# novelty-illumination-map end to end on the four-lightings clip (tests/data/four_lightings.scn):
# the map learnt from the four passes of one rawlog (phases of the ground truth), saved, loaded
# and used to judge the fifth pass, where a red box was put down. Asserts the issue's AUC ≥ 0.95
# over the pass, one novelty picture and one frames.csv row per frame, the report's plots, and
# clear errors for one lighting and an unknown phase.
#   illumination_map_tool.sh BIN_DIR SOURCE_DIR
set -euo pipefail
BIN=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
W=$(mktemp -d /tmp/novelty_illumination_map.XXXXXX)
trap 'rm -rf "$W"' EXIT
status=0
fail() { echo "FAIL: $1" >&2; status=1; }

"$BIN/novelty-sim" "$SRC/tests/data/four_lightings.scn" -o "$W/sim" -q > /dev/null
R=$W/sim/lights.rawlog
GT=(--poses groundtruth --groundtruth "$W/sim/groundtruth")
"$BIN/novelty-illumination-map" --lighting "$R:L1" --lighting "$R:L2" --lighting "$R:L3" \
  --lighting "$R:L4" --ini "$SRC/share/illumination_invariant.ini" "${GT[@]}" \
  --map-out "$W/room.illumination_invariant" 2> /dev/null
test -s "$W/room.illumination_invariant" || fail "no map saved"
"$BIN/novelty-illumination-map" --map-in "$W/room.illumination_invariant" --rawlog "$R:test" \
  "${GT[@]}" --out "$W/judge" 2> /dev/null
cat "$W/judge/findings.csv"
auc=$(awk -F, '$1 == "pixel AUC of novelty over all frames" { print $2 }' "$W/judge/findings.csv")
awk -v a="${auc:-0}" 'BEGIN { exit !(a >= 0.95) }' || fail "AUC ${auc:-none} < 0.95"
test "$(ls "$W/judge/novelty" | wc -l)" -eq 10 || fail "not one novelty picture per frame"
test "$(($(wc -l < "$W/judge/frames.csv") - 1))" -eq 10 || fail "not one frames.csv row per frame"
test -s "$W/judge/report.html" || fail "no report"
# The report plots Δ and coverage per frame and the pixel ROC (full and up to FPR 5 %).
test "$(grep -c '<svg' "$W/judge/report.html")" -eq 4 || fail "report: not the four plots"
grep -q 'ROC at FPR up to 5 %' "$W/judge/report.html" || fail "report: no ROC plot"

expect_error() {  # expected message, arguments...
  local message=$1
  shift
  if "$BIN/novelty-illumination-map" "$@" > /dev/null 2> "$W/err"; then
    fail "accepted: $*"
  elif ! grep -qF "$message" "$W/err"; then
    fail "for $*: expected '$message', got '$(cat "$W/err")'"
  fi
}
expect_error "at least two lightings" --lighting "$R:L1" --map-out "$W/x" "${GT[@]}"
expect_error "no phase 'L9'" --lighting "$R:L1" --lighting "$R:L9" --map-out "$W/x" "${GT[@]}"
test ! -e "$W/x" || fail "a map was written after an error"
exit $status
