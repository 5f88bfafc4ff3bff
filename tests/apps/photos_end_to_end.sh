#!/usr/bin/env bash
# One's own photos end to end, as a user would run the documented commands, without ground truth:
# - objects: novelty-learn-objects learns the graffiti (graf1) and two other photos, and
#   novelty-find-objects finds the graffiti, verified, in graf3 (30° away) and nothing verified in
#   a photo of fruits' neighbour; errors name the file;
# - lightings: novelty-import --layout fixed-camera turns a folder of the MIT box's lightings into
#   a rawlog rawlog-edit reads, and novelty-illumination-map learns from it one lighting a frame
#   (RAWLOG:each) and saves a map.
#   photos_end_to_end.sh BIN_DIR SOURCE_DIR
set -euo pipefail
BIN=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
DATA="${NOVELTY_SHARED_DATA:-$SRC/../shared/data}"
if [ ! -d "$DATA/graf" ] || [ ! -d "$DATA/mit-intrinsic" ]; then
  echo "graf/ or mit-intrinsic/ of the shared data is absent: skipped"
  exit 0
fi
W=$(mktemp -d /tmp/novelty_photos.XXXXXX)
trap 'rm -rf "$W"' EXIT
status=0
fail() { echo "FAIL: $1" >&2; status=1; }

"$BIN/novelty-learn-objects" "graffiti=$DATA/graf/graf1.png" "$DATA/textures/cards.png" \
  "$DATA/textures/fruits.jpg" --out "$W/objects.object_database" > "$W/learn.out"
cat "$W/learn.out"
grep -q "^3 photos → .* (3 objects, [0-9]* features, sift)" "$W/learn.out" || fail "learn summary"
mkdir "$W/today"
cp "$DATA/graf/graf3.png" "$DATA/textures/building.jpg" "$W/today/"
"$BIN/novelty-find-objects" "$W/today" --objects "$W/objects.object_database" --out "$W/found" \
  > "$W/find.out"
cat "$W/find.out"
grep -q "frame 2 (graf3.png): graffiti verified" "$W/find.out" || fail "graffiti not verified in graf3"
if grep "building.jpg" "$W/find.out" | grep -q " verified"; then fail "something verified in building.jpg"; fi
awk -F, 'NR > 1 && $1 == "graffiti" && $3 == 1 { ok = 1 } END { exit !ok }' "$W/found/objects.csv" \
  || fail "objects.csv: $(cat "$W/found/objects.csv")"
test -s "$W/found/panels/2.png" || fail "no panel of graf3"
# The database is a map novelty-info can name.
"$BIN/novelty-find-objects" "$W/today" --objects "$W/none" --out "$W/x" 2> "$W/err" && fail "no db accepted"
grep -q "none" "$W/err" || fail "missing database: $(cat "$W/err")"
"$BIN/novelty-learn-objects" "x=$DATA/graf/graf1.png@700,600,200,200" --out "$W/x.object_database" \
  2> "$W/err" && fail "a box outside the photo accepted"
grep -q "graf1.png: the box 700,600,200,200 is not inside the 800x640 photo" "$W/err" \
  || fail "box outside: $(cat "$W/err")"
test ! -e "$W/x.object_database" || fail "a database written after an error"

mkdir "$W/lamps"
for f in light01 light04 light07 light10 mask; do cp "$DATA/mit-intrinsic/box/$f.png" "$W/lamps/"; done
"$BIN/novelty-import" "$W/lamps" --layout fixed-camera --out "$W/lamps.rawlog" > "$W/import.out"
cat "$W/import.out"
grep -q "4 images of one fixed camera" "$W/import.out" || fail "import: $(cat "$W/import.out")"
rawlog-edit --info -i "$W/lamps.rawlog" > "$W/info.txt" 2>&1 || fail "rawlog-edit cannot read it"
grep -q "Overall number of objects *: 8" "$W/info.txt" || fail "rawlog-edit: not 8 objects"
"$BIN/novelty-illumination-map" --lighting "$W/lamps.rawlog:each" --map-out "$W/box.illumination_invariant" \
  > "$W/learn_lamps.out" 2> /dev/null || fail "learning from the imported lightings"
grep -q "4 lightings" "$W/learn_lamps.out" || fail "not 4 lightings: $(cat "$W/learn_lamps.out")"
test -s "$W/box.illumination_invariant" || fail "no map saved"
exit $status
