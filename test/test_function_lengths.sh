#!/usr/bin/env bash
# Issue 40: no function of the library, the application, the tools or the Python module over
# 120 lines (scripts/function_lengths.py), and no header of theirs over 600 lines. Controls
# first: a planted function of 121 lines must be found and one of 120 must not, else the scan
# itself is broken.
set -u
root="$1"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
scan="$root/scripts/function_lengths.py"
plant() { # plant FILE BODY_LINES: a template function whose length (template line to closing brace) is BODY_LINES + 4
  { echo "template <class T>"; echo "int planted(const T& t, int k = {})"; echo "{"
    for ((i = 0; i < $2; ++i)); do echo "  if(t) { k += $i; } // }{ \"{\""; done
    echo "}"; } > "$1"
}
plant "$tmp/long.h" 117   # 121 lines
plant "$tmp/short.h" 116  # 120 lines
python3 "$scan" "$tmp/long.h" > "$tmp/out" && fail "a function of 121 lines was not found"
grep -q "planted 121" "$tmp/out" || fail "the planted function's length: $(cat "$tmp/out")"
python3 "$scan" "$tmp/short.h" > "$tmp/out" || fail "a function of 120 lines was reported: $(cat "$tmp/out")"
python3 "$scan" || fail "functions over 120 lines (above)"
# headers: at most 600 lines (a planted one of 601 lines first)
long_headers() { find "$@" -name '*.h' -exec awk 'END { if(NR > 600) print FILENAME ": " NR " lines" }' {} \; ; }
seq 601 > "$tmp/long_header.h"
[ -n "$(long_headers "$tmp")" ] || fail "a header of 601 lines was not found"
over="$(long_headers "$root/include" "$root/application" "$root/tools" "$root/python/src")"
[ -z "$over" ] || fail "headers over 600 lines: $over"
echo ok
