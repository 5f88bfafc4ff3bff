#!/usr/bin/env bash
# The moving-camera experiment of thesis 6.4 end to end on a short clip: novelty-sim renders a
# robot driving an arc in front of a table four times, the lamp moved between passes (four
# lightings, 6.1), then once more under a fifth lighting with a red box put down; novelty-illumination
# learns the illumination-invariant map from the four passes (one phase each) and scores the
# fifth against NGC and SCT, whose reference is the first pass's virtual image at each pose.
# Asserts the issue's targets: AUC >= 0.95 and a TPR above both baselines at every FPR <= 10 %.
#   illumination_moving.sh BIN_DIR
set -euo pipefail
BIN=$(cd "$1" && pwd)
W=$(mktemp -d /tmp/novelty_illumination_moving.XXXXXX)
trap 'rm -rf "$W"' EXIT
status=0
fail() { echo "FAIL: $1" >&2; status=1; }

# Half a cycle (a pass along the arc and a 0.5 s stop) takes 2.83 s at 4 fps; the lamp moves in
# each stop, the box appears in the fourth.
cat > "$W/lights.scn" << 'SCN'
name lights
frames 68
fps 4
seed 3
camera 320 240 60
rig rgbd
sensor noise 1.0 gamma 2.2
mount 0.0 0.0 1.10 90 16
room 6 6 2.8
ambient 0.08 0.08 0.08
material wood phong 0.45 0.28 0.14
material cloth phong 0.85 0.82 0.75
texture cloth checker 0.65 0.75 0.85 12
material green phong 0.15 0.60 0.20 0.4 60
material red phong 0.80 0.10 0.08
object table box 1.2 0.8 0.72 wood at 0 0 fixed
object cloth plane 1.3 0.9 cloth at 0 0 on table
object can cylinder 0.05 0.15 green at -0.20 0.10 on cloth mass 0.3
object box box 0.12 0.10 0.10 red at 0.15 -0.05 on cloth absent mass 0.3
lamp l1 -1.0 0.8 2.0 1.8 1.7 1.5
arc 0 0 1.0 -100 -80 0.15
stop 0.5
arc 0 0 1.0 -80 -100 0.15
stop 0.5
repeat 2
event 2.58 lamp l1 0.2 1.3 1.9
event 5.41 lamp l1 1.1 0.6 2.2
event 8.24 lamp l1 -1.2 -0.2 1.7
event 11.07 lamp l1 0.6 1.1 1.6
event 11.07 add box
phase L1 1 11 Lighting 1.
phase L2 13 22 Lighting 2.
phase L3 24 33 Lighting 3.
phase L4 35 45 Lighting 4.
phase test 58 67 Lighting 5, a red box added.
SCN
"$BIN/novelty-sim" "$W/lights.scn" -o "$W/sim" -q > /dev/null
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
