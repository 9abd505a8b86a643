#!/usr/bin/env bash
# Hostile-input corpus for the command-line program:
#
#   test_hostile_inputs.sh PROGRAM [DATA_DIR]
#
# Generates (bash and awk only) small valid meshes in every format -- a subdivided
# icosahedron (sphere type), a grid (disk type) -- and landmark files, checks that the
# valid ones succeed, then corrupts them (truncation, lying headers, NaN / huge / tiny
# coordinates, duplicate and isolated vertices, non-manifold edges and vertices, bad
# orientation, components, holes, bad indices, polygons, garbage bytes, bad landmark
# files, bad manifests) and runs embed / landmarks / map / collection on each item.
# Every failing item must give: its expected exit status (2 usage, 3 bad data, 1 output
# file), exactly one line on stderr containing the item's own expected phrase, no crash
# (status < 128), no hang (timeout 60 s), and no output file nor *.tmp left behind.
# DATA_DIR is not needed (everything is generated); it is accepted for uniformity with
# the other CLI tests.
set -u
export LC_ALL=C
prog="$1"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
C="$tmp/corpus"   # the generated inputs
O="$tmp/out"      # every output goes here; emptied before each item
mkdir -p "$C" "$O"
cases=0
failures=0
verbose=1
limit=60          # seconds before a run counts as a hang

# run_item NAME STATUS PHRASE ARG...   runs PROGRAM ARG... and checks the outcome; STATUS 0
# means success is expected (then PHRASE is a fragment of stdout)
run_item() {
  local name="$1" want="$2" phrase="$3"
  shift 3
  cases=$((cases + 1))
  rm -rf "$O"
  mkdir -p "$O"
  # (in a subshell whose own stderr is dropped: bash's "Segmentation fault" job notice)
  (timeout "$limit" "$prog" "$@" >"$tmp/stdout" 2>"$tmp/stderr"; exit $?) 2>/dev/null
  local rc=$? problem=""
  local err
  err="$(head -c 600 "$tmp/stderr")"
  if [ $rc -eq 124 ]; then
    problem="hang: killed after $limit s"
  elif [ $rc -ge 128 ]; then
    problem="crash: killed by signal $((rc - 128))"
  elif [ $rc -ne "$want" ]; then
    problem="exit status $rc, expected $want"
  elif [ "$want" -eq 0 ]; then
    grep -qF -- "$phrase" "$tmp/stdout" || problem="stdout lacks '$phrase'"
    [ -z "$(find "$O" -name '*.tmp')" ] || problem="temporary file left behind: $(find "$O" -name '*.tmp')"
  else
    if [ "$(wc -l <"$tmp/stderr")" -ne 1 ] || [ "$(wc -c <"$tmp/stderr")" -le 1 ]; then
      problem="stderr is not one line"
    elif ! grep -qF -- "$phrase" "$tmp/stderr"; then
      problem="stderr lacks '$phrase'"
    elif [ "${err#hyperbolic_orbifold_tutte: }" = "$err" ]; then
      problem="stderr does not start with the program name"
    elif [ -n "$(find "$O" -type f)" ]; then
      problem="output left behind: $(find "$O" -type f | sed "s|$O/||" | tr '\n' ' ')"
    fi
  fi
  if [ -n "$problem" ]; then
    failures=$((failures + 1))
    [ $verbose -eq 1 ] && echo "FAIL $name: $problem -- stderr: $err"
  elif [ $verbose -eq 1 ]; then
    if [ "$want" -eq 0 ]; then echo "ok   $name (exit 0)"; else echo "ok   $name (exit $rc): ${err#hyperbolic_orbifold_tutte: }"; fi
  fi
  return 0
}

# ---------------------------------------------------------------------------------------
# generators
# ---------------------------------------------------------------------------------------

# icosahedron subdivided LEVEL times, on the unit sphere (OFF; vertex i on line i+3,
# face j on line j+3+V)
icosphere() {
  awk -v level="$1" '
    function unit(i,   l) { l = sqrt(X[i]*X[i] + Y[i]*Y[i] + Z[i]*Z[i]); X[i] /= l; Y[i] /= l; Z[i] /= l }
    function mid(a, b,   k, i) {
      k = (a < b) ? a "," b : b "," a
      if (k in M) return M[k]
      i = n++; X[i] = (X[a] + X[b]) / 2; Y[i] = (Y[a] + Y[b]) / 2; Z[i] = (Z[a] + Z[b]) / 2; unit(i); M[k] = i
      return i
    }
    BEGIN {
      t = (1 + sqrt(5)) / 2; n = 0
      split("-1 t 0 1 t 0 -1 -t 0 1 -t 0 0 -1 t 0 1 t 0 -1 -t 0 1 -t t 0 -1 t 0 1 -t 0 -1 -t 0 1", c, " ")
      for (i = 0; i < 12; i++) {
        for (k = 1; k <= 3; k++) { v = c[3*i + k]; s = (v ~ /^-/) ? -1 : 1; P[k] = (v ~ /t/) ? s * t : v + 0 }
        X[n] = P[1]; Y[n] = P[2]; Z[n] = P[3]; unit(n); n++
      }
      split("0 11 5 0 5 1 0 1 7 0 7 10 0 10 11 1 5 9 5 11 4 11 10 2 10 7 6 7 1 8 3 9 4 3 4 2 3 2 6 3 6 8 3 8 9 4 9 5 2 4 11 6 2 10 8 6 7 9 8 1", f, " ")
      nf = 20
      for (j = 0; j < nf; j++) { A[j] = f[3*j + 1]; B[j] = f[3*j + 2]; Cc[j] = f[3*j + 3] }
      for (l = 0; l < level; l++) {
        m = 0
        for (j = 0; j < nf; j++) {
          a = A[j]; b = B[j]; c3 = Cc[j]; ab = mid(a, b); bc = mid(b, c3); ca = mid(c3, a)
          A2[m] = a;  B2[m] = ab; C2[m] = ca; m++
          A2[m] = b;  B2[m] = bc; C2[m] = ab; m++
          A2[m] = c3; B2[m] = ca; C2[m] = bc; m++
          A2[m] = ab; B2[m] = bc; C2[m] = ca; m++
        }
        nf = m
        for (j = 0; j < nf; j++) { A[j] = A2[j]; B[j] = B2[j]; Cc[j] = C2[j] }
      }
      print "OFF"; print n, nf, 0
      for (i = 0; i < n; i++) printf "%.9f %.9f %.9f\n", X[i], Y[i], Z[i]
      for (j = 0; j < nf; j++) print 3, A[j], B[j], Cc[j]
    }'
}

