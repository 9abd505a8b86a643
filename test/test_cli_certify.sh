#!/usr/bin/env bash
# The `certify` command: test_cli_certify.sh PROGRAM CASE DATA. Embeddings written by `embed`
# are certified (exit 0, a report with every count), files edited into wrong embeddings are
# refused by the check that names their fault (exit 4, one line, the report says the same),
# and bad input is an error (2: usage, 3: data, 1: files) with one line and no report left.
set -u
prog="$1"; case_name="$2"; data="${3:-}"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

expect_error() { # expect_error STATUS OUTFILE ARGS...: that exit status, one line on stderr, no output file
  local want="$1" outfile="$2"; shift 2
  "$prog" "$@" >"$tmp/stdout" 2>"$tmp/stderr"; local rc=$?
  [ $rc -eq "$want" ] || fail "exit $rc (expected $want) for: $* -- $(cat "$tmp/stderr")"
  [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "stderr is not one line for: $* -- $(cat "$tmp/stderr")"
  [ ! -e "$outfile" ] || fail "output file left behind for: $*"
  [ ! -e "$outfile.tmp" ] || fail "temporary file left behind for: $*"
  echo "ok (exit $rc): $(cat "$tmp/stderr")"
}

expect_rejected() { # expect_rejected CHECK MESH OBJ CONES [ARGS...]: exit 4, one line naming CHECK, the report saying so
  local check="$1" mesh="$2" obj="$3" cones="$4"; shift 4
  rm -f "$tmp/r.json"
  "$prog" certify --mesh "$mesh" --embedding "$obj" --cones "$cones" --report "$tmp/r.json" "$@" >"$tmp/stdout" 2>"$tmp/stderr"; local rc=$?
  [ $rc -eq 4 ] || fail "exit $rc (expected 4) for $obj -- $(cat "$tmp/stderr")"
  [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "stderr is not one line for $obj -- $(cat "$tmp/stderr")"
  grep -q "not certified: $check: " "$tmp/stderr" || fail "$obj: expected check $check -- $(cat "$tmp/stderr")"
  grep -q '"certified": false' "$tmp/r.json" || fail "$obj: report verdict"
  grep -q "\"first_failed_check\": \"$check\"" "$tmp/r.json" || fail "$obj: report's first failed check"
  echo "ok (exit 4): $(cat "$tmp/stderr")"
}

json_ok() { # the report is JSON (when python3 is there)
  if command -v python3 >/dev/null; then python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$1" || fail "$1 is not JSON"; fi
}

# the number of vertices on a boundary of an OFF triangle mesh: edges in one face only
boundary_vertices() {
  awk 'NR == 2 { n = $1 } NR > 2 + n && NF >= 4 {
         for(i = 0; i < 3; i++) { a = $(2 + i); b = $(2 + (i + 1) % 3); k = (a < b) ? a " " b : b " " a; e[k]++ } }
       END { for(k in e) if(e[k] == 1) { split(k, v, " "); bv[v[1]]; bv[v[2]] } c = 0; for(x in bv) c++; print c }' "$1"
}

bear="$data/meshes/bear.off"
mushroom="$data/meshes/mushroom.off"

case "$case_name" in
  sphere)
    "$prog" landmarks --mesh "$bear" --count 7 --out "$tmp/bear.cones" >/dev/null || fail "landmarks"
    "$prog" embed --mesh "$bear" --cones "$tmp/bear.cones" --out "$tmp/b.obj" >/dev/null || fail "embed"
    "$prog" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --report "$tmp/b.json" >"$tmp/out" \
      || fail "certify refused embed's own output: $(cat "$tmp/out")"
    grep -q "^certified: " "$tmp/out" || fail "stdout: $(cat "$tmp/out")"
    json_ok "$tmp/b.json"
    grep -q '"certified": true' "$tmp/b.json" || fail "report verdict"
    grep -q '"first_failed_check": null' "$tmp/b.json" || fail "report first failed check"
    grep -q '"orbifold": "sphere"' "$tmp/b.json" || fail "report orbifold"
    nv=$(grep -c '^v ' "$tmp/b.obj"); nvt=$(grep -c '^vt ' "$tmp/b.obj"); nf=$(grep -c '^f ' "$tmp/b.obj")
    grep -q "\"faces\": $nf," "$tmp/b.json" || fail "report faces"
    # the cut is a simple path through the cones: its inner vertices have two points each
    grep -q "\"seam_edges\": $((nvt - nv + 1))," "$tmp/b.json" || fail "report seam edges ($((nvt - nv + 1)) expected)"
    for c in repeated_face mesh_faces finite inside_disk cones border degenerate_face orientation angle_sum seams area; do
      grep -q "\"$c\": {\"run\": true, \"checked\": [0-9]*, \"failures\": 0, \"first_failure\": null}" "$tmp/b.json" || fail "report check $c"
    done
    # the cones in another order: the order is found, not assumed
    tac "$tmp/bear.cones" > "$tmp/bear.rev"
    "$prog" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.rev" >/dev/null || fail "cones in another order"
    # --cone-orders of 2 are the default; --orbifold sphere is what the mesh is
    "$prog" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --cone-orders 2,2,2,2,2,2,2 --orbifold sphere \
      >/dev/null || fail "--cone-orders 2,...,2"
    echo ok ;;
  disk)
    echo "1166 1785 147 932 2251 139" > "$tmp/m.cones"
    "$prog" embed --mesh "$mushroom" --cones "$tmp/m.cones" --out "$tmp/m.obj" >/dev/null || fail "embed"
    "$prog" certify --mesh "$mushroom" --embedding "$tmp/m.obj" --cones "$tmp/m.cones" --report "$tmp/m.json" >/dev/null \
      || fail "certify refused embed's own output"
    json_ok "$tmp/m.json"
    grep -q '"certified": true' "$tmp/m.json" || fail "report verdict"
    grep -q '"orbifold": "disk"' "$tmp/m.json" || fail "report orbifold"
    grep -q '"seam_edges": 0,' "$tmp/m.json" || fail "a disk has no seam"
    nb=$(boundary_vertices "$mushroom")
    grep -q "\"border_vertices\": $nb," "$tmp/m.json" || fail "report boundary vertices ($nb expected)"
    grep -q "\"border\": {\"run\": true, \"checked\": $((nb - 6)), \"failures\": 0" "$tmp/m.json" || fail "report border check"
    # a disk's corners are right angles: other orders are refused (the tiles are not built)
    expect_error 3 "$tmp/r2.json" certify --mesh "$mushroom" --embedding "$tmp/m.obj" --cones "$tmp/m.cones" --cone-orders 2,2,2,2,2,3 --report "$tmp/r2.json"
    grep -q -- "--cone-orders: .*sphere-type" "$tmp/stderr" || fail "orders on a disk refused without saying why"
    echo ok ;;
  recentred)
    # a capsule whose far end is too squeezed for the tile (test_cli.sh, embed_recentre): embed
    # --recentre writes it in a moved frame, which certify needs (--frame, from the report)
    awk -v L=50 -v S=24 -f "$(dirname "${BASH_SOURCE[0]}")/capsule.awk" > "$tmp/tube.off" 2> "$tmp/tube.cones"
    "$prog" embed --mesh "$tmp/tube.off" --cones "$tmp/tube.cones" --out "$tmp/t.obj" --report "$tmp/t.json" --recentre >/dev/null \
      || fail "embed --recentre"
    grep -q '"recentred": true' "$tmp/t.json" || fail "not recentred"
    frame=$(sed -n 's/.*"frame": {"a": \[\([^]]*\)\], "b": \[\([^]]*\)\]}.*/\1,\2/p' "$tmp/t.json" | tr -d ' ')
    [ -n "$frame" ] || fail "no frame in the report"
    "$prog" certify --mesh "$tmp/tube.off" --embedding "$tmp/t.obj" --cones "$tmp/tube.cones" --frame "$frame" >"$tmp/out" \
      || fail "certify --frame $frame refused embed's recentred output: $(cat "$tmp/out")"
    expect_rejected cones "$tmp/tube.off" "$tmp/t.obj" "$tmp/tube.cones"
    expect_error 2 "$tmp/r2.json" certify --mesh "$tmp/tube.off" --embedding "$tmp/t.obj" --cones "$tmp/tube.cones" --frame 1,0,2 --report "$tmp/r2.json"
    expect_error 2 "$tmp/r2.json" certify --mesh "$tmp/tube.off" --embedding "$tmp/t.obj" --cones "$tmp/tube.cones" --frame 0,0,1,0 --report "$tmp/r2.json"
    echo "ok (frame $frame)" ;;
  charts)
    # capsules of length 80 and 150 whose tip is a landmark: embed solves the protrusion in a
    # chart around the tip cone's image and writes those points as '# hot vtc' lines after the
    # chart table ('# hot chart'), their vt lines only rounded tile points. certify reads the
    # charts and certifies in their coordinates; files edited into wrong ones are refused by
    # the check that names the fault (test/chart_edit.awk), and the file without its chart lines
    # is refused (its vt lines are too coarse near the cone)
    d="$(dirname "${BASH_SOURCE[0]}")"
    for L in 80 150; do
      awk -v L=$L -v S=24 -f "$d/capsule.awk" > "$tmp/c$L.off" 2> "$tmp/ring.cones"
      nv=$(sed -n 2p "$tmp/c$L.off" | awk '{print $1}')
      echo "$(cat "$tmp/ring.cones") $((nv - 1))" > "$tmp/c$L.cones"
      "$prog" embed --mesh "$tmp/c$L.off" --cones "$tmp/c$L.cones" --out "$tmp/e$L.obj" >/dev/null || fail "embed $L"
      nc=$(grep -c '^# hot vtc ' "$tmp/e$L.obj"); nch=$(grep -c '^# hot chart ' "$tmp/e$L.obj")
      [ "$nc" -gt 1000 ] && [ "$nch" -ge 1 ] || fail "length $L: $nch charts, $nc chart points (the case no longer tests charts)"
      "$prog" certify --mesh "$tmp/c$L.off" --embedding "$tmp/e$L.obj" --cones "$tmp/c$L.cones" --report "$tmp/r$L.json" >"$tmp/out" 2>"$tmp/stderr" \
        || fail "certify refused embed's charted output (length $L): $(cat "$tmp/stderr")"
      grep -q "^certified: .* faces in $nch charts\? around cone images" "$tmp/out" || fail "stdout: $(cat "$tmp/out")"
      json_ok "$tmp/r$L.json"
      grep -q '"certified": true' "$tmp/r$L.json" || fail "report verdict ($L)"
      grep -q "\"charts\": $nch," "$tmp/r$L.json" || fail "report charts ($L)"
      grep -q "\"chart_points\": $nc," "$tmp/r$L.json" || fail "report chart points ($L)"
      grep -q "\"chart_vtc_lines\": $nc," "$tmp/r$L.json" || fail "report vtc lines ($L)"
      grep -q '"chart_points_not_read": 0,' "$tmp/r$L.json" || fail "report: chart points not read ($L)"
      grep -q '"charted_faces": [1-9][0-9][0-9][0-9]' "$tmp/r$L.json" || fail "report: charted faces ($L)"
      grep -q '"chart_seam_edges": [1-9]' "$tmp/r$L.json" || fail "report: no seam between charts checked as a rotation ($L)"
      grep -q '"charts": {"run": true, "checked": [1-9][0-9]*, "failures": 0' "$tmp/r$L.json" || fail "report: charts check ($L)"
      echo "ok: length $L: $(cat "$tmp/out")"
    done
    # deeper than double resolves in the tile (|w| < 1e-20 at length 150): a flipped face, a seam
    # side moved by 1e-9 of its distance to the cone
    m="$tmp/c150.off"; o="$tmp/e150.obj"; cn="$tmp/c150.cones"
    awk -v mode=flip -v depth=1e-20 -f "$d/chart_edit.awk" "$o" "$o" > "$tmp/flip.obj" || fail "chart_edit flip"
    expect_rejected orientation "$m" "$tmp/flip.obj" "$cn"
    grep -q "(in chart 0) is negatively oriented" "$tmp/stderr" || fail "the flipped face is not named in its chart"
    awk -v mode=seam -v depth=1e-20 -f "$d/chart_edit.awk" "$o" "$o" > "$tmp/seam.obj" || fail "chart_edit seam"
    expect_rejected seams "$m" "$tmp/seam.obj" "$cn"
    grep -q "a rotation about the cone's image" "$tmp/stderr" || fail "the seam is not checked as a rotation"
    # the other edits on length 80
    m="$tmp/c80.off"; o="$tmp/e80.obj"; cn="$tmp/c80.cones"
    awk -v mode=flip -v depth=1e-15 -f "$d/chart_edit.awk" "$o" "$o" > "$tmp/flip.obj" || fail "chart_edit flip"
    expect_rejected orientation "$m" "$tmp/flip.obj" "$cn"
    awk -v mode=vt -f "$d/chart_edit.awk" "$o" "$o" > "$tmp/vt.obj" || fail "chart_edit vt"
    expect_rejected charts "$m" "$tmp/vt.obj" "$cn"
    grep -q "away from its vt line" "$tmp/stderr" || fail "the vt line is not named"
    awk -v mode=b -f "$d/chart_edit.awk" "$o" "$o" > "$tmp/b.obj" || fail "chart_edit b"
    expect_rejected charts "$m" "$tmp/b.obj" "$cn"
    grep -q "chart 0's origin is the tile point .* away from tile corner" "$tmp/stderr" || fail "wrong b: not the chart's origin"
    awk -v mode=corner -f "$d/chart_edit.awk" "$o" "$o" > "$tmp/corner.obj" || fail "chart_edit corner"
    expect_rejected charts "$m" "$tmp/corner.obj" "$cn"
    grep -q "chart 0's origin is the tile point .* away from tile corner" "$tmp/stderr" || fail "wrong corner: not the chart's origin"
    awk -v mode=cone -f "$d/chart_edit.awk" "$o" "$o" > "$tmp/cone.obj" || fail "chart_edit cone"
    expect_rejected cones "$m" "$tmp/cone.obj" "$cn"
    grep -q "in chart 0, not at its origin" "$tmp/stderr" || fail "the cone off its chart's origin is not named"
    # without its chart lines: the vt lines alone, too coarse near the cone: the tip cone is off
    # its corner by more than its (tiny) edges allow, faces are flipped and seams torn
    grep -v '^# hot ' "$o" > "$tmp/plain.obj"
    expect_rejected cones "$m" "$tmp/plain.obj" "$cn"
    grep -q '"charts": 0,' "$tmp/r.json" || fail "the plain file has no chart"
    grep -q '"orientation": {"run": true, "checked": [0-9]*, "failures": [1-9]' "$tmp/r.json" || fail "the plain file has no flipped face"
    # malformed chart lines: data errors (3), one line, no report
    sed 's/^# hot vtc \([0-9]*\) 0 /# hot vtc \1 7 /' "$o" > "$tmp/bad1.obj"
    expect_error 3 "$tmp/r2.json" certify --mesh "$m" --embedding "$tmp/bad1.obj" --cones "$cn" --report "$tmp/r2.json"
    grep -q "is not a chart of the table" "$tmp/stderr" || fail "vtc of an unknown chart"
    sed 's/^\(# hot chart 0 \)[^ ]*/\1x/' "$o" > "$tmp/bad2.obj"
    expect_error 3 "$tmp/r2.json" certify --mesh "$m" --embedding "$tmp/bad2.obj" --cones "$cn" --report "$tmp/r2.json"
    awk '{ print } /^# hot vtc / && !done { print; done = 1 }' "$o" > "$tmp/bad3.obj"
    expect_error 3 "$tmp/r2.json" certify --mesh "$m" --embedding "$tmp/bad3.obj" --cones "$cn" --report "$tmp/r2.json"
    grep -q "given a chart point twice" "$tmp/stderr" || fail "a vt given two chart points"
    echo ok ;;
  wrong)
    "$prog" landmarks --mesh "$bear" --count 7 --out "$tmp/bear.cones" >/dev/null || fail "landmarks"
    "$prog" embed --mesh "$bear" --cones "$tmp/bear.cones" --out "$tmp/b.obj" >/dev/null || fail "embed"
    # a NaN and a point on the unit circle (vt line 100)
    awk '/^vt / && ++n == 100 { print "vt nan " $3; next } { print }' "$tmp/b.obj" > "$tmp/nan.obj"
    expect_rejected finite "$bear" "$tmp/nan.obj" "$tmp/bear.cones"
    awk '/^vt / && ++n == 100 { print "vt 1 0"; next } { print }' "$tmp/b.obj" > "$tmp/out.obj"
    expect_rejected inside_disk "$bear" "$tmp/out.obj" "$tmp/bear.cones"
    # face 20 given twice; face 0 reversed
    awk '{ print } /^f / && ++n == 20 { print }' "$tmp/b.obj" > "$tmp/rep.obj"
    expect_rejected repeated_face "$bear" "$tmp/rep.obj" "$tmp/bear.cones"
    grep -q '"message": "face 20 ' "$tmp/r.json" || fail "the repeated face is face 20"
    awk '/^f / && ++n == 1 { print "f " $2 " " $4 " " $3; next } { print }' "$tmp/b.obj" > "$tmp/rev.obj"
    expect_rejected mesh_faces "$bear" "$tmp/rev.obj" "$tmp/bear.cones"
    awk '/^f / && ++n == 1 { print "f " $2 " " $2 " " $4; next } { print }' "$tmp/b.obj" > "$tmp/degenerate.obj"
    expect_rejected mesh_faces "$bear" "$tmp/degenerate.obj" "$tmp/bear.cones"
    grep -q "repeats a vertex" "$tmp/stderr" || fail "the face with a repeated vertex is not named so"
    # every coordinate squared, and everything shrunk: the cones leave the tile's corners
    awk '/^vt / { printf "vt %.17g %.17g\n", $2 * $2 - $3 * $3, 2 * $2 * $3; next } { print }' "$tmp/b.obj" > "$tmp/sq.obj"
    expect_rejected cones "$bear" "$tmp/sq.obj" "$tmp/bear.cones"
    awk '/^vt / { printf "vt %.17g %.17g\n", 0.9 * $2, 0.9 * $3; next } { print }' "$tmp/b.obj" > "$tmp/shrunk.obj"
    expect_rejected cones "$bear" "$tmp/shrunk.obj" "$tmp/bear.cones"
    # two neighbours' points swapped: the first face from the 5000th on whose first two vertices
    # are not cones and have one point each (off the cut) turns over
    awk -v cones="$(cat "$tmp/bear.cones" | tr '\n' ' ')" '
      BEGIN { split(cones, c, " "); for(i in c) cone[c[i]] = 1 }
      NR == FNR { if($1 == "f") for(i = 2; i <= 4; i++) { split($i, a, "/"); if(!((a[1] " " a[2]) in seen)) { seen[a[1] " " a[2]]; nvt[a[1]]++ } } next }
      FNR == 1 { nf = 0; nt = 0 }
      $1 == "f" && !done && ++nf >= 5000 { split($2, a, "/"); split($3, b, "/");
        if(nvt[a[1]] == 1 && nvt[b[1]] == 1 && !((a[1] - 1) in cone) && !((b[1] - 1) in cone)) { ta = a[2]; tb = b[2]; done = 1 } }
      { line[FNR] = $0; if($1 == "vt") vt[++nt] = FNR }
      END { l1 = line[vt[ta]]; line[vt[ta]] = line[vt[tb]]; line[vt[tb]] = l1; for(i = 1; i <= FNR; i++) print line[i] }' \
      "$tmp/b.obj" "$tmp/b.obj" > "$tmp/swap.obj"
    [ "$(grep -c '' "$tmp/swap.obj")" -eq "$(grep -c '' "$tmp/b.obj")" ] || fail "swap.obj"
    ! cmp -s "$tmp/swap.obj" "$tmp/b.obj" || fail "nothing swapped"
    expect_rejected orientation "$bear" "$tmp/swap.obj" "$tmp/bear.cones"
    echo ok ;;
  errors)
    "$prog" landmarks --mesh "$bear" --count 7 --out "$tmp/bear.cones" >/dev/null || fail "landmarks"
    "$prog" embed --mesh "$bear" --cones "$tmp/bear.cones" --out "$tmp/b.obj" >/dev/null || fail "embed"
    r="$tmp/r.json"
    expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/none.obj" --cones "$tmp/bear.cones" --report "$r"
    expect_error 3 "$r" certify --mesh "$tmp/none.off" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --report "$r"
    : > "$tmp/empty.obj"
    expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/empty.obj" --cones "$tmp/bear.cones" --report "$r"
    head -c 3000 "$bear" | tr 'a-z0-9' '#@!$%^&*()_+=-[]{}|;:,.<>?~' > "$tmp/junk.obj"
    expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/junk.obj" --cones "$tmp/bear.cones" --report "$r"
    # an OBJ face without point indices, a quad, a point index beyond the vt lines
    awk '/^f / && ++n == 3 { split($2, a, "/"); split($3, b, "/"); split($4, c, "/"); print "f " a[1] " " b[1] " " c[1]; next } { print }' \
      "$tmp/b.obj" > "$tmp/novt.obj"
    expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/novt.obj" --cones "$tmp/bear.cones" --report "$r"
    grep -q "no point (vt) index" "$tmp/stderr" || fail "the reason is not the missing vt index"
    awk '/^f / && ++n == 3 { print $0 " " $2; next } { print }' "$tmp/b.obj" > "$tmp/quad.obj"
    expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/quad.obj" --cones "$tmp/bear.cones" --report "$r"
    awk '/^f / && ++n == 3 { print "f 1/999999 2/1 3/1"; next } { print }' "$tmp/b.obj" > "$tmp/range.obj"
    expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/range.obj" --cones "$tmp/bear.cones" --report "$r"
    # the embedding of another mesh
    echo "1166 1785 147 932 2251 139" > "$tmp/m.cones"
    expect_error 3 "$r" certify --mesh "$mushroom" --embedding "$tmp/b.obj" --cones "$tmp/m.cones" --report "$r"
    grep -q "not an embedding of this mesh" "$tmp/stderr" || fail "the reason is not the other mesh"
    # cones: too few, repeated, beyond the mesh
    echo "1 2 3 4" > "$tmp/four.cones"; echo "1 2 3 4 4" > "$tmp/dup.cones"; echo "1 2 3 4 99999999" > "$tmp/range.cones"
    for c in four dup range; do
      expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/$c.cones" --report "$r"
    done
    # --cone-orders: one per cone, at least 2, hyperbolic (orders that are not the map's: the
    # case orders)
    expect_error 2 "$r" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --cone-orders 2,2,2,2,2,2,1 --report "$r"
    head -n 3 "$tmp/bear.cones" > "$tmp/three.cones"
    expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/three.cones" --cone-orders 2,3,6 --report "$r"
    grep -q -- "--cone-orders: .*not hyperbolic" "$tmp/stderr" || fail "(2,3,6) refused without saying why"
    expect_error 2 "$r" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --cone-orders 2,2 --report "$r"
    expect_error 2 "$r" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --cone-orders two --report "$r"
    # the orbifold type the mesh is not; usage
    expect_error 3 "$r" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --orbifold disk --report "$r"
    expect_error 2 "$r" certify --mesh "$bear" --cones "$tmp/bear.cones" --report "$r"
    expect_error 2 "$r" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --bogus 1
    # the report cannot be written: a file error, nothing left
    expect_error 1 "$tmp/nodir/r.json" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --report "$tmp/nodir/r.json"
    echo ok ;;
  orders)
    # cones of orders other than 2 (issue 22): embed --cone-orders takes one order per landmark
    # in the cones file's order, and so does certify; the checker finds on the map which tile
    # corner each cone is at, which gives the sequence of the orders along the tile's boundary
    # (the cut's order, which embed's report gives as landmark_order_used and cone_orders)
    echo "8768 4116 9726" > "$tmp/bear.cones"
    "$prog" embed --mesh "$bear" --cones "$tmp/bear.cones" --cone-orders 2,3,7 --out "$tmp/b.obj" --report "$tmp/e.json" >/dev/null \
      || fail "embed (2,3,7)"
    used=$(tr -d ' \n' < "$tmp/e.json" | sed -n 's/.*"landmark_order_used":\[\([0-9,]*\)\].*/\1/p')
    cut_orders=$(tr -d ' \n' < "$tmp/e.json" | sed -n 's/.*"cone_orders":\[\([0-9,]*\)\].*/\1/p')
    echo "embed: cut order $used, orders $cut_orders"
    "$prog" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --cone-orders 2,3,7 --report "$tmp/c.json" >"$tmp/out" \
      || fail "certify (2,3,7) refused embed's output: $(cat "$tmp/out")"
    grep -q "^certified: .* with 3 cones of orders 2,3,7 (" "$tmp/out" || fail "stdout: $(cat "$tmp/out")"
    json_ok "$tmp/c.json"
    grep -q '"certified": true' "$tmp/c.json" || fail "report verdict"
    for c in repeated_face mesh_faces finite inside_disk charts cones border degenerate_face orientation angle_sum seams area; do
      grep -q "\"$c\": {\"run\": true, \"checked\": [0-9]*, \"failures\": 0, \"first_failure\": null}" "$tmp/c.json" || fail "report check $c"
    done
    grep -q '"cone_orders": \[2, 3, 7\],' "$tmp/c.json" || fail "report: the orders given"
    grep -q '"cone_orders_found": \[2, 3, 7\],' "$tmp/c.json" || fail "report: the orders found"
    measured=$(sed -n 's/.*"cone_orders_measured": \[\([^]]*\)\].*/\1/p' "$tmp/c.json")
    echo "$measured" | awk -F', ' '{ split("2 3 7", p, " "); for(i = 1; i <= 3; i++) { e = $i - p[i]; if(e < 0) e = -e; if(e > 1e-9) exit 1 } }' \
      || fail "report: the orders measured, $measured"
    # the cone order found is the cut's: the j-th landmark of landmark_order_used at tile cone j
    order=$(tr -d ' \n' < "$tmp/c.json" | sed -n 's/.*"cone_order":\[\([-0-9,]*\)\].*/\1/p')
    awk -v used="$used" -v order="$order" -v cones="8768,4116,9726" 'BEGIN { split(used, u, ","); split(order, o, ","); split(cones, c, ",")
        for(i = 1; i <= 3; i++) if(u[o[i] + 1] != c[i]) exit 1 }' || fail "cone order $order is not the cut's ($used)"
    # the area is 2 pi (sum (1 - 1/p) - 2) = pi / 21
    grep -q '"expected_area": 0.14959965017094' "$tmp/c.json" || fail "report: expected area $(grep -o '"expected_area": [0-9.e-]*' "$tmp/c.json")"
    # the cones file in another order, the orders with it
    echo "9726 8768 4116" > "$tmp/bear2.cones"
    "$prog" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear2.cones" --cone-orders 7,2,3 >/dev/null \
      || fail "the cones in another order with their orders"
    # orders that are not the map's: on other cones (not the right permutation), or another
    # order; refused by the cones check, which says which cone has which order on the map
    expect_rejected cones "$bear" "$tmp/b.obj" "$tmp/bear.cones" --cone-orders 3,2,7
    grep -q "cone 0 (vertex 8768) has order 2.0000, not 3" "$tmp/stderr" || fail "3,2,7: the message does not name cone 0's order"
    grep -q '"cone_orders": \[3, 2, 7\],' "$tmp/r.json" || fail "report: the orders given (3,2,7)"
    expect_rejected cones "$bear" "$tmp/b.obj" "$tmp/bear2.cones" --cone-orders 2,7,3
    expect_rejected cones "$bear" "$tmp/b.obj" "$tmp/bear.cones" --cone-orders 2,3,8
    grep -q "at no corner of the tile" "$tmp/stderr" || fail "2,3,8: not at a corner"
    grep -q "cone 2 (vertex 9726) has order 7.0000, not 8" "$tmp/stderr" || fail "2,3,8: the message does not name cone 2's order"
    # without the orders: three cones of order 2 are too few
    expect_error 3 "$tmp/r2.json" certify --mesh "$bear" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --report "$tmp/r2.json"
    grep -q "at least 5 cones" "$tmp/stderr" || fail "3 cones of order 2: not refused as too few"
    # a cone's point (the first vt of vertex 4116, order 3) moved by 1e-6 off its corner
    vt=$(awk '/^f / { for(i = 2; i <= 4; i++) { split($i, a, "/"); if(a[1] == 4117) { print a[2]; exit } } }' "$tmp/b.obj")
    [ -n "$vt" ] || fail "no vt of vertex 4116"
    awk -v T="$vt" '/^vt / && ++n == T { printf "vt %.17g %.17g\n", $2 + 1e-6, $3; next } { print }' "$tmp/b.obj" > "$tmp/moved.obj"
    expect_rejected cones "$bear" "$tmp/moved.obj" "$tmp/bear.cones" --cone-orders 2,3,7
    grep -q "cone 1 (vertex 4116) is at .*, at no corner of the tile" "$tmp/stderr" || fail "the moved cone is not named"
    # (2,2,2,3) on armadillo with 4 landmarks and (2,2,3,3,4) on homer with 5 (issue 22)
    for mc in "armadillo 4 2,2,2,3 2,2,3,2" "homer 5 2,2,3,3,4 4,2,3,3,2"; do
      set -- $mc
      mesh="$data/meshes/$1.off"
      "$prog" landmarks --mesh "$mesh" --count $2 --out "$tmp/$1.cones" >/dev/null || fail "landmarks $1"
      "$prog" embed --mesh "$mesh" --cones "$tmp/$1.cones" --cone-orders $3 --out "$tmp/$1.obj" >/dev/null || fail "embed $1 ($3)"
      "$prog" certify --mesh "$mesh" --embedding "$tmp/$1.obj" --cones "$tmp/$1.cones" --cone-orders $3 --report "$tmp/$1.json" >"$tmp/out" \
        || fail "certify $1 ($3) refused embed's output: $(cat "$tmp/out")"
      grep -q "\"cone_orders_found\": \[$(echo $3 | sed 's/,/, /g')\]," "$tmp/$1.json" || fail "report $1: the orders found"
      echo "ok: $1: $(cat "$tmp/out")"
      expect_rejected cones "$mesh" "$tmp/$1.obj" "$tmp/$1.cones" --cone-orders $4
    done
    echo ok ;;
  genus_*)
    # closed meshes of genus g >= 1 (issue 22): embed's OBJ of the cut graph's polygon is
    # certified without a tile (the seams' isometries are read from the map); the mesh, its
    # landmark count and orders (empty: 2) per case
    name="${case_name#genus_}"
    case "$name" in
      eight) n=0; orders="" ;;
      elk) n=1; orders="" ;;
      knot1) n=2; orders="3,5" ;;
      femur) n=3; orders="" ;;
      joint) n=3; orders="2,3,7" ;;
      helmet) n=1; orders="" ;;
      *) fail "unknown mesh $name" ;;
    esac
    mesh="$data/meshes/$name.off"
    if [ "$n" -gt 0 ]; then
      "$prog" landmarks --mesh "$mesh" --count $n --out "$tmp/m.cones" >/dev/null || fail "landmarks $name"
    else
      : > "$tmp/m.cones"
    fi
    oo=(); [ -n "$orders" ] && oo=(--cone-orders "$orders")
    "$prog" embed --mesh "$mesh" --cones "$tmp/m.cones" "${oo[@]}" --out "$tmp/m.obj" >/dev/null || fail "embed $name"
    "$prog" certify --mesh "$mesh" --embedding "$tmp/m.obj" --cones "$tmp/m.cones" "${oo[@]}" --report "$tmp/c.json" >"$tmp/out" \
      || fail "certify $name refused embed's output: $(cat "$tmp/out")"
    grep -q "^certified: .* onto the closed genus-[1-9][0-9]* orbifold with $n cone" "$tmp/out" || fail "stdout: $(cat "$tmp/out")"
    echo "ok: $(cat "$tmp/out")"
    json_ok "$tmp/c.json"
    grep -q '"certified": true' "$tmp/c.json" || fail "report verdict"
    grep -q '"genus": [1-9]' "$tmp/c.json" || fail "report genus"
    for c in repeated_face mesh_faces finite inside_disk charts cones border degenerate_face orientation angle_sum seams area; do
      grep -q "\"$c\": {\"run\": true, \"checked\": [0-9]*, \"failures\": 0, \"first_failure\": null}" "$tmp/c.json" || fail "report check $c"
    done
    grep -q '"seam_isometries": [1-9]' "$tmp/c.json" || fail "report: seam isometries"
    [ -n "$orders" ] && { grep -q "\"cone_orders_found\": \[$(echo $orders | sed 's/,/, /g')\]," "$tmp/c.json" || fail "report: orders found"; }
    # tampered files, each refused for its reason
    # (1) a vt of an interior vertex (one point, in no seam) moved across a neighbour: flipped faces
    awk 'FNR == NR { if($1 == "f") for(i = 2; i <= 4; i++) { split($i, a, "/"); if(!((a[1], a[2]) in seen)) { seen[a[1], a[2]] = 1; nvt[a[1]]++ } }
                     next }
         FNR == 1 { pass2 = 1 }
         { lines[FNR] = $0 }
         $1 == "vt" { nt++; x[nt] = $2; y[nt] = $3 }
         $1 == "f" && !done { split($2, a, "/"); split($3, b, "/"); split($4, c, "/")
                              if(nvt[a[1]] == 1 && nvt[b[1]] == 1 && nvt[c[1]] == 1) { T = a[2]; N = b[2]; done = 1 } }
         END { t = 0; for(i = 1; i <= FNR; i++) { $0 = lines[i]
                 if($1 == "vt" && ++t == T) printf "vt %.17g %.17g\n", 2 * x[N] - x[T], 2 * y[N] - y[T]; else print lines[i] } }' \
      "$tmp/m.obj" "$tmp/m.obj" > "$tmp/flip.obj"
    cmp -s "$tmp/m.obj" "$tmp/flip.obj" && fail "no interior vertex to move"
    expect_rejected orientation "$mesh" "$tmp/flip.obj" "$tmp/m.cones" "${oo[@]}"
    # (2) one vt of a seam vertex (two points or more, not a cone) moved by 1e-6: the seam's isometry is broken
    vt=$(awk -v cones="$(cat "$tmp/m.cones")" 'BEGIN { n = split(cones, c); for(i = 1; i <= n; i++) cone[c[i] + 1] = 1 }
              $1 == "f" { for(i = 2; i <= 4; i++) { split($i, a, "/"); if(cone[a[1]]) continue
                          if(!((a[1], a[2]) in seen)) { seen[a[1], a[2]] = 1; if(++nvt[a[1]] == 2) { print a[2]; exit } } } }' \
         "$tmp/m.obj")
    [ -n "$vt" ] || fail "no seam vertex"
    awk -v T="$vt" '/^vt / && ++n == T { printf "vt %.17g %.17g\n", $2 + 1e-6, $3; next } { print }' "$tmp/m.obj" > "$tmp/moved.obj"
    "$prog" certify --mesh "$mesh" --embedding "$tmp/moved.obj" --cones "$tmp/m.cones" "${oo[@]}" --report "$tmp/r.json" >/dev/null 2>"$tmp/stderr"
    [ $? -eq 4 ] || fail "a seam copy moved by 1e-6 is certified -- $(cat "$tmp/stderr")"
    grep -q '"seams": {"run": true, "checked": [0-9]*, "failures": [1-9]' "$tmp/r.json" || fail "the moved seam copy does not fail the seams check"
    echo "ok (exit 4): seam copy moved: $(cat "$tmp/stderr"); seams: $(grep -o '"seams": {[^}]*' "$tmp/r.json" | head -c 300)"
    # (3) a cone claimed at one more vertex (an interior vertex): its angle sum is 2 pi, not pi
    extra=$(awk -v cones="$(cat "$tmp/m.cones")" 'BEGIN { n = split(cones, c); for(i = 1; i <= n; i++) cone[c[i]] = 1
                                                           for(v = 0; v in cone; v++); print v }')
    { cat "$tmp/m.cones"; echo "$extra"; } > "$tmp/extra.cones"
    eo=(); [ -n "$orders" ] && eo=(--cone-orders "$orders,2")
    expect_rejected angle_sum "$mesh" "$tmp/m.obj" "$tmp/extra.cones" "${eo[@]}"
    grep -q "(a cone) has an angle sum of 6.28" "$tmp/stderr" || fail "the extra cone is not named"
    if [ "$n" -gt 0 ]; then
      # (4) wrong orders: 3 for every cone of order 2 and 2 for the others
      wrong=$(awk -v n=$n -v o="$orders" 'BEGIN { split(o, p, ","); for(i = 1; i <= n; i++) printf "%s%d", (i > 1 ? "," : ""), (o == "" || p[i] == 2) ? 3 : 2 }')
      expect_rejected angle_sum "$mesh" "$tmp/m.obj" "$tmp/m.cones" --cone-orders "$wrong"
      grep -q "(a cone) has an angle sum" "$tmp/stderr" || fail "the wrong order's cone is not named"
    fi
    if [ "$name" = elk ]; then
      # (5) the cone dropped on genus 1: a flat torus, not hyperbolic
      : > "$tmp/none.cones"
      expect_error 3 "$tmp/r5.json" certify --mesh "$mesh" --embedding "$tmp/m.obj" --cones "$tmp/none.cones" --report "$tmp/r5.json"
      grep -q "hyperbolic" "$tmp/stderr" || fail "no cone on genus 1: not refused as not hyperbolic"
      # (6) the OBJ of another mesh (eight, genus 2)
      : > "$tmp/e.cones"
      "$prog" embed --mesh "$data/meshes/eight.off" --cones "$tmp/e.cones" --out "$tmp/eight.obj" >/dev/null || fail "embed eight"
      expect_error 3 "$tmp/r6.json" certify --mesh "$mesh" --embedding "$tmp/eight.obj" --cones "$tmp/m.cones" --report "$tmp/r6.json"
      grep -q "not an embedding of this mesh" "$tmp/stderr" || fail "another mesh's OBJ"
    fi
    echo ok ;;
  *)
    fail "unknown case $case_name" ;;
esac
