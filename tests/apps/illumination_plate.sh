#!/usr/bin/env bash
# The plate experiment of thesis 6.4.2 (fig. 6.13) end to end: novelty-sim renders
# plate_sixteen_lights.scn (16 lightings, then a white box under 6 new ones), novelty-illumination
# learns the invariant image and the illumination statistics and scores the test frames. The
# thesis: "below a FPR of 7 % the method in Section 6.3 again outperforms the NGC algorithm" —
# so at FPR 1 % and 5 % the novelty's TPR must be above NGC's and SCT's.
#   illumination_plate.sh BIN_DIR SOURCE_DIR
set -euo pipefail
BIN=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
W=$(mktemp -d /tmp/novelty_plate.XXXXXX)
trap 'rm -rf "$W"' EXIT
"$BIN/novelty-sim" "$SRC/share/scenarios/plate_sixteen_lights.scn" -o "$W/sim" -q > /dev/null
"$BIN/novelty-illumination" --rawlog "$W/sim/plate_sixteen_lights.rawlog" \
  --groundtruth "$W/sim/groundtruth" --out "$W/out" 2> /dev/null
cat "$W/out/findings.csv"
# The TPR (percent) of a method at an FPR, from findings.csv.
tpr() { awk -F, -v key="$1: TPR at FPR <= $2 %" '$1 == key { sub(/ %/, "", $2); print $2 }' \
  "$W/out/findings.csv"; }
status=0
for fpr in 1 5; do
  mine=$(tpr "novelty" "$fpr") ngc=$(tpr "NGC" "$fpr") sct=$(tpr "SCT" "$fpr")
  if ! awk -v a="$mine" -v b="$ngc" -v c="$sct" 'BEGIN { exit !(a > b && a > c) }'; then
    echo "FAIL: at FPR $fpr % novelty TPR $mine % is not above NGC $ngc % and SCT $sct %" >&2
    status=1
  fi
done
test -s "$W/out/report.html" && test -s "$W/out/panels/000017.png"
exit $status