# N x N grid of the unit square (a disk; vertex i*(N+1)+j at (i/N, j/N)); BUMP scales a
# smooth height (0: flat)
grid() {
  awk -v n="$1" -v bump="$2" 'BEGIN {
    m = n + 1; print "OFF"; print m*m, 2*n*n, 0
    for (i = 0; i < m; i++) for (j = 0; j < m; j++) printf "%.9g %.9g %.9g\n", i/n, j/n, bump * sin(3*i/n) * cos(2*j/n)
    for (i = 0; i < n; i++) for (j = 0; j < n; j++) { a = i*m + j; b = a + m; print 3, a, b, b + 1; print 3, a, b + 1, a + 1 }
  }'
}

# N x N torus (genus 1)
torus() {
  awk -v n="$1" 'BEGIN {
    pi = 3.14159265358979; print "OFF"; print n*n, 2*n*n, 0
    for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
      u = 2*pi*i/n; v = 2*pi*j/n; printf "%.9f %.9f %.9f\n", (2 + cos(v)) * cos(u), (2 + cos(v)) * sin(u), sin(v) }
    for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
      a = i*n + j; b = ((i+1)%n)*n + j; c = ((i+1)%n)*n + (j+1)%n; d = i*n + (j+1)%n
      print 3, a, b, c; print 3, a, c, d }
  }'
}

# OFF (as written above: header on 2 lines, one record per line) to other formats
off_to_obj() { awk 'NR == 2 { nv = $1; next } NR > 2 && NR <= 2 + nv { print "v", $1, $2, $3; next }
                    NR > 2 + nv { printf "f"; for (k = 2; k <= NF; k++) printf " %d", $k + 1; printf "\n" }' "$1"; }
off_to_ply() {
  awk 'NR == 2 { nv = $1; nf = $2
                 printf "ply\nformat ascii 1.0\ncomment hostile-input corpus\nelement vertex %d\n", nv
                 printf "property float x\nproperty float y\nproperty float z\nelement face %d\n", nf
                 printf "property list uchar int vertex_indices\nend_header\n"; next }
       NR > 2 { print }' "$1"
}
off_to_stl() {
  awk 'NR == 2 { nv = $1; print "solid corpus"; next }
       NR > 2 && NR <= 2 + nv { P[NR - 3] = $1 " " $2 " " $3; next }
       NR > 2 + nv { print "  facet normal 0 0 0"; print "    outer loop"
                     for (k = 2; k <= 4; k++) print "      vertex " P[$k]
                     print "    endloop"; print "  endfacet" }
       END { print "endsolid corpus" }' "$1"
}
off_to_ts() { # off_to_ts FILE [FIRST_ID]: vertex ids FIRST_ID, FIRST_ID + 1, ...
  awk -v o="${2:-0}" 'NR == 1 { printf "GOCAD TSurf 1\nHEADER {\nname:corpus\n}\nTFACE\n"; next } NR == 2 { nv = $1; next }
       NR > 2 && NR <= 2 + nv { printf "VRTX %.0f %s %s %s\n", NR - 3 + o, $1, $2, $3; next }
       NR > 2 + nv { printf "TRGL %.0f %.0f %.0f\n", $2 + o, $3 + o, $4 + o } END { print "END" }' "$1"
}
# binary files: awk writes octal escapes, printf turns them into bytes
awk_binary_lib='
  function f32(x,   s, e, m) {
    if (x == 0) return 0
    s = 0; if (x < 0) { s = 2147483648; x = -x }
    e = 0; while (x >= 2) { x /= 2; e++ } while (x < 1) { x *= 2; e-- }
    m = int((x - 1) * 8388608 + 0.5); if (m >= 8388608) { m = 0; e++ }
    return s + (e + 127) * 8388608 + m
  }
  function le32(v,   i, out) { out = ""; for (i = 0; i < 4; i++) { out = out sprintf("\\%03o", v % 256); v = int(v / 256) } return out }
  function u8(v) { return sprintf("\\%03o", v) }'
off_to_binary_ply() { # little endian, float coordinates, uchar/int lists
  local nv nf
  nv=$(awk 'NR == 2 { print $1 }' "$1"); nf=$(awk 'NR == 2 { print $2 }' "$1")
  printf 'ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n' "$nv"
  printf 'element face %d\nproperty list uchar int vertex_indices\nend_header\n' "$nf"
  printf "$(awk "$awk_binary_lib"'
    NR == 2 { nv = $1; next }
    NR > 2 && NR <= 2 + nv { printf "%s%s%s", le32(f32($1)), le32(f32($2)), le32(f32($3)); next }
    NR > 2 + nv { printf "%s", u8($1); for (k = 2; k <= NF; k++) printf "%s", le32($k) }' "$1")"
}
off_to_binary_stl() {
  printf "$(awk "$awk_binary_lib"'
    NR == 2 { nv = $1; nf = $2; for (i = 0; i < 80; i++) printf " "; printf "%s", le32(nf); next }
    NR > 2 && NR <= 2 + nv { P[NR - 3] = le32(f32($1)) le32(f32($2)) le32(f32($3)); next }
    NR > 2 + nv { printf "%s%s%s%s%s%s%s", le32(0), le32(0), le32(0), P[$2], P[$3], P[$4], u8(0) u8(0) }' "$1")"
}
# LCG bytes (no dependency on /dev/urandom: the corpus is the same on every run)
garbage() { # garbage N SEED
  printf "$(awk -v n="$1" -v seed="$2" 'BEGIN { x = seed; for (i = 0; i < n; i++) { x = (x * 1103515245 + 12345) % 2147483648; printf "\\%03o", int(x / 65536) % 256 } }')"
}
# awk edits of an OFF file; V = number of vertices (vertex i is on line i+3)
set_vertex() { awk -v i="$2" -v p="$3" 'NR == i + 3 { print p; next } { print }' "$1"; }
set_face() { awk -v j="$2" -v f="$3" 'NR == 2 { nv = $1 } NR == 3 + nv + j && NR > 2 { print f; next } { print }' "$1"; }
scale_off() { awk -v s="$2" 'NR == 2 { nv = $1 } NR > 2 && NR <= 2 + nv { printf "%.17g %.17g %.17g\n", $1 * s, $2 * s, $3 * s; next } { print }' "$1"; }
# two copies of a mesh, the second moved by DX; with SHARE=1 the second copy's vertex 0 is
# the first copy's vertex 0
two_copies() {
  awk -v dx="$2" -v share="$3" '
    NR == 2 { nv = $1; nf = $2; next } NR > 2 && NR <= 2 + nv { V[NR - 3] = $0; next } NR > 2 + nv { F[NR - 3 - nv] = $0 }
    END {
      print "OFF"; print 2 * nv - share, 2 * nf, 0
      for (i = 0; i < nv; i++) print V[i]
      for (i = share; i < nv; i++) { split(V[i], p, " "); printf "%.9f %s %s\n", p[1] + dx, p[2], p[3] }
      for (j = 0; j < nf; j++) print F[j]
      for (j = 0; j < nf; j++) { split(F[j], f, " "); printf "3"
        for (k = 2; k <= 4; k++) { w = f[k]; printf " %d", (share && w == 0) ? 0 : w + nv - share } printf "\n" }
    }' "$1"
}

