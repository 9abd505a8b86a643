# Sourced by the command-line test scripts (test_cli_order.sh, test_cli_repair.sh), which set
# $prog (the program) and $tmp (a scratch folder):
#   fail MESSAGE...: the test fails, saying why
#   expect_error OUTFILE PATTERN ARGS...: the program run with ARGS exits non-zero without
#     crashing, says one line on stderr (a collection's progress lines, which start with two
#     blanks, apart) matching PATTERN (grep), and leaves no OUTFILE behind
fail() { echo "FAIL: $*"; exit 1; }
expect_error() {
  local outfile="$1" pattern="$2"; shift 2
  "$prog" "$@" >"$tmp/stdout" 2>"$tmp/stderr"; local rc=$?
  [ $rc -ne 0 ] || fail "exit 0 for: $*"
  [ $rc -lt 128 ] || fail "crash ($rc) for: $*"
  [ "$(grep -vc '^  ' "$tmp/stderr")" -eq 1 ] || fail "stderr is not one line for: $* -- $(cat "$tmp/stderr")"
  grep -v '^  ' "$tmp/stderr" | grep -q -- "$pattern" || fail "no '$pattern' in: $(cat "$tmp/stderr")"
  [ ! -e "$outfile" ] || fail "output file left behind for: $*"
  echo "ok (exit $rc): $(grep -v '^  ' "$tmp/stderr")"
}
