# Sourced by the test scripts: reads a list of ctest names or regular expressions (one a line,
# '#' comments) and prints them joined into one expression for ctest -R / -E. Every line must name
# a test of the build tree, or the script fails: a renamed test would otherwise slip from one
# stage to another unnoticed.
#   ctest_patterns LIST_FILE BUILD_DIR
ctest_patterns() {
  local list=$1 build=$2 p n
  [ -r "$list" ] || { echo "$list: cannot read it" >&2; return 1; }
  local patterns=()
  mapfile -t patterns < <(sed -E 's/^[[:space:]]+//; s/[[:space:]]+$//' "$list" | grep -vE '^(#|$)')
  [ "${#patterns[@]}" -gt 0 ] || { echo "$list names no test" >&2; return 1; }
  for p in "${patterns[@]}"; do
    case "$p" in *'('*) echo "$list: '$p': no parentheses (see the file)" >&2; return 1 ;; esac
    n=$(ctest --test-dir "$build" -N -R "$p" | sed -n 's/^Total Tests: //p')
    [ "${n:-0}" -gt 0 ] || { echo "$list: '$p' names no test in $build" >&2; return 1; }
  done
  (IFS='|'; echo "${patterns[*]}")
}