# ---------------------------------------------------------------------------------------
# the valid inputs
# ---------------------------------------------------------------------------------------
icosphere 2 >"$C/s.off"                      # 162 vertices, 320 faces, closed genus 0
grid 8 0.1 >"$C/d.off"                       # 81 vertices, 128 faces, a disk
grid 8 0 >"$C/flat.off"                      # the same, flat (exact coordinates)
torus 6 >"$C/torus.off"
: >"$C/empty.cones"                          # (no landmark)
off_to_obj "$C/s.off" >"$C/s.obj"
off_to_ply "$C/s.off" >"$C/s.ply"
off_to_binary_ply "$C/s.off" >"$C/s_bin.ply"
off_to_stl "$C/s.off" >"$C/s.stl"
off_to_binary_stl "$C/s.off" >"$C/s_bin.stl"
off_to_ts "$C/s.off" >"$C/s.ts"
off_to_ts "$C/s.off" -2147483648 >"$C/s_int_min_ids.ts"  # ids that overflowed in CGAL::IO::read_GOCAD()
scale_off "$C/s.off" 1.3 >"$C/s2.off"
echo "0 10 20 30 40 50 60" >"$C/s.cones"      # any 7 distinct vertices (sphere type)
echo "0 4 8 44 80 76 72 36" >"$C/d.cones"     # 8 border vertices of the grid, in border order
printf 's.off s.cones\ns2.off s.cones\n' >"$C/good.manifest"
S="$C/s.off"; D="$C/d.off"; SC="$C/s.cones"; DC="$C/d.cones"
embed_s() { run_item "$1" "$2" "$3" embed --mesh "$4" --cones "$SC" --out "$O/x.obj"; }
embed_d() { run_item "$1" "$2" "$3" embed --mesh "$4" --cones "$DC" --out "$O/x.obj"; }
cones_s() { run_item "$1" "$2" "$3" embed --mesh "$S" --cones "$4" --out "$O/x.obj"; }

# the harness must be able to fail: a wrong status, a wrong phrase, a success expected
# from a bad input, and (with a stub program) a file left behind, two lines on stderr, a
# crash and a hang must each be reported (run quietly, then the count is restored)
verbose=${HOT_HOSTILE_VERBOSE_SELFTEST:-0}
before=$failures
run_item selftest_status 3 "" embed --mesh "$S" --cones "$SC" --out "$O/x.obj"
run_item selftest_phrase 3 "a phrase no message holds" embed --mesh "$C/missing.off" --cones "$SC" --out "$O/x.obj"
run_item selftest_success 0 "embedded" embed --mesh "$C/missing.off" --cones "$SC" --out "$O/x.obj"
cat >"$tmp/stub.sh" <<'STUB'
#!/usr/bin/env bash
case "$1" in
  leftover) echo "hyperbolic_orbifold_tutte: bad data" >&2; : >"$2"; exit 3 ;;
  two_lines) printf 'hyperbolic_orbifold_tutte: bad data\nmore\n' >&2; exit 3 ;;
  crash) echo "hyperbolic_orbifold_tutte: bad data" >&2; kill -SEGV $$ ;;
  hang) exec sleep 30 ;;
esac
STUB
chmod +x "$tmp/stub.sh"
real_prog="$prog"; prog="$tmp/stub.sh"; limit=2
run_item selftest_leftover 3 "bad data" leftover "$O/x.obj.tmp"
run_item selftest_two_lines 3 "bad data" two_lines
run_item selftest_crash 3 "bad data" crash
run_item selftest_hang 3 "bad data" hang
prog="$real_prog"; limit=60
if [ $((failures - before)) -ne 7 ]; then
  echo "FAIL: the harness does not detect wrong expectations ($((failures - before)) of 7)"
  exit 1
fi
failures=$before
cases=0
verbose=1

echo "--- valid inputs (each must succeed: the corrupted copies below fail because of the corruption)"
for f in s.off s.obj s.ply s_bin.ply s.stl s_bin.stl s.ts s_int_min_ids.ts; do
  embed_s "valid_$f" 0 "certified bijective" "$C/$f"
done
embed_d valid_disk 0 "disk type" "$D"
run_item valid_landmarks 0 "wrote 7 landmarks" landmarks --mesh "$S" --count 7 --out "$O/l.txt"
run_item valid_map 0 "mapped 162 vertices" map --source "$S" --source-cones "$SC" --target "$C/s2.off" \
  --target-cones "$SC" --out "$O/m.txt"
run_item valid_collection 0 "collection of 2 meshes" collection --manifest "$C/good.manifest" --out "$O/coll"

