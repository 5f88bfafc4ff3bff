#!/usr/bin/env bash
# Runs every case of docs/bad_inputs.md: the command's exit status, its one-line message on
# stderr (exactly one line for an error, no MRPT stack trace, no libpng or OpenCV line), and the
# check of the last column.
#   bad_inputs.sh BIN_DIR SOURCE_DIR [--no-memory-limit]   (sanitizer builds reserve terabytes)
set -uo pipefail
BIN=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
MEMORY_LIMIT_KB=4000000  # 4 GB: the blow-ups the cases reproduce took more
[ "${3:-}" = "--no-memory-limit" ] && MEMORY_LIMIT_KB=unlimited
export PATH="$BIN:$PATH"
export W
W=$(mktemp -d /tmp/novelty_bad_inputs.XXXXXX)
trap 'rm -rf "$W"' EXIT

# Fixtures: a 12-frame 80×60 RGB-D clip and a stereo one, and a map made from the first.
sed -e 's/^frames .*/frames 12/' -e 's/^camera .*/camera 80 60 60/' -e '/^event/d' -e '/^phase/d' \
  "$SRC/share/scenarios/glass_and_cup.scn" > "$W/tiny.scn"
echo "phase A 1 12 all frames" >> "$W/tiny.scn"
sed 's/^rig .*/rig stereo 0.12/' "$W/tiny.scn" > "$W/stereo.scn"
novelty-sim "$W/tiny.scn" -o "$W/sim" -q > /dev/null &&
  novelty-sim "$W/stereo.scn" -o "$W/stereo" -q > /dev/null &&
  novelty-run --rawlog "$W/sim/glass_and_cup.rawlog" --groundtruth "$W/sim/groundtruth" \
    --out "$W/good" --map-out "$W/good.map" > /dev/null 2>&1 || {
  echo "bad_inputs: the fixtures could not be made" >&2
  exit 1
}

failures=0 cases=0
fail() {
  echo "FAIL: $1" >&2
  echo "  command: $2" >&2
  sed 's/^/  stderr: /' "$W/stderr" | head -20 >&2
  failures=$((failures + 1))
}

while IFS= read -r row; do
  # | input | `command` | exit | says | `then` |   (no '|' inside a cell)
  IFS=$'\x1f' read -r input command want says then < <(printf '%s\n' "$row" | awk -F'|' '{
    for (i = 2; i < NF; ++i) { gsub(/^ +| +$/, "", $i); printf "%s%s", $i, (i < NF - 1 ? "\x1f" : "\n") }
  }')
  command=${command#\`} command=${command%\`} then=${then#\`} then=${then%\`}
  cases=$((cases + 1))
  rm -rf "$W/r" "$W/o"
  (cd "$W" && ulimit -v "$MEMORY_LIMIT_KB" && exec timeout 120 bash -c "$command") \
    > "$W/stdout" 2> "$W/stderr"
  rc=$?
  tr '\r' '\n' < "$W/stderr" | grep -v '^\s*$' | grep -v '^\[novelty-' > "$W/lines"
  if [ "$rc" = 124 ]; then
    fail "$input: hung (killed after 120 s)" "$command"
  elif [ "$rc" != "$want" ]; then
    fail "$input: exit $rc, expected $want" "$command"
  elif [ -n "$says" ] && ! grep -qF -- "$says" "$W/lines"; then
    fail "$input: stderr does not say '$says'" "$command"
  # An error is exactly one line; a run that succeeds prints at most one (the skipped frames).
  elif grep -qE 'backtrace|Call stack|==== MRPT|^\s+at |^libpng |\[ *WARN:' "$W/lines" || [ "$(wc -l < "$W/lines")" -gt 1 ] ||
       { [ "$rc" != 0 ] && [ "$(wc -l < "$W/lines")" != 1 ]; }; then
    fail "$input: stderr is not one line" "$command"
  elif [ -n "$then" ] && ! (cd "$W" && bash -c "$then"); then
    fail "$input: the check failed: $then" "$command"
  fi
done < <(sed -n '/<!-- cases -->/,/<!-- \/cases -->/p' "$SRC/docs/bad_inputs.md" |
         grep '^| ' | tail -n +2)

echo "bad_inputs: $cases cases, $failures failed"
[ "$cases" -gt 30 ] && [ "$failures" = 0 ]
