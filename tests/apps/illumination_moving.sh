#!/usr/bin/env bash
# The moving-camera experiment of thesis 6.4 end to end on a short clip: novelty-sim renders a
# robot driving an arc in front of a table four times, the lamp moved between passes (four
# lightings, 6.1), then once more under a fifth lighting with a red box put down; novelty-illumination
# learns the illumination-invariant map from the four passes (one phase each) and scores the
# fifth against NGC and SCT, whose reference is the first pass's virtual image at each pose.
# Asserts the issue's targets: AUC >= 0.95 and a TPR above both baselines at every FPR <= 10 %.
#   illumination_moving.sh BIN_DIR SOURCE_DIR
set -euo pipefail
BIN=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
W=$(mktemp -d /tmp/novelty_illumination_moving.XXXXXX)
trap 'rm -rf "$W"' EXIT
status=0
fail() { echo "FAIL: $1" >&2; status=1; }

"$BIN/novelty-sim" "$SRC/tests/data/four_lightings.scn" -o "$W/sim" -q > /dev/null
"$BIN/novelty-illumination" --rawlog "$W/sim/lights.rawlog" --groundtruth "$W/sim/groundtruth" \
  --out "$W/out" --train-phase L1,L2,L3,L4 --test-phase test --kappa 0.5 2> /dev/null
cat "$W/out/findings.csv"
value() { awk -F, -v key="$2" '$1 == key { sub(/ %/, "", $2); print $2 }' "$1"; }
auc=$(value "$W/out/findings.csv" "novelty: AUC")
awk -v a="$auc" 'BEGIN { exit !(a >= 0.95) }' || fail "AUC $auc < 0.95"
ahead=$(value "$W/out/findings.csv" "novelty TPR above NGC and SCT at every FPR <= 10 % (0.1 % steps)")
[ "$ahead" = yes ] || fail "novelty not ahead at every FPR <= 10 % ($ahead)"
viewpoints=$(value "$W/out/findings.csv" "viewpoints")
[ "$viewpoints" -ge 4 ] || fail "$viewpoints viewpoints along a 0.35 m arc (a viewpoint every 7.5 cm)"
test "$(ls "$W/out/panels" | wc -l)" -eq 10 || fail "not one panel per test frame"
exit $status