# ---------------------------------------------------------------------------------------
echo "--- truncated and empty files"
head -c 2000 "$S" >"$C/trunc_vertices.off"
head -c "$(($(wc -c <"$S") - 4))" "$S" >"$C/trunc_face.off"
head -n -10 "$S" >"$C/trunc_lines.off"
{ head -n 100 "$C/s.obj"; printf 'v 0.5 0.25'; } >"$C/trunc_vertex.obj"
{ grep '^v ' "$C/s.obj"; grep '^f ' "$C/s.obj" | head -n 200; grep '^f ' "$C/s.obj" | sed -n 201p | cut -d' ' -f1-3; } >"$C/trunc_face.obj"
head -c "$(($(wc -c <"$C/s.ply") - 100))" "$C/s.ply" >"$C/trunc.ply"
ply_header_bytes=$(grep -a -b -m1 '^end_header' "$C/s_bin.ply" | cut -d: -f1)
head -c "$((ply_header_bytes + 11 + 1000))" "$C/s_bin.ply" >"$C/trunc_vertices_bin.ply"
head -c "$(($(wc -c <"$C/s_bin.ply") - 7))" "$C/s_bin.ply" >"$C/trunc_faces_bin.ply"
head -c 8000 "$C/s_bin.stl" >"$C/trunc_bin.stl"
{ head -n 697 "$C/s.stl"; printf '      vertex 0.5 0.25'; } >"$C/trunc.stl"
head -n 100 "$C/s.ts" >"$C/trunc.ts"
: >"$C/empty.off"; : >"$C/empty.obj"; : >"$C/empty.ply"; : >"$C/empty.stl"
printf '  \n\n# nothing but a comment\n' >"$C/blank.off"
printf 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n' >"$C/no_face.off"
embed_s trunc_off_in_vertices 3 "line 56: vertex 53 has 2 coordinates, 3 expected (truncated or malformed record)" "$C/trunc_vertices.off"
embed_s trunc_off_in_last_face 3 "face 319 announces 3 vertices but lists only 2" "$C/trunc_face.off"
embed_s trunc_off_last_lines 3 "the file ends after 310 of the 320 faces announced by the OFF header" "$C/trunc_lines.off"
embed_s trunc_obj_in_vertex 3 "line 101: vertex 100 has 2 coordinates, 3 expected" "$C/trunc_vertex.obj"
embed_s trunc_obj_in_face 3 "face 200 (line 363) is degenerate: it has only 2 vertices" "$C/trunc_face.obj"
embed_s trunc_ply_ascii 3 "line 485: face 312: the list size 3 is larger than the rest of the file holds (only 1 byte left: truncated file?)" "$C/trunc.ply"
embed_s trunc_ply_binary_vertices 3 "announces 162 'vertex' elements, but only 1000 bytes follow" "$C/trunc_vertices_bin.ply"
embed_s trunc_ply_binary_faces 3 "face 319: the list size 3 is larger than the rest of the file holds (only 5 bytes left" "$C/trunc_faces_bin.ply"
embed_s trunc_stl_binary 3 "the header announces 320 triangles, i.e. 16084 bytes, but the file has 8000 bytes" "$C/trunc_bin.stl"
embed_s trunc_stl_ascii 3 "the file ends inside facet 99 (truncated file?)" "$C/trunc.stl"
embed_s trunc_gocad 3 "trunc.ts: the file ends without END (truncated file?)" "$C/trunc.ts"
embed_s empty_off 3 "empty.off': the file is empty" "$C/empty.off"
embed_s empty_obj 3 "empty.obj': the file is empty" "$C/empty.obj"
embed_s empty_ply 3 "empty.ply': the file is empty" "$C/empty.ply"
embed_s empty_stl 3 "empty.stl': the file is empty" "$C/empty.stl"
embed_s blank_off 3 "the file holds no OFF header (it is blank or only comments)" "$C/blank.off"
embed_s no_face 3 "The mesh is empty: $C/no_face.off: the mesh has no face (it has 3 vertices but no face)" "$C/no_face.off"

# ---------------------------------------------------------------------------------------
echo "--- headers lying about counts"
body() { tail -n +3 "$S"; }
{ printf 'OFF\n2000000000 2000000000 0\n'; body; } >"$C/huge_counts.off"
{ printf 'OFF\n99999999999999999999999 320 0\n'; body; } >"$C/overflow_count.off"
{ printf 'OFF\n-162 320 0\n'; body; } >"$C/negative_vertices.off"
{ printf 'OFF\n162 -320 0\n'; body; } >"$C/negative_faces.off"
{ printf 'OFF\n100 320 0\n'; body; } >"$C/few_vertices.off"
set_face "$S" 5 "4000000000 1 2 3" >"$C/huge_face.off"
sed 's/^element vertex 162$/element vertex 4000000000/' "$C/s.ply" >"$C/huge_count.ply"
sed 's/^element face 320$/element face -5/' "$C/s.ply" >"$C/negative_count.ply"
sed 's/^element face 320$/element face 99999/' "$C/s_bin.ply" >"$C/huge_count_bin.ply"
{ head -c 80 "$C/s_bin.stl"; printf '\377\377\377\377'; tail -c +85 "$C/s_bin.stl"; } >"$C/huge_count.stl"
{ head -c 80 "$C/s_bin.stl"; printf '\144\0\0\0'; tail -c +85 "$C/s_bin.stl"; } >"$C/small_count.stl"
embed_s header_huge_counts 3 "announces 2000000000 vertices and 2000000000 faces, but only" "$C/huge_counts.off"
embed_s header_count_overflow 3 "vertex count '99999999999999999999999' in the OFF header is too large" "$C/overflow_count.off"
embed_s header_negative_vertex_count 3 "negative vertex count '-162' in the OFF header" "$C/negative_vertices.off"
embed_s header_negative_face_count 3 "negative face count '-320' in the OFF header" "$C/negative_faces.off"
embed_s header_too_few_vertices 3 "line 103: face 0: the vertex count '" "$C/few_vertices.off"
embed_s face_huge_vertex_count 3 "face 5 announces 4000000000 vertices but lists only 3" "$C/huge_face.off"
embed_s ply_huge_count 3 "announces 4000000000 'vertex' elements, but only" "$C/huge_count.ply"
embed_s ply_negative_count 3 "bad PLY element line (expected 'element <name> <non-negative count>')" "$C/negative_count.ply"
embed_s ply_binary_huge_count 3 "announces 99999 'face' elements, but only 4160 bytes follow" "$C/huge_count_bin.ply"
embed_s stl_huge_count 3 "the header announces 4294967295 triangles" "$C/huge_count.stl"
embed_s stl_small_count 3 "the header announces 100 triangles, i.e. 5084 bytes, but the file has 16084 bytes" "$C/small_count.stl"

# ---------------------------------------------------------------------------------------
echo "--- coordinates"
set_vertex "$S" 5 "nan 0.5 0.5" >"$C/nan.off"
set_vertex "$S" 7 "0.5 -inf 0.5" >"$C/inf.off"
set_vertex "$S" 9 "0.5 0.5 1e400" >"$C/overflow.off"
set_vertex "$S" 11 "0.5 1.0.0 0.5" >"$C/bad_number.off"
scale_off "$S" 1e308 >"$C/scale_1e308.off"
scale_off "$S" 1e100 >"$C/scale_1e100.off"
scale_off "$S" 1e-100 >"$C/scale_1e-100.off"
scale_off "$S" 1e-310 >"$C/scale_1e-310.off"
{ head -c "$((ply_header_bytes + 11 + 3 * 12 + 4))" "$C/s_bin.ply"; printf '\0\0\300\177'
  tail -c +"$((ply_header_bytes + 11 + 3 * 12 + 8 + 1))" "$C/s_bin.ply"; } >"$C/nan_bin.ply"
