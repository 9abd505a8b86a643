#!/usr/bin/env bash
# Command-line tests: test_cli.sh PROGRAM CASE. Each case checks exit status, the
# one-line error and that no (partial) output file is left behind on errors.
set -u
prog="$1"; case_name="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

expect_error() { # expect_error OUTFILE ARGS...: non-zero exit, one line on stderr, no output file
  local outfile="$1"; shift
  "$prog" "$@" >"$tmp/stdout" 2>"$tmp/stderr"; local rc=$?
  [ $rc -ne 0 ] || fail "exit 0 for: $*"
  [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "stderr is not one line for: $* -- $(cat "$tmp/stderr")"
  [ ! -e "$outfile" ] || fail "output file left behind for: $*"
  [ ! -e "$outfile.tmp" ] || fail "temporary file left behind for: $*"
  echo "ok (exit $rc): $(cat "$tmp/stderr")"
}

case "$case_name" in
  tile_sphere|tile_disk)
    kind="${case_name#tile_}"
    for k in 5 7 12; do
      "$prog" tile --orbifold "$kind" --cones $k --svg "$tmp/t.svg" --depth 2 || fail "exit status for k=$k"
      [ -s "$tmp/t.svg" ] || fail "no svg"
      head -c 4 "$tmp/t.svg" | grep -q "<svg" || fail "not an svg"
      tail -n 1 "$tmp/t.svg" | grep -q "</svg>" || fail "svg not closed"
      # one dot per tile corner: 2k-2 (sphere) or k (disk)
      dots=$(grep -c "<circle cx=.*r=\"7\"" "$tmp/t.svg")
      if [ "$kind" = sphere ]; then want=$((2*k-2)); else want=$k; fi
      [ "$dots" -eq "$want" ] || fail "$dots cone dots for k=$k, expected $want"
      if command -v xmllint >/dev/null 2>&1; then xmllint --noout "$tmp/t.svg" || fail "malformed svg"; fi
      rm -f "$tmp/t.svg"
    done
    echo ok ;;
  tile_errors)
    expect_error "$tmp/a.svg" tile --orbifold sphere --cones 4 --svg "$tmp/a.svg"
    expect_error "$tmp/a.svg" tile --orbifold disk --cones 3 --svg "$tmp/a.svg"
    expect_error "$tmp/a.svg" tile --orbifold torus --cones 7 --svg "$tmp/a.svg"
    expect_error "$tmp/a.svg" tile --orbifold sphere --cones seven --svg "$tmp/a.svg"
    expect_error "$tmp/a.svg" tile --orbifold sphere --cones 7 --svg "$tmp/a.svg" --depth -1
    expect_error "$tmp/a.svg" tile --orbifold sphere --svg "$tmp/a.svg"
    expect_error "$tmp/a.svg" tile --orbifold sphere --cones 7 --svg "$tmp/a.svg" --bogus 1
    expect_error "$tmp/nodir/a.svg" tile --orbifold sphere --cones 7 --svg "$tmp/nodir/a.svg"
    expect_error "$tmp/a.svg" frobnicate
    expect_error "$tmp/a.svg"
    echo ok ;;
  *) fail "unknown case $case_name" ;;
esac
