#!/usr/bin/env bash
# NoveltyMaps from a user's own MRPT program, as the README says to do it: installs a build tree
# to a prefix (cmake --install), builds examples/ against the installed package with default
# compiler flags (no -march, no build type), simulates a short glass-and-cup clip with the
# installed novelty-sim and scenario, and runs the example on it with examples/maps.ini: PNGs
# written, and the maps saved after frame 20, loaded and continued give the surprise of the maps
# never saved (same pixels, within 1 %: map files round the planes, docs/map_storage.md).
#   bash scripts/example.sh [BUILD_DIR=build]
set -euo pipefail
cd "$(dirname "$0")/.."
build="$(realpath -m "${1:-build}")"
if grep -q "^NOVELTY_SANITIZE:BOOL=ON" "$build/CMakeCache.txt"; then
  # A sanitized library needs a sanitized program (the runtime must come first).
  echo "example: skipped for a sanitizer build ($build)"
  exit 0
fi
prefix="$build/install"
work="$build/example"
rm -rf "$prefix" "$work"
cmake --install "$build" --prefix "$prefix" > /dev/null
cmake -S examples -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$work/build"
"$prefix/bin/novelty-sim" -q -n 40 "$prefix/share/novelty/scenarios/glass_and_cup.scn" \
  -o "$work/clip"
"$work/build/surprise_from_rawlog" "$work/clip/glass_and_cup.rawlog" examples/maps.ini \
  "$work/out" 20
pngs=$(find "$work/out" -name 'surprise_*.png' | wc -l)
[ "$pngs" -eq 4 ] || { echo "example: expected 4 surprise PNGs, found $pngs" >&2; exit 1; }
# The README's program: 40 frames, a PNG every tenth.
mkdir -p "$work/readme"
"$work/build/surprise_pngs" "$work/clip/glass_and_cup.rawlog" examples/maps.ini "$work/readme" > /dev/null
pngs=$(find "$work/readme" -name 'surprise_*.png' | wc -l)
[ "$pngs" -eq 4 ] || { echo "example: surprise_pngs wrote $pngs PNGs, expected 4" >&2; exit 1; }
# Every program the build made is installed.
for p in $(find "$build/bin" -maxdepth 1 -type f \( -name novelty -o -name 'novelty-*' \) -printf '%f\n'); do
  [ -x "$prefix/bin/$p" ] || { echo "example: $prefix/bin/$p is not installed" >&2; exit 1; }
done
"$prefix/bin/novelty" info > /dev/null
[ -f "$prefix/share/novelty/examples/surprise_pngs.cc" ] || { echo "example: examples/ not installed" >&2; exit 1; }
echo "example: built against $prefix with default flags; 4 PNGs; save, load, continue within 1 %;"
echo "  the README's surprise_pngs: 4 PNGs; every program installed"