sed '1s/.*/v 0 nan 0/' "$C/s.obj" >"$C/nan.obj"
embed_s nan_coordinate 3 "vertex 5 (line 8) has a non-finite coordinate (nan 0.5 0.5)" "$C/nan.off"
embed_s inf_coordinate 3 "vertex 7 (line 10) has a non-finite coordinate (0.5 -inf 0.5)" "$C/inf.off"
embed_s overflowing_coordinate 3 "vertex 9 (line 12) has a non-finite coordinate (0.5 0.5 inf)" "$C/overflow.off"
embed_s malformed_coordinate 3 "line 14: vertex 11: coordinate '1.0.0' is not a number" "$C/bad_number.off"
embed_s coordinates_1e308 3 "face 0 is out of the range of double-precision geometry: its squared edge lengths overflow" "$C/scale_1e308.off"
embed_s coordinates_1e100 3 "so its squared area overflows (coordinates too large: rescale the mesh)" "$C/scale_1e100.off"
embed_s coordinates_1e-100 3 "so its squared area underflows (coordinates too small: rescale the mesh)" "$C/scale_1e-100.off"
embed_s coordinates_1e-310 3 "its longest edge has length 3.21e-311, so its squared area underflows" "$C/scale_1e-310.off"
embed_s nan_binary_ply 3 "vertex 3 has a non-finite coordinate (0.525731 nan 0)" "$C/nan_bin.ply"
embed_s nan_obj 3 "vertex 0 (line 1) has a non-finite coordinate (0 nan 0)" "$C/nan.obj"

# ---------------------------------------------------------------------------------------
echo "--- vertices, faces and topology"
nv=162; nf=320
faces_with() { awk -v v="$2" 'NR == 2 { nv = $1 } NR > 2 + nv && ($2 == v || $3 == v || $4 == v) { print NR - 3 - nv }' "$1"; }
face_line() { awk -v j="$2" 'NR == 2 { nv = $1 } NR == 3 + nv + j { print; exit }' "$1"; }
# a seam: vertex 162 is a copy of vertex 0 and replaces it in two adjacent faces of its fan
f1=$(faces_with "$S" 0 | head -1)
read -r _ a1 b1 c1 <<<"$(face_line "$S" "$f1")"
f2=$(for g in $(faces_with "$S" 0); do
       [ "$g" = "$f1" ] && continue
       read -r _ a b c <<<"$(face_line "$S" "$g")"
       for w in $a $b $c; do [ "$w" != 0 ] && { [ "$w" = "$a1" ] || [ "$w" = "$b1" ] || [ "$w" = "$c1" ]; } && echo "$g"; done
     done | head -1)
awk -v f1="$f1" -v f2="$f2" -v nv=$nv 'NR == 2 { print nv + 1, $2, 0; next }
  NR == 3 + nv { print p0 } NR == 3 { p0 = $0 }
  NR > 2 + nv && (NR - 3 - nv == f1 || NR - 3 - nv == f2) { for (k = 2; k <= 4; k++) if ($k == 0) $k = nv; print; next }
  { print } END { }' "$S" >"$C/seam.off"
# vertex 1 moved onto a neighbour
read -r _ a b c <<<"$(face_line "$S" "$(faces_with "$S" 1 | head -1)")"
nb=$a; [ "$nb" = 1 ] && nb=$b
set_vertex "$S" 1 "$(sed -n "$((nb + 3))p" "$S")" >"$C/coincident.off"
{ cat "$S" | awk -v nv=$nv 'NR == 2 { print nv + 1, $2, 0; next } { print } NR == 2 + nv { print "5 5 5" }'; } >"$C/isolated.off"
read -r _ a b c <<<"$(face_line "$S" 0)"
awk -v nv=$nv -v nf=$nf -v a="$a" -v b="$b" 'NR == 2 { print nv + 1, nf + 1, 0; next } { print } NR == 2 + nv { print "3 3 3" }
  END { print 3, a, b, nv }' "$S" >"$C/nm_edge.off"
two_copies "$S" 2 1 >"$C/nm_vertex.off"
read -r _ a b c <<<"$(face_line "$S" 7)"
set_face "$S" 7 "3 $a $c $b" >"$C/flipped.off"
two_copies "$S" 3 0 >"$C/two_spheres.off"
two_copies "$D" 2 0 >"$C/two_disks.off"
awk -v nv=$nv -v nf=$nf 'NR == 2 { print nv, nf - 1, 0; next } NR == 3 + nv + 100 { next } { print }' "$S" >"$C/hole.off"
read -r _ a b c <<<"$(face_line "$S" 5)"
set_face "$S" 5 "3 $a $a $c" >"$C/repeated_index.off"
set_face "$S" 10 "3 0 1 162" >"$C/index_out_of_range.off"
set_face "$S" 10 "3 0 1 99999999999999999999999" >"$C/index_overflow.off"
set_face "$S" 10 "3 0 -1 2" >"$C/index_negative.off"
set_face "$S" 10 "3 0 1 x" >"$C/index_garbage.off"
set_face "$S" 12 "3 0 1.5 2" >"$C/index_float.off"
sed '0,/^f /s/^f .*/f 0 1 2/' "$C/s.obj" >"$C/index_zero.obj"
sed '0,/^f /s/^f .*/f 1 2 163/' "$C/s.obj" >"$C/index_past_end.obj"
sed '0,/^f /s/^f .*/f -1 -2 -500/' "$C/s.obj" >"$C/index_relative.obj"
sed '0,/^f /s/^f .*/f 1 2 3x/' "$C/s.obj" >"$C/index_garbage.obj"
sed '0,/^frobnicate/s/^f /frobnicate /' "$C/s.obj" | sed '0,/^f /s/^f /frobnicate /' >"$C/unknown_statement.obj"
awk '/^end_header/ { print; getline; h = 1 } h && ++n == 170 { $3 = -3 } { print }' "$C/s.ply" >"$C/index_negative.ply"
awk '/^end_header/ { h = 1 } h && /^3 / && ++n == 4 { $4 = 500 } { print }' "$C/s.ply" >"$C/index_out_of_range.ply"
# face 0 (a b c) and its neighbour across (b c) (c b d) become the quad (a b d c)
read -r _ a b c <<<"$(face_line "$S" 0)"
g=$(awk -v nv=$nv -v b="$b" -v c="$c" 'NR > 2 + nv && NR > 3 + nv {
      for (k = 2; k <= 4; k++) { k2 = (k == 4) ? 2 : k + 1; if ($k == c && $k2 == b) { print NR - 3 - nv; exit } } }' "$S")
d=$(face_line "$S" "$g" | awk -v b="$b" -v c="$c" '{ for (k = 2; k <= 4; k++) if ($k != b && $k != c) print $k }')
awk -v nv=$nv -v nf=$nf -v g="$g" -v q="4 $a $b $d $c" 'NR == 2 { print nv, nf - 1, 0; next }
  NR == 3 + nv { print q; next } NR == 3 + nv + g { next } { print }' "$S" >"$C/quad.off"
set_face "$S" 7 "2 0 1" >"$C/two_vertex_face.off"
awk 'NR == 2 { print $1, $2 + 1, 0; next } { print } END { print "3 0 9 10" }' "$D" >"$C/duplicated_face.off"
set_vertex "$C/flat.off" 49 "0.5625 0.5625 0" >"$C/collinear.off"
# without --orbifold the seam makes it a disk (valid as such): the landmarks are not on its border
embed_s seam_duplicate_vertex_auto_type 3 "s.cones: landmark 1 (vertex 10) is not on the boundary loop" "$C/seam.off"
run_item seam_duplicate_vertex_sphere_given 3 "but the mesh has 1 boundary loop (border vertices 0 and 162 have the same coordinates" \
  embed --mesh "$C/seam.off" --cones "$SC" --orbifold sphere --out "$O/x.obj"
embed_s coincident_vertices 3 "is degenerate: its vertices 1 and $nb have the same coordinates" "$C/coincident.off"
embed_s isolated_vertex 3 "vertex 162 is isolated (it has no incident face)" "$C/isolated.off"
embed_s non_manifold_edge 3 "non-manifold edge: the edge ($(( a < b ? a : b )), $(( a < b ? b : a ))) is shared by 3 faces" "$C/nm_edge.off"
embed_s non_manifold_vertex 3 "non-manifold vertex: the faces around vertex 0 (line 3) form more than one fan" "$C/nm_vertex.off"
embed_s inconsistent_orientation 3 "inconsistent face orientation: face" "$C/flipped.off"
embed_s two_components_closed 3 "the mesh has 2 connected components (faces 0 and 320 are not connected" "$C/two_spheres.off"
embed_d two_components_open 3 "the mesh has 2 connected components (faces 0 and 128 are not connected" "$C/two_disks.off"
run_item hole_in_sphere 3 "the sphere-type (closed) orbifold needs a closed mesh, but the mesh has 1 boundary loop" \
  embed --mesh "$C/hole.off" --cones "$SC" --orbifold sphere --out "$O/x.obj"
run_item closed_mesh_as_disk 3 "the disk-type orbifold needs a mesh with one boundary loop, but the mesh is closed" \
  embed --mesh "$S" --cones "$SC" --orbifold disk --out "$O/x.obj"
run_item genus_one_without_cone 3 "0 landmarks are given, but the sphere-type orbifold needs at least 1 on a surface of genus 1" \
  embed --mesh "$C/torus.off" --cones "$C/empty.cones" --out "$O/x.obj"
embed_s repeated_vertex_index 3 "face 5 (line 170) is degenerate: it uses vertex $(face_line "$S" 5 | cut -d' ' -f2) more than once" "$C/repeated_index.off"
embed_s index_out_of_range 3 "line 175: face 10: vertex index '162' is out of range (the file has 162 vertices)" "$C/index_out_of_range.off"
embed_s index_overflow 3 "line 175: face 10: vertex index '99999999999999999999999' is out of range" "$C/index_overflow.off"
embed_s index_negative 3 "line 175: face 10: negative vertex index '-1'" "$C/index_negative.off"
embed_s index_garbage 3 "line 175: face 10: 'x' is not a vertex index" "$C/index_garbage.off"
embed_s index_float 3 "line 177: face 12: '1.5' is not a vertex index" "$C/index_float.off"
embed_s obj_index_zero 3 "line 163: face 0: vertex index 0 is invalid (OBJ indices start at 1)" "$C/index_zero.obj"
embed_s obj_index_past_end 3 "line 163: face 0: vertex index 163 is out of range (the file has 162 vertices)" "$C/index_past_end.obj"
embed_s obj_index_relative 3 "line 163: face 0: relative vertex index '-500' refers to a vertex before the first one" "$C/index_relative.obj"
embed_s obj_index_garbage 3 "line 163: face 0: '3x' is not a vertex reference" "$C/index_garbage.obj"
embed_s obj_unknown_statement 3 "line 163: unknown OBJ statement 'frobnicate'" "$C/unknown_statement.obj"
embed_s ply_index_negative 3 "negative vertex index -3" "$C/index_negative.ply"
embed_s ply_index_out_of_range 3 "face 3 (line 176): vertex index 500 is out of range (the file has 162 vertices)" "$C/index_out_of_range.ply"
embed_s quad 3 "face 0 has 4 vertices; only triangle meshes are supported" "$C/quad.off"
embed_s two_vertex_face 3 "face 7 (line 172) is degenerate: it has only 2 vertices" "$C/two_vertex_face.off"
embed_d duplicated_face 3 "duplicated face: face 128 (line 212) repeats face 0 (line 84) (the same vertices in the same order)" "$C/duplicated_face.off"
embed_d collinear_face 3 "has zero area: its vertices" "$C/collinear.off"

# ---------------------------------------------------------------------------------------
echo "--- garbage bytes and bad files"
for ext in off obj ply stl ts; do garbage 3000 17 >"$C/garbage.$ext"; done
{ printf 'OFF\n'; garbage 3000 5; } >"$C/garbage_after_header.off"
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 10\nproperty float x\nproperty float y\nproperty float z\n'
  printf 'element face 10\nproperty list uchar int vertex_indices\nend_header\n'; garbage 300 9; } >"$C/garbage_body.ply"
cp "$S" "$C/mesh.xyz"
sed 's/^VRTX 7 /VRTX 6 /' "$C/s.ts" >"$C/duplicate_id.ts"
sed 's/^TRGL 0 /TRGL 4000 /' "$C/s.ts" >"$C/undefined_id.ts"
sed 's/^VRTX 3 .*/VRTX 3 0.1 zero 0.2/' "$C/s.ts" >"$C/bad_coordinate.ts"
sed 's/^TRGL 0 /SURFACE 0 /' "$C/s.ts" >"$C/unknown_keyword.ts"
mkdir -p "$C/directory.off"
embed_s garbage_off 3 "garbage.off: line 1: '+\\xa8/\\x16%\\x9b\`xy" "$C/garbage.off" # ... is not an OFF header keyword
embed_s garbage_obj 3 "garbage.obj: line 1: unknown OBJ statement '+\\xa8/\\x16%" "$C/garbage.obj"
embed_s garbage_ply 3 "line 1: not a PLY file (the first line is not 'ply')" "$C/garbage.ply"
embed_s garbage_stl 3 "the header announces" "$C/garbage.stl"
embed_s garbage_gocad 3 "garbage.ts: no TFACE line: not a GOCAD TSurf file" "$C/garbage.ts"
embed_s garbage_after_off_header 3 "line 2: the OFF header's vertex count '\\xdf' is not a non-negative integer" "$C/garbage_after_header.off"
embed_s garbage_binary_ply_body 3 "face 0: the list size 219 is larger than the rest of the file holds (only 179 bytes left" "$C/garbage_body.ply"
embed_s gocad_duplicate_id 3 "duplicate_id.ts: line 13: vertex id 6 is defined twice" "$C/duplicate_id.ts"
embed_s gocad_undefined_id 3 "vertex id 4000 is not defined (no VRTX, PVRTX or ATOM with that id)" "$C/undefined_id.ts"
embed_s gocad_bad_coordinate 3 "bad_coordinate.ts: line 9: vertex 3: coordinate 'zero' is not a number" "$C/bad_coordinate.ts"
embed_s gocad_unknown_keyword 3 "unknown GOCAD TSurf keyword 'SURFACE'" "$C/unknown_keyword.ts"
embed_s unsupported_extension 3 "unsupported file extension 'xyz' (supported: off, obj, ply, stl, ts)" "$C/mesh.xyz"
embed_s mesh_is_a_directory 3 "directory.off' is a directory, not a file" "$C/directory.off"
embed_s missing_mesh 3 "missing.off': no such file" "$C/missing.off"

# ---------------------------------------------------------------------------------------
echo "--- landmark files"
echo "0 10 twenty 30 40 50" >"$C/garbage_text.cones"
echo "0 10 -20 30 40 50" >"$C/negative.cones"
echo "0 10 99999999999999999999999 30 40 50" >"$C/beyond_uint64.cones"
echo "0 10 9223372036854775808 30 40 50" >"$C/beyond_int64.cones"
echo "0 10 20 30 162 50" >"$C/out_of_range.cones"
echo "0 10 20 30 40 30 60" >"$C/duplicate.cones"
echo "0 10 20 30" >"$C/four.cones"
printf '0 10 20\n30 40\n' >"$C/ambiguous.cones"
echo "0 10 1.5 30 40" >"$C/float.cones"
echo "0 10 12abc 30 40" >"$C/suffix.cones"
garbage 500 3 >"$C/binary.cones"
: >"$C/empty.cones"
printf '# only comments\n\n' >"$C/comments.cones"
printf '\n0 1 2 3 4 5\n' >"$C/s.selection.txt"
mkdir -p "$C/directory.cones"
echo "0 4 8 40 80 76" >"$C/interior.cones"
echo "0 8 4 44 80 76 72 36" >"$C/unordered.cones"
echo "0 4 8 80" >"$C/four_disk.cones"
cones_s landmark_garbage_text 3 "line 1: 'twenty' is not a vertex index (a non-negative integer)" "$C/garbage_text.cones"
cones_s landmark_negative 3 "line 1: negative vertex index '-20'" "$C/negative.cones"
cones_s landmark_beyond_uint64 3 "line 1: vertex index '99999999999999999999999' is too large" "$C/beyond_uint64.cones"
cones_s landmark_beyond_int64 3 "landmark 2 is vertex 9223372036854775808, but the mesh has only 162 vertices" "$C/beyond_int64.cones"
cones_s landmark_out_of_range 3 "landmark 4 is vertex 162, but the mesh has only 162 vertices (valid indices are 0 to 161)" "$C/out_of_range.cones"
cones_s landmark_duplicate 3 "vertex 30 is given twice, as landmarks 3 and 5" "$C/duplicate.cones"
cones_s landmark_too_few 3 "4 landmarks are given, but the sphere-type orbifold needs at least 5" "$C/four.cones"
cones_s landmark_ambiguous_layout 3 "line 1: ambiguous layout: give all indices on one line, or one index per line" "$C/ambiguous.cones"
cones_s landmark_float 3 "line 1: '1.5' is not a vertex index" "$C/float.cones"
cones_s landmark_suffix 3 "line 1: '12abc' is not a vertex index" "$C/suffix.cones"
cones_s landmark_binary 3 "binary.cones: line 1: 'S\\xc3}\\xfd\$\\xefk" "$C/binary.cones"
cones_s landmark_empty 3 "empty.cones: the file holds no vertex index" "$C/empty.cones"
cones_s landmark_only_comments 3 "comments.cones: the file holds no vertex index" "$C/comments.cones"
cones_s landmark_selection_line_1_empty 3 "line 1 of the selection file holds no vertex index" "$C/s.selection.txt"
cones_s landmark_directory 3 "directory.cones' is a directory, not a file" "$C/directory.cones"
cones_s landmark_missing 3 "missing.cones': no such file" "$C/missing.cones"
run_item landmark_inside_disk 3 "landmark 3 (vertex 40) is not on the boundary loop" \
  embed --mesh "$D" --cones "$C/interior.cones" --out "$O/x.obj"
run_item landmark_disk_order 3 "the landmarks are not in boundary order" \
  embed --mesh "$D" --cones "$C/unordered.cones" --out "$O/x.obj"
run_item landmark_too_few_disk 3 "4 landmarks are given, but the disk-type orbifold needs at least 5" \
  embed --mesh "$D" --cones "$C/four_disk.cones" --out "$O/x.obj"

# ---------------------------------------------------------------------------------------
echo "--- command line: usage (2) and output files (1)"
run_item usage_unknown_option 2 "unknown option '--bogus' (see --help)" embed --mesh "$S" --cones "$SC" --out "$O/x.obj" --bogus 1
run_item usage_bad_orbifold 2 "--orbifold must be 'sphere' or 'disk', got 'torus'" \
  embed --mesh "$S" --cones "$SC" --orbifold torus --out "$O/x.obj"
run_item usage_missing_cones 2 "missing option --cones" embed --mesh "$S" --out "$O/x.obj"
run_item usage_bad_weights 2 "--weights must be cotan, mvc or uniform, got 'harmonic'" \
  embed --mesh "$S" --cones "$SC" --weights harmonic --out "$O/x.obj"
run_item output_directory_missing 1 "cannot write '$O/nodir/x.obj'" embed --mesh "$S" --cones "$SC" --out "$O/nodir/x.obj"

# ---------------------------------------------------------------------------------------
echo "--- landmarks command"
run_item landmarks_non_manifold 3 "non-manifold edge" landmarks --mesh "$C/nm_edge.off" --count 7 --out "$O/l.txt"
run_item landmarks_nan 3 "has a non-finite coordinate (nan" landmarks --mesh "$C/nan.off" --count 7 --out "$O/l.txt"
run_item landmarks_empty_mesh 3 "the mesh has no face" landmarks --mesh "$C/no_face.off" --count 7 --out "$O/l.txt"
run_item landmarks_two_disks 3 "the mesh has 2 connected components" landmarks --mesh "$C/two_disks.off" --count 7 --out "$O/l.txt"
run_item landmarks_count_too_large 2 "--count is larger than the number of vertices (162)" landmarks --mesh "$S" --count 200 --out "$O/l.txt"
run_item landmarks_count_zero 2 "--count must be between 1 and 100000, got 0" landmarks --mesh "$S" --count 0 --out "$O/l.txt"
run_item landmarks_count_garbage 2 "--count must be an integer, got 'seven'" landmarks --mesh "$S" --count seven --out "$O/l.txt"
run_item landmarks_short_boundary 3 "the boundary has fewer than 40 vertices" landmarks --mesh "$D" --count 40 --out "$O/l.txt"
run_item landmarks_output_directory_missing 1 "cannot write '$O/nodir/l.txt'" landmarks --mesh "$S" --count 7 --out "$O/nodir/l.txt"

# ---------------------------------------------------------------------------------------
echo "--- map command"
run_item map_bad_target_mesh 3 "vertex 5 (line 8) has a non-finite coordinate" \
  map --source "$S" --source-cones "$SC" --target "$C/nan.off" --target-cones "$SC" --out "$O/m.txt"
run_item map_bad_source_cones 3 "'twenty' is not a vertex index" \
  map --source "$S" --source-cones "$C/garbage_text.cones" --target "$S" --target-cones "$SC" --out "$O/m.txt"
run_item map_sphere_to_disk 3 "the source is closed but the target is a disk" \
  map --source "$S" --source-cones "$SC" --target "$D" --target-cones "$DC" --out "$O/m.txt"
run_item map_landmark_counts 3 "the source has 7 landmarks and the target 8" \
  map --source "$S" --source-cones "$SC" --target "$S" --target-cones "$C/d.cones" --out "$O/m.txt"
run_item map_missing_option 2 "missing option --target" map --source "$S" --source-cones "$SC" --target-cones "$SC" --out "$O/m.txt"
run_item map_colors_unwritable 1 "cannot write '$O/nodir/c.ply'" \
  map --source "$S" --source-cones "$SC" --target "$S" --target-cones "$SC" --out "$O/m.txt" --colors-out "$O/nodir/c.ply"

# ---------------------------------------------------------------------------------------
echo "--- collection command"
manifest() { local f="$C/$1.manifest"; shift; printf '%s\n' "$@" >"$f"; }
manifest missing_mesh "s.off s.cones" "nowhere.off s.cones"
manifest bad_mesh "s.off s.cones" "nm_vertex.off s.cones"
manifest missing_cones "s.off s.cones" "s2.off nowhere.cones"
manifest malformed "s.off s.cones" "s2.off"
manifest one "s.off s.cones"
manifest mixed "s.off s.cones" "d.off d.cones"
: >"$C/empty.manifest"
garbage 400 11 >"$C/binary.manifest"
mkdir -p "$C/directory.manifest"
coll() { run_item "$1" "$2" "$3" collection --manifest "$C/$4" --out "$O/coll"; }
coll collection_missing_mesh 3 "nowhere.off': no such file" missing_mesh.manifest
coll collection_bad_mesh 3 "nm_vertex.off: non-manifold vertex: the faces around vertex 0" bad_mesh.manifest
coll collection_missing_cones 3 "nowhere.cones': no such file" missing_cones.manifest
coll collection_malformed_line 3 "malformed.manifest: line 2: expected 'mesh_path cones_path', found 1 field" malformed.manifest
coll collection_one_mesh 3 "the manifest lists 1 mesh, a collection needs at least 2" one.manifest
coll collection_empty_manifest 3 "the manifest lists 0 meshes, a collection needs at least 2" empty.manifest
coll collection_mixed_types 3 "d.off: its topology or number of landmarks differs from the first mesh's" mixed.manifest
coll collection_binary_manifest 3 "binary.manifest: line 2: expected 'mesh_path cones_path', found 1 field" binary.manifest
coll collection_manifest_directory 3 "directory.manifest' is a directory, not a file" directory.manifest
coll collection_missing_manifest 3 "nowhere.manifest': no such file" nowhere.manifest

# --repair on every mesh of the corpus, with the sphere and the disk landmarks: either a
# certified embedding or a one-line refusal (exit 2 or 3) with no output left; never a crash,
# a hang, or a result that is not certified
run_repaired() {
  local name="$1"
  shift
  cases=$((cases + 1))
  rm -rf "$O"
  mkdir -p "$O"
  (timeout "$limit" "$prog" "$@" >"$tmp/stdout" 2>"$tmp/stderr"; exit $?) 2>/dev/null
  local rc=$? problem="" err
  err="$(head -c 600 "$tmp/stderr")"
  if [ $rc -eq 124 ]; then problem="hang: killed after $limit s"
  elif [ $rc -ge 128 ]; then problem="crash: killed by signal $((rc - 128))"
  elif [ $rc -eq 0 ]; then
    grep -q "certified bijective" "$tmp/stdout" || problem="exit 0 without a certified embedding"
    [ -s "$O/x.obj" ] || problem="exit 0 without output"
  elif [ $rc -ne 2 ] && [ $rc -ne 3 ]; then problem="exit status $rc"
  elif [ "$(wc -l <"$tmp/stderr")" -ne 1 ] || [ "${err#hyperbolic_orbifold_tutte: }" = "$err" ]; then problem="stderr is not one line from the program"
  elif [ -n "$(find "$O" -type f)" ]; then problem="output left behind: $(find "$O" -type f | sed "s|$O/||" | tr '\n' ' ')"
  fi
  if [ -n "$problem" ]; then
    failures=$((failures + 1)); echo "FAIL $name: $problem -- stderr: $err"
  elif [ $verbose -eq 1 ]; then
    if [ $rc -eq 0 ]; then echo "ok   $name (repaired and certified)"; else echo "ok   $name (exit $rc): ${err#hyperbolic_orbifold_tutte: }"; fi
  fi
}
for f in "$C"/*.off "$C"/*.obj "$C"/*.ply "$C"/*.stl "$C"/*.ts; do
  [ -f "$f" ] || continue
  b="$(basename "$f")"
  run_repaired "repair_sphere_cones:$b" embed --mesh "$f" --cones "$SC" --repair --largest-component --out "$O/x.obj"
  run_repaired "repair_disk_cones:$b" embed --mesh "$f" --cones "$DC" --repair --snap-landmarks --out "$O/x.obj"
done

echo "$cases corpus items, $failures failed"
[ "$failures" -eq 0 ]
