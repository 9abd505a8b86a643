#!/usr/bin/env bash
# Command-line tests: test_cli.sh PROGRAM CASE. Each case checks exit status, the
# one-line error and that no (partial) output file is left behind on errors.
set -u
prog="$1"; case_name="$2"; data="${3:-}"
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

. "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"   # make_hands, same_files

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
  embed_sphere)
    # 7 landmarks spread by farthest-point sampling on bear.off (libcgal-demo)
    echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/bear.cones"
    "$prog" embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --out "$tmp/b.obj" --svg "$tmp/b.svg" \
      --report "$tmp/b.json" || fail "embed failed"
    nv=$(sed -n 2p "$data/meshes/bear.off" | awk '{print $1}'); nf=$(sed -n 2p "$data/meshes/bear.off" | awk '{print $2}')
    [ "$(grep -c '^v ' "$tmp/b.obj")" -eq "$nv" ] || fail "v lines"
    [ "$(grep -c '^f ' "$tmp/b.obj")" -eq "$nf" ] || fail "f lines"
    nvt=$(grep -c '^vt ' "$tmp/b.obj")
    [ "$nvt" -gt "$nv" ] || fail "a sphere-type cut must duplicate the seam vertices ($nvt vt for $nv v)"
    # every vt is strictly inside the unit disk
    awk '/^vt /{ if ($2*$2+$3*$3 >= 1) bad++ } END { exit bad > 0 }' "$tmp/b.obj" || fail "vt outside the disk"
    # faces in input order, each with its vertices in input order (1-based in OBJ)
    awk -v n="$nv" 'NR>2+n && NF>=4 {print $2+1, $3+1, $4+1}' "$data/meshes/bear.off" > "$tmp/off_faces"
    awk '/^f /{ split($2,a,"/"); split($3,b,"/"); split($4,c,"/"); print a[1], b[1], c[1] }' "$tmp/b.obj" > "$tmp/obj_faces"
    cmp -s "$tmp/off_faces" "$tmp/obj_faces" || fail "faces differ from the input's: $(diff "$tmp/off_faces" "$tmp/obj_faces" | head -3)"
    # vertices in input order
    awk -v n="$nv" 'NR>2 && NR<=2+n {printf "%.6f %.6f %.6f\n", $1, $2, $3}' "$data/meshes/bear.off" > "$tmp/off_v"
    awk '/^v /{printf "%.6f %.6f %.6f\n", $2, $3, $4}' "$tmp/b.obj" > "$tmp/obj_v"
    cmp -s "$tmp/off_v" "$tmp/obj_v" || fail "vertices differ from the input's"
    grep -q '"bijective": true' "$tmp/b.json" || fail "report verdict"
    grep -q '"orbifold": "sphere"' "$tmp/b.json" || fail "report orbifold"
    grep -q '"converged_at_rounding_floor": false' "$tmp/b.json" || fail "report rounding floor"
    if command -v python3 >/dev/null; then
      python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$tmp/b.json" || fail "the report is not JSON"
    fi
    tail -n 1 "$tmp/b.svg" | grep -q "</svg>" || fail "svg"
    echo ok ;;
  cone_orders)
    # cones of angle 2 pi / p: the (2,3,7) tile (4 corners), an embedding of bear with three
    # landmarks whose cone angles, measured on the OBJ's own coordinates, are 2 pi / p, and a
    # map onto a bent copy (vertex i <-> vertex i) that takes the landmarks onto the landmarks
    d="$(dirname "${BASH_SOURCE[0]}")"
    "$prog" tile --orbifold sphere --cone-orders 2,3,7 --svg "$tmp/t.svg" --depth 3 > "$tmp/stdout" || fail "tile (2,3,7)"
    dots=$(grep -c "<circle cx=.*r=\"7\"" "$tmp/t.svg")
    [ "$dots" -eq 4 ] || fail "$dots cone dots in the (2,3,7) tile, expected 4"
    expect_error "$tmp/u.svg" tile --orbifold sphere --cone-orders 2,3,6 --svg "$tmp/u.svg"
    grep -q "not hyperbolic" "$tmp/stderr" || fail "(2,3,6) refused without saying why"
    expect_error "$tmp/u.svg" tile --orbifold sphere --cone-orders 2,3,x --svg "$tmp/u.svg"
    expect_error "$tmp/u.svg" tile --orbifold disk --cone-orders 3,3,3,3,3 --svg "$tmp/u.svg"
    echo "8768 4116 9726" > "$tmp/bear.cones"
    expect_error "$tmp/b.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --out "$tmp/b.obj"
    grep -q "at least 5" "$tmp/stderr" || fail "3 cones of angle pi refused without saying why"
    expect_error "$tmp/b.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --cone-orders 2,3 --out "$tmp/b.obj"
    grep -q "one per landmark" "$tmp/stderr" || fail "a wrong number of orders refused without saying why"
    "$prog" embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --cone-orders 2,3,7 --out "$tmp/b.obj" \
      --report "$tmp/b.json" > "$tmp/stdout" || fail "embed (2,3,7) failed"
    grep -q '"bijective": true' "$tmp/b.json" || fail "report verdict"
    [ "$(tr -d ' \n' < "$tmp/b.json" | grep -o '"cone_orders":\[[0-9,]*\]' | grep -o '[0-9,]*\]' | tr -d ']' | tr ',' '\n' | sort -n | tr '\n' ' ')" = "2 3 7 " ] \
      || fail "report cone_orders"
    # the angle at each landmark's corners, from the vt coordinates: at z, the angle between the
    # geodesics to a and b is the angle between T(a) and T(b), T(w) = (w - z) / (1 - conj(z) w)
    for pair in "8768 2" "4116 3" "9726 7"; do
      set -- $pair
      awk -v V=$(( $1 + 1 )) -v P=$2 '
        function tr(ar, ai, zr, zi,   nr, ni, dr, di, q) { nr = ar - zr; ni = ai - zi; dr = 1 - (zr * ar + zi * ai); di = -(zr * ai - zi * ar)
          q = dr * dr + di * di; TR = (nr * dr + ni * di) / q; TI = (ni * dr - nr * di) / q }
        /^vt / { n++; X[n] = $2; Y[n] = $3 }
        /^f / { for(j = 2; j <= 4; j++) { split($j, t, "/"); fv[j - 1] = t[1]; ft[j - 1] = t[2] }
          for(j = 1; j <= 3; j++) if(fv[j] == V) {
            z = ft[j]; a = ft[j % 3 + 1]; b = ft[(j + 1) % 3 + 1]
            tr(X[a], Y[a], X[z], Y[z]); ar = TR; ai = TI; tr(X[b], Y[b], X[z], Y[z])
            s += atan2(ar * TI - ai * TR, ar * TR + ai * TI) } }
        END { want = 2 * atan2(0, -1) / P; e = s - want; if(e < 0) e = -e
          if(e > 1e-6) { print "angle " s " at the cone of order " P ", want " want; exit 1 } }' "$tmp/b.obj" \
        || fail "cone angle of landmark $1"
    done
    awk -v R=3 -f "$d/bend.awk" "$data/meshes/bear.off" > "$tmp/bent.off"
    "$prog" map --source "$data/meshes/bear.off" --source-cones "$tmp/bear.cones" --target "$tmp/bent.off" \
      --target-cones "$tmp/bear.cones" --cone-orders 2,3,7 --out "$tmp/m.txt" > /dev/null || fail "map (2,3,7) failed"
    for v in 8768 4116 9726; do
      line=$(sed -n "$((v + 1))p" "$tmp/m.txt")
      echo "$line" | awk -v V=$v -v F="$tmp/bent.off" '{ f = $1 + 3; split("", c); i = 0
          while((getline l < F) > 0) { i++; if(i == 2) { split(l, h, " "); nv = h[1] } if(i == nv + 2 + f - 2) { split(l, c, " "); break } }
          ok = 0; for(j = 2; j <= 4; j++) if(c[j] == V && $j > 1 - 1e-9) ok = 1; exit !ok }' \
        || fail "landmark $v is not mapped onto landmark $v: $line"
    done
    echo "map: $(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/m.txt" "$tmp/bent.off" "$tmp/bent.off")"
    echo ok ;;
  genus)
    # closed meshes of genus 1 and 2: the genus detected, an empty cones file for genus 2, the
    # angles around every vertex and the areas measured on the OBJ's own coordinates (2 pi and
    # 2 pi (2g - 2 + sum(1 - 1/p))), the cut graph written and read back (the same OBJ), and a map
    # onto a twisted copy (vertex i <-> vertex i) within 2% of the diagonal
    d="$(dirname "${BASH_SOURCE[0]}")"
    : > "$tmp/none.cones"
    "$prog" embed --mesh "$data/meshes/eight.off" --cones "$tmp/none.cones" --out "$tmp/e.obj" --report "$tmp/e.json" \
      --cut-graph-out "$tmp/e.cut" --svg "$tmp/e.svg" > "$tmp/stdout" || fail "embed eight failed"
    grep -q "genus 2" "$tmp/stdout" || fail "genus not reported on stdout"
    grep -q '"genus": 2' "$tmp/e.json" || fail "report genus"
    grep -q '"bijective": true' "$tmp/e.json" || fail "report verdict"
    [ "$(grep -cv '^#' "$tmp/e.cut")" -ge 2 ] || fail "cut graph file"
    measure() { # measure OBJ: the largest |angle sum - 2 pi| over the vertices, and the total area
      awk 'function tr(ar, ai, zr, zi,   nr, ni, dr, di, q) { nr = ar - zr; ni = ai - zi; dr = 1 - (zr * ar + zi * ai); di = -(zr * ai - zi * ar)
          q = dr * dr + di * di; TR = (nr * dr + ni * di) / q; TI = (ni * dr - nr * di) / q }
        /^vt / { n++; X[n] = $2; Y[n] = $3 }
        /^f / { for(j = 2; j <= 4; j++) { split($j, t, "/"); fv[j - 1] = t[1]; ft[j - 1] = t[2] }
          fs = 0
          for(j = 1; j <= 3; j++) { z = ft[j]; a = ft[j % 3 + 1]; b = ft[(j + 1) % 3 + 1]
            tr(X[a], Y[a], X[z], Y[z]); ar = TR; ai = TI; tr(X[b], Y[b], X[z], Y[z])
            w = atan2(ar * TI - ai * TR, ar * TR + ai * TI); S[fv[j]] += w; fs += w }
          area += atan2(0, -1) - fs }
        END { worst = 0; for(v in S) { e = S[v] - 4 * atan2(0, -1) / 2; if(e < 0) e = -e; if(e > worst) worst = e }
          printf "%.3g %.12f\n", worst, area }' "$1"
    }
    set -- $(measure "$tmp/e.obj")
    awk -v w="$1" -v a="$2" 'BEGIN { pi = atan2(0, -1); e = a - 4 * pi; if(e < 0) e = -e; exit !(w < 1e-6 && e < 1e-6) }' \
      || fail "eight: angle sums within $1 of 2 pi, area $2 (4 pi expected)"
    echo "eight: angle sums within $1 of 2 pi, area $2"
    "$prog" embed --mesh "$data/meshes/eight.off" --cones "$tmp/none.cones" --out "$tmp/e2.obj" --cut-graph "$tmp/e.cut" > /dev/null \
      || fail "embed along the written cut graph"
    cmp -s "$tmp/e.obj" "$tmp/e2.obj" || fail "the written cut graph does not give the same embedding"
    head -n -1 "$tmp/e.cut" > "$tmp/short.cut" # a path less: no longer a disk
    expect_error "$tmp/e3.obj" embed --mesh "$data/meshes/eight.off" --cones "$tmp/none.cones" --out "$tmp/e3.obj" --cut-graph "$tmp/short.cut"
    echo "0 999999" > "$tmp/bad.cut"
    expect_error "$tmp/e3.obj" embed --mesh "$data/meshes/eight.off" --cones "$tmp/none.cones" --out "$tmp/e3.obj" --cut-graph "$tmp/bad.cut"
    echo "10138 5326 2877 3940 7260" > "$tmp/bear.cones"
    expect_error "$tmp/b.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --out "$tmp/b.obj" --cut-graph "$tmp/e.cut"
    # genus 1: one cone at least (a torus without cone is flat); with one, certified
    expect_error "$tmp/k.obj" embed --mesh "$data/meshes/elk.off" --cones "$tmp/none.cones" --out "$tmp/k.obj"
    echo "0" > "$tmp/elk.cones"
    "$prog" embed --mesh "$data/meshes/elk.off" --cones "$tmp/elk.cones" --out "$tmp/k.obj" --report "$tmp/k.json" > /dev/null || fail "embed elk"
    grep -q '"genus": 1' "$tmp/k.json" || fail "elk genus"
    # the map onto a twisted copy (57 degrees from end to end)
    awk -v T=1 -f "$d/twist.awk" "$data/meshes/eight.off" > "$tmp/twisted.off"
    "$prog" map --source "$data/meshes/eight.off" --source-cones "$tmp/none.cones" --target "$tmp/twisted.off" \
      --target-cones "$tmp/none.cones" --out "$tmp/m.txt" > /dev/null || fail "map eight -> twisted"
    err=$(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/m.txt" "$tmp/twisted.off" "$tmp/twisted.off")
    echo "eight -> twisted: $err"
    echo "$err" | awk '{ exit !($2 == 315 && $4 == 0 && $6 < 0.02) }' || fail "map error: $err"
    # --refine handles genus 0 only: refused in one line that says why, no file left
    expect_error "$tmp/m3.txt" map --source "$data/meshes/eight.off" --source-cones "$tmp/none.cones" --target "$tmp/twisted.off" \
      --target-cones "$tmp/none.cones" --out "$tmp/m3.txt" --refine
    grep -q -- "--refine: .*genus 2" "$tmp/stderr" || fail "--refine on genus 2 refused without saying why: $(cat "$tmp/stderr")"
    # maps need corresponding cut graphs: another mesh of genus 2 without them, and another genus, are refused
    expect_error "$tmp/m2.txt" map --source "$data/meshes/eight.off" --source-cones "$tmp/none.cones" --target "$data/meshes/femur.off" \
      --target-cones "$tmp/none.cones" --out "$tmp/m2.txt"
    grep -q "cut graph" "$tmp/stderr" || fail "missing cut graphs refused without saying why"
    expect_error "$tmp/m2.txt" map --source "$data/meshes/eight.off" --source-cones "$tmp/none.cones" --target "$data/meshes/elk.off" \
      --target-cones "$tmp/elk.cones" --out "$tmp/m2.txt"
    echo ok ;;
  embed_disk)
    echo "1166 1785 147 932 2251 139" > "$tmp/m.cones"
    "$prog" embed --mesh "$data/meshes/mushroom.off" --cones "$tmp/m.cones" --weights mvc --out "$tmp/m.obj" \
      --report "$tmp/m.json" || fail "embed failed"
    nv=$(sed -n 2p "$data/meshes/mushroom.off" | awk '{print $1}')
    [ "$(grep -c '^vt ' "$tmp/m.obj")" -eq "$nv" ] || fail "a disk is not cut: one vt per vertex"
    grep -q '"orbifold": "disk"' "$tmp/m.json" || fail "report orbifold"
    grep -q '"weights": "mvc"' "$tmp/m.json" || fail "report weights"
    echo ok ;;
  embed_recentre)
    # a capsule (tube of radius 1, length 50, 24 segments per ring, closed by hemispheres;
    # landmarks at the bottom): its far end is squeezed below what double resolves in the
    # tile (e^-50), so the embedding is refused unless --recentre lets it move the frame
    awk -v L=50 -v S=24 -f "$(dirname "${BASH_SOURCE[0]}")/capsule.awk" > "$tmp/tube.off" 2> "$tmp/tube.cones"
    expect_error "$tmp/t.obj" embed --mesh "$tmp/tube.off" --cones "$tmp/tube.cones" --out "$tmp/t.obj"
    grep -q "below what double resolves" "$tmp/stderr" || fail "the refusal does not say why"
    grep -q "recentring" "$tmp/stderr" || fail "the refusal does not name recentring"
    "$prog" embed --mesh "$tmp/tube.off" --cones "$tmp/tube.cones" --out "$tmp/t.obj" --report "$tmp/t.json" --recentre \
      || fail "embed --recentre failed"
    grep -q '"bijective": true' "$tmp/t.json" || fail "report verdict"
    grep -q '"recentred": true' "$tmp/t.json" || fail "report: not recentred"
    grep -q '"frame": {"a": \[' "$tmp/t.json" || fail "report: no frame"
    [ "$(grep -c '^vt ' "$tmp/t.obj")" -gt 0 ] || fail "no coordinates written"
    echo ok ;;
  charts)
    # a capsule of length 80 with a landmark at its far tip: the tube converges onto the tip
    # cone's image, below what double resolves in the tile (e^-40); embed writes that part in a
    # chart centred at the cone's tile corner ('# hot chart' and '# hot vtc' comment lines)
    d="$(dirname "${BASH_SOURCE[0]}")"
    awk -v L=80 -v S=24 -f "$d/capsule.awk" > "$tmp/c.off" 2> "$tmp/c.cones0"
    nv=$(sed -n 2p "$tmp/c.off" | cut -d' ' -f1)
    echo "$(cat "$tmp/c.cones0") $((nv - 1))" > "$tmp/c.cones"
    awk -v R=40 -f "$d/bend.awk" "$tmp/c.off" > "$tmp/b.off"
    "$prog" embed --mesh "$tmp/c.off" --cones "$tmp/c.cones" --out "$tmp/e.obj" --report "$tmp/e.json" > "$tmp/stdout" \
      || fail "embed failed"
    grep -q '"bijective": true' "$tmp/e.json" || fail "report verdict"
    grep -q '"charted_faces": [1-9]' "$tmp/e.json" || fail "report: no charted faces"
    grep -q 'faces in charts around cone images' "$tmp/stdout" || fail "stdout does not say charts were used"
    [ "$(grep -c '^# hot chart ' "$tmp/e.obj")" -ge 1 ] || fail "no chart table"
    [ "$(grep -c '^# hot vtc ' "$tmp/e.obj")" -gt 1000 ] || fail "too few chart points"
    # the format: a vt in a chart is the chart's inverse applied to its chart point, rounded
    # (z = (conj(a) w - b) / (a - conj(b) w)), and the deepest chart points are far below what
    # the vt lines resolve
    awk '/^vt / { n++; x[n] = $2; y[n] = $3 }
         /^# hot chart / { ar[$4] = $5; ai[$4] = $6; br[$4] = $7; bi[$4] = $8 }
         /^# hot vtc / { k = $4; c = $5; u = $6; v = $7; m++
           nr = ar[c] * u + ai[c] * v - br[c]; ni = ar[c] * v - ai[c] * u - bi[c]
           dr = ar[c] - (br[c] * u + bi[c] * v); di = ai[c] - (br[c] * v - bi[c] * u)
           q = dr * dr + di * di; zr = (nr * dr + ni * di) / q; zi = (ni * dr - nr * di) / q
           e = sqrt((zr - x[k])^2 + (zi - y[k])^2); if(e > worst) worst = e
           r = sqrt(u * u + v * v); if(m == 1 || r < deepest) deepest = r }
         END { if(m == 0 || worst > 1e-12 || deepest > 1e-17) { print "chart points: " m ", worst " worst ", deepest " deepest; exit 1 } }' \
      "$tmp/e.obj" || fail "chart points do not match their vt lines"
    # maps both ways onto the bent copy (vertex i <-> vertex i) within 1% of the diagonal
    "$prog" map --source "$tmp/c.off" --source-cones "$tmp/c.cones" --target "$tmp/b.off" --target-cones "$tmp/c.cones" \
      --out "$tmp/ab.txt" > /dev/null || fail "map failed"
    "$prog" map --source "$tmp/b.off" --source-cones "$tmp/c.cones" --target "$tmp/c.off" --target-cones "$tmp/c.cones" \
      --out "$tmp/ba.txt" > /dev/null || fail "map back failed"
    awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/ab.txt" "$tmp/b.off" "$tmp/b.off" | awk '{ if(!($4 == 0 && $6 < 0.01)) exit 1 }' \
      || fail "map error: $(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/ab.txt" "$tmp/b.off" "$tmp/b.off")"
    awk -f "$d/off_reader.awk" -f "$d/round_trip.awk" "$tmp/ab.txt" "$tmp/ba.txt" "$tmp/c.off" "$tmp/b.off" | awk '{ if(!($4 < 0.01)) exit 1 }' \
      || fail "round trip: $(awk -f "$d/off_reader.awk" -f "$d/round_trip.awk" "$tmp/ab.txt" "$tmp/ba.txt" "$tmp/c.off" "$tmp/b.off")"
    # the collection writes the charts too
    printf '%s %s\n%s %s\n' "$tmp/c.off" "$tmp/c.cones" "$tmp/b.off" "$tmp/c.cones" > "$tmp/list.txt"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/coll" > /dev/null 2>&1 || fail "collection failed"
    [ "$(grep -c '^# hot vtc ' "$tmp/coll/1_b.obj")" -gt 1000 ] || fail "collection: no chart points"
    echo ok ;;
  embed_errors)
    echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/bear.cones"
    echo "1 2 3 4" > "$tmp/four.cones"
    echo "1 2 3 4 4" > "$tmp/dup.cones"
    echo "1 2 3 4 99999999" > "$tmp/range.cones"
    echo "1 2 x 4 5" > "$tmp/garbage.cones"
    echo "1 2 3 4 5 6" > "$tmp/inner.cones"
    printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' > "$tmp/trunc.off"
    expect_error "$tmp/o.obj" embed --mesh "$tmp/missing.off" --cones "$tmp/bear.cones" --out "$tmp/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$tmp/trunc.off" --cones "$tmp/bear.cones" --out "$tmp/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/four.cones" --out "$tmp/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/dup.cones" --out "$tmp/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/range.cones" --out "$tmp/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/garbage.cones" --out "$tmp/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$data/meshes/mushroom.off" --cones "$tmp/inner.cones" --out "$tmp/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --orbifold disk --out "$tmp/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --weights harmonic --out "$tmp/o.obj"
    expect_error "$tmp/nodir/o.obj" embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --out "$tmp/nodir/o.obj"
    expect_error "$tmp/o.obj" embed --mesh "$data/meshes/bear.off" --out "$tmp/o.obj"
    # the exit status tells usage errors (2) from data errors (3)
    "$prog" embed --mesh "$data/meshes/bear.off" --cones "$tmp/four.cones" --out "$tmp/o.obj" 2>/dev/null; [ $? -eq 3 ] || fail "status for too few cones"
    "$prog" embed --bogus 1 2>/dev/null; [ $? -eq 2 ] || fail "status for a usage error"
    echo ok ;;
  landmarks)
    for mesh in hand mushroom; do
      "$prog" landmarks --mesh "$data/meshes/$mesh.off" --count 9 --out "$tmp/$mesh.cones" || fail "landmarks $mesh"
      [ "$(wc -l < "$tmp/$mesh.cones")" -eq 9 ] || fail "9 lines"
      [ "$(sort -u "$tmp/$mesh.cones" | wc -l)" -eq 9 ] || fail "distinct landmarks"
      "$prog" embed --mesh "$data/meshes/$mesh.off" --cones "$tmp/$mesh.cones" --out "$tmp/$mesh.obj" || fail "embed $mesh"
    done
    expect_error "$tmp/x.cones" landmarks --mesh "$data/meshes/hand.off" --count 0 --out "$tmp/x.cones"
    expect_error "$tmp/x.cones" landmarks --mesh "$tmp/none.off" --count 7 --out "$tmp/x.cones"
    echo ok ;;
  map)
    # a mesh onto itself with the same landmarks: every vertex lands on itself (weight 1 at its corner)
    for mesh in hand mushroom; do
      "$prog" landmarks --mesh "$data/meshes/$mesh.off" --count 7 --out "$tmp/$mesh.cones" >/dev/null || fail "landmarks"
      "$prog" map --source "$data/meshes/$mesh.off" --source-cones "$tmp/$mesh.cones" --target "$data/meshes/$mesh.off" \
        --target-cones "$tmp/$mesh.cones" --out "$tmp/$mesh.map" --colors-out "$tmp/$mesh.ply" || fail "map $mesh"
      nv=$(sed -n 2p "$data/meshes/$mesh.off" | awk '{print $1}')
      [ "$(wc -l < "$tmp/$mesh.map")" -eq "$nv" ] || fail "one line per source vertex"
      bad=$(awk -v n="$nv" 'BEGIN{nf=0} NR==FNR && FNR>2+n && NF==4 {fa[nf]=$2; fb[nf]=$3; fc[nf]=$4; nf++; next}
                NR!=FNR { i=FNR-1; f=$1; s=$2+$3+$4; ok=(s>0.999999 && s<1.000001 && $2>=0 && $3>=0 && $4>=0);
                          id=((fa[f]==i && $2>0.999999) || (fb[f]==i && $3>0.999999) || (fc[f]==i && $4>0.999999));
                          if(!(ok && id)) bad++ } END {print bad+0}' "$data/meshes/$mesh.off" "$tmp/$mesh.map")
      [ "$bad" -eq 0 ] || fail "$bad vertices of $mesh do not map onto themselves"
      head -1 "$tmp/$mesh.ply" | grep -q ply || fail "ply"
      [ "$(grep -c '' "$tmp/$mesh.ply")" -gt "$nv" ] || fail "ply content"
    done
    echo "1 2 3 4 5 6" > "$tmp/six"
    # disk landmarks given the other way around the boundary: no orientation-preserving map
    tac "$tmp/mushroom.cones" > "$tmp/mushroom.rev"
    expect_error "$tmp/x.map" map --source "$data/meshes/mushroom.off" --source-cones "$tmp/mushroom.cones" \
      --target "$data/meshes/mushroom.off" --target-cones "$tmp/mushroom.rev" --out "$tmp/x.map"
    expect_error "$tmp/x.map" map --source "$data/meshes/hand.off" --source-cones "$tmp/hand.cones" \
      --target "$data/meshes/mushroom.off" --target-cones "$tmp/mushroom.cones" --out "$tmp/x.map"
    expect_error "$tmp/x.map" map --source "$data/meshes/hand.off" --source-cones "$tmp/hand.cones" \
      --target "$data/meshes/hand.off" --target-cones "$tmp/six" --out "$tmp/x.map"
    echo ok ;;
  map_report)
    # honest maps: a capsule (tube of radius 1, length 20, hemispherical caps, five landmarks on
    # the bottom cap) onto a copy bent by bend.awk (same triangulation and vertex order: vertex
    # i corresponds to vertex i). Without a landmark at the far tip the map sends most of the
    # tube far off; the report lists the unreliable source vertices and stderr warns once.
    here="$(dirname "${BASH_SOURCE[0]}")"
    awk -v L=20 -v S=24 -f "$here/capsule.awk" > "$tmp/c.off" 2> "$tmp/c.cones"
    awk -v R=20 -f "$here/bend.awk" "$tmp/c.off" > "$tmp/b.off"
    nv=$(sed -n 2p "$tmp/c.off" | awk '{print $1}')
    [ "$(sed -n 2p "$tmp/b.off" | awk '{print $1}')" -eq "$nv" ] || fail "bend.awk changed the number of vertices"
    cmp -s <(awk -v n="$nv" 'NR > 2 + n' "$tmp/c.off") <(awk -v n="$nv" 'NR > 2 + n' "$tmp/b.off") || fail "bend.awk changed the faces"
    "$prog" map --source "$tmp/c.off" --source-cones "$tmp/c.cones" --target "$tmp/b.off" --target-cones "$tmp/c.cones" \
      --out "$tmp/m.txt" --report "$tmp/r.json" >"$tmp/stdout" 2>"$tmp/stderr" || fail "map failed: $(cat "$tmp/stderr")"
    if command -v python3 >/dev/null; then
      python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$tmp/r.json" || fail "the report is not JSON"
    fi
    # the list, one index per line
    list() { sed -n 's/.*"unreliable_vertices": \[\([^]]*\)\].*/\1/p' "$1" | tr -d ' ' | tr ',' '\n' | sed '/^$/d'; }
    count=$(sed -n 's/.*"unreliable_vertex_count": \([0-9]*\).*/\1/p' "$tmp/r.json")
    list "$tmp/r.json" > "$tmp/flagged"
    [ -n "$count" ] && [ "$count" -gt 0 ] || fail "no unreliable vertices reported"
    [ "$(wc -l < "$tmp/flagged")" -eq "$count" ] || fail "unreliable_vertex_count $count, $(wc -l < "$tmp/flagged") listed"
    [ "$count" -lt "$nv" ] || fail "the whole mesh is flagged"
    grep -q "\"source_vertices\": $nv," "$tmp/r.json" || fail "report: source_vertices"
    grep -q '"source": ".*c.off"' "$tmp/r.json" && grep -q '"target": ".*b.off"' "$tmp/r.json" || fail "report: source, target"
    # one warning line on stderr, with the count and the hint
    [ "$(wc -l < "$tmp/stderr")" -eq 1 ] || fail "stderr is not one line: $(cat "$tmp/stderr")"
    grep -q "^warning: .* $count of the $nv source vertices" "$tmp/stderr" || fail "the warning does not give the count: $(cat "$tmp/stderr")"
    grep -q "put a landmark at the tip" "$tmp/stderr" || fail "the warning has no hint: $(cat "$tmp/stderr")"
    # ground truth: every vertex whose image is more than 5% of the diagonal off is listed, no
    # vertex of the landmark cap (z <= 0) is
    awk -v n="$nv" 'FILENAME == ARGV[1] { if(FNR > 2 && FNR <= 2 + n) z[FNR - 3] = $3; next }
      FILENAME == ARGV[2] { if(FNR > 2 && FNR <= 2 + n) { k = FNR - 3; P[k, 0] = $1; P[k, 1] = $2; P[k, 2] = $3
                              for(d = 0; d < 3; d++) { if(k == 0 || $(d + 1) < lo[d]) lo[d] = $(d + 1); if(k == 0 || $(d + 1) > hi[d]) hi[d] = $(d + 1) } }
                            else if(FNR > 2 + n) { f = FNR - 3 - n; F[f, 0] = $2; F[f, 1] = $3; F[f, 2] = $4 } next }
      FILENAME == ARGV[3] { flagged[$1] = 1; next }
      { i = FNR - 1; e2 = 0
        for(d = 0; d < 3; d++) { x = $2 * P[F[$1, 0], d] + $3 * P[F[$1, 1], d] + $4 * P[F[$1, 2], d]; e2 += (x - P[i, d])^2 }
        diag = sqrt((hi[0] - lo[0])^2 + (hi[1] - lo[1])^2 + (hi[2] - lo[2])^2)
        if(sqrt(e2) > 0.05 * diag) { off++; if(!(i in flagged)) missed++ }
        if(z[i] <= 0 && (i in flagged)) cap++ }
      END { printf "%d off by more than 5%%, %d of them not listed, %d listed on the landmark cap\n", off, missed, cap
            exit !(off > 0 && missed == 0 && cap == 0) }' "$tmp/c.off" "$tmp/b.off" "$tmp/flagged" "$tmp/m.txt" \
      || fail "the list does not hold every vertex off by more than 5%, or holds vertices of the landmark cap"
    # with a landmark at the tip (the last vertex) the map is good: nothing listed, no warning
    (tr '\n' ' ' < "$tmp/c.cones"; echo "$((nv - 1))") > "$tmp/t.cones"
    "$prog" map --source "$tmp/c.off" --source-cones "$tmp/t.cones" --target "$tmp/b.off" --target-cones "$tmp/t.cones" \
      --out "$tmp/mt.txt" --report "$tmp/rt.json" >"$tmp/stdout" 2>"$tmp/stderr" || fail "map with a tip landmark failed"
    [ ! -s "$tmp/stderr" ] || fail "a warning with a tip landmark: $(cat "$tmp/stderr")"
    grep -q '"unreliable_vertex_count": 0,' "$tmp/rt.json" && grep -q '"unreliable_vertices": \[\]' "$tmp/rt.json" || fail "report with a tip landmark"
    # --repair: the indices are those of the input file (a vertex on no face put first shifts
    # every index by one; the repair drops it, MAP.txt gives it '-1 0 0 0')
    shift_off() { awk -v n="$nv" 'NR == 1 { print; next } NR == 2 { print $1 + 1, $2, $3; print "7 7 7"; next }
                   NR <= 2 + n { print; next } { print $1, $2 + 1, $3 + 1, $4 + 1 }' "$1"; }
    shift_off "$tmp/c.off" > "$tmp/c1.off"; shift_off "$tmp/b.off" > "$tmp/b1.off"
    tr ' ' '\n' < "$tmp/c.cones" | sed '/^$/d' | awk '{ printf "%d ", $1 + 1 } END { print "" }' > "$tmp/c1.cones"
    "$prog" map --repair --source "$tmp/c1.off" --source-cones "$tmp/c1.cones" --target "$tmp/b1.off" --target-cones "$tmp/c1.cones" \
      --out "$tmp/m1.txt" --report "$tmp/r1.json" >"$tmp/stdout" 2>"$tmp/stderr" || fail "map --repair failed: $(cat "$tmp/stderr")"
    [ "$(head -1 "$tmp/m1.txt")" = "-1 0 0 0" ] || fail "--repair: the vertex on no face is mapped"
    list "$tmp/r1.json" > "$tmp/flagged1"
    cmp -s "$tmp/flagged1" <(awk '{ print $1 + 1 }' "$tmp/flagged") || fail "--repair: the indices are not the input file's"
    grep -q '"source_repair": ' "$tmp/r1.json" || fail "--repair: no repair in the report"
    grep -q "^warning: .* $count of the $nv source vertices" "$tmp/stderr" || fail "--repair: warning $(cat "$tmp/stderr")"
    # no folder for the report: exit 1, one line, neither MAP.txt nor the report left behind
    expect_error "$tmp/nodir/r.json" map --source "$tmp/c.off" --source-cones "$tmp/c.cones" --target "$tmp/b.off" \
      --target-cones "$tmp/c.cones" --out "$tmp/m2.txt" --report "$tmp/nodir/r.json"
    [ ! -e "$tmp/m2.txt" ] || fail "MAP.txt left behind when the report cannot be written"
    echo "ok ($count of $nv source vertices listed)" ;;
  map_refine)
    # --refine (issue 39) on bear.off and a copy bent by bend.awk (same triangulation: vertex i
    # <-> vertex i; bent without stretching its axis, so the truth is near an isometry): the
    # refined map is closer to that truth than the harmonic one, its symmetric Dirichlet energy
    # is lower and not below 4 (the least value, an isometry's); the report says what ran
    command -v python3 >/dev/null || fail "python3 is needed to read the report"
    d="$(dirname "${BASH_SOURCE[0]}")"
    awk -v R=3 -f "$d/bend.awk" "$data/meshes/bear.off" > "$tmp/bent.off"
    echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/bear.cones"
    args=(--source "$data/meshes/bear.off" --source-cones "$tmp/bear.cones" --target "$tmp/bent.off" --target-cones "$tmp/bear.cones")
    # (--augment: the landmarks --refine adds by default, so that r0 is the map it starts from)
    "$prog" map "${args[@]}" --out "$tmp/m0.txt" --report "$tmp/r0.json" --augment > /dev/null || fail "map failed"
    "$prog" map "${args[@]}" --out "$tmp/m1.txt" --report "$tmp/r1.json" --refine 20 > "$tmp/stdout" || fail "map --refine failed"
    grep -q '^refined: [0-9]* certified iterations' "$tmp/stdout" || fail "stdout does not say what the refinement did"
    "$prog" map "${args[@]}" --out "$tmp/m3.txt" --report "$tmp/r3.json" --refine 1 --no-augment > /dev/null || fail "map --refine --no-augment failed"
    ! grep -q '"augmentation"' "$tmp/r3.json" || fail "--no-augment: the report has an augmentation block"
    e0=$(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/m0.txt" "$tmp/bent.off" "$tmp/bent.off")
    e1=$(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/m1.txt" "$tmp/bent.off" "$tmp/bent.off")
    echo "harmonic: $e0; refined: $e1"
    # ("mapped N unmapped U max E mean M"): every vertex mapped, the worst error down by a fifth
    # or more, the mean down
    echo "$e0 $e1" | awk '{ if(!($4 == 0 && $12 == 0 && $14 < 0.8 * $6 && $16 < $8)) exit 1 }' || fail "the refined map is not closer to the truth"
    python3 - "$tmp/r0.json" "$tmp/r1.json" <<'PY' || fail "the report of --refine"
import json, sys
r0, r1 = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert "refinement" not in r0, "a report without --refine has a refinement block"
f = r1["refinement"]
assert 1 <= f["iterations"] <= 20 and f["stop"] in ("iterations", "converged"), f
assert 4 - 1e-9 <= f["symmetric_dirichlet_energy_after"] < f["symmetric_dirichlet_energy_before"], f
# the distortion before the refinement is the unrefined map's
assert f["distortion_before"]["conformal"] == r0["distortion"]["conformal"], (f["distortion_before"], r0["distortion"])
assert f["distortion_before"]["symmetric_dirichlet_energy"] == r0["distortion"]["symmetric_dirichlet_energy"]
assert r1["distortion"]["symmetric_dirichlet_energy"] < r0["distortion"]["symmetric_dirichlet_energy"]
assert f["free_vertices"] == r1["source_vertices"] - r1["landmarks"] and f["seconds"] > 0
# --refine adds the matched extremities, as --augment does (the same pairs)
assert r1["augmentation"]["added"] == r0["augmentation"]["added"] and r1["landmarks"] == 7 + len(r0["augmentation"]["added"])
PY
    # --progress: the phase 'refine' from 0% to 100%, never going down (told after every
    # iteration; the lines at most every 0.5 s), and the same map
    "$prog" map "${args[@]}" --out "$tmp/m4.txt" --refine 20 --progress > /dev/null 2> "$tmp/p.stderr" || fail "map --refine --progress failed"
    cmp -s "$tmp/m1.txt" "$tmp/m4.txt" || fail "map --refine --progress: another map"
    awk '/^map: refine [0-9]+%$/ { pc = $3 + 0; if(n == 0 && pc != 0) bad = 1; if(pc < last) bad = 1; last = pc; n++ }
      END { exit !(n >= 2 && last == 100 && !bad) }' "$tmp/p.stderr" || fail "the refinement's progress: $(cat "$tmp/p.stderr")"
    # usage errors: exit 2, no file left
    for bad in -1 x 1.5; do
      "$prog" map "${args[@]}" --out "$tmp/m2.txt" --refine "$bad" 2> "$tmp/stderr"; [ $? -eq 2 ] || fail "--refine $bad: not a usage error"
      [ ! -e "$tmp/m2.txt" ] || fail "--refine $bad: MAP.txt left behind"
    done
    grep -q -- "--refine" "$tmp/stderr" || fail "the usage error does not name --refine: $(cat "$tmp/stderr")"
    echo ok ;;
  map_augment)
    # --augment (issue 39): an octopus (octopus.awk, L=6: eight tentacles) and a twirled copy
    # (same vertices: vertex i <-> vertex i), landmarks at the poles and at the tips of
    # tentacles 0-4: the tips of tentacles 5-7 are protrusions without a landmark. Facts from
    # the construction: each of the three gets one added pair, on its tip's cap (the tip and the
    # four rings before it, 65 vertices) on both meshes; every added pair is a landmark of the
    # map (the source vertex maps onto the target vertex); the map is closer to the truth.
    command -v python3 >/dev/null || fail "python3 is needed to read the report"
    d="$(dirname "${BASH_SOURCE[0]}")"
    awk -v L=6 -f "$d/octopus.awk" > "$tmp/o.off" 2> "$tmp/o.std" || fail "octopus.awk"
    awk -v L=6 -v TWIRL=0.08 -f "$d/octopus.awk" > "$tmp/t.off" 2> /dev/null || fail "octopus.awk TWIRL"
    read -r p0 p1 b0 t0 b1 t1 b2 t2 b3 t3 b4 t4 b5 t5 b6 t6 b7 t7 < "$tmp/o.std"
    printf "%s\n" "$p0" "$p1" "$t0" "$t1" "$t2" "$t3" "$t4" > "$tmp/o.cones"
    args=(--source "$tmp/o.off" --source-cones "$tmp/o.cones" --target "$tmp/t.off" --target-cones "$tmp/o.cones")
    "$prog" map "${args[@]}" --out "$tmp/m0.txt" --report "$tmp/r0.json" > /dev/null 2>&1 || fail "map failed"
    "$prog" map "${args[@]}" --out "$tmp/m1.txt" --report "$tmp/r1.json" --augment > "$tmp/stdout" || fail "map --augment failed"
    grep -q '^augmented: [0-9]* matched extremities added' "$tmp/stdout" || fail "stdout does not say what --augment added: $(cat "$tmp/stdout")"
    e0=$(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/m0.txt" "$tmp/t.off" "$tmp/t.off")
    e1=$(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/m1.txt" "$tmp/t.off" "$tmp/t.off")
    echo "without: $e0; augmented: $e1"
    # ("mapped N unmapped U max E mean M"): every vertex mapped, the worst and the mean error down
    echo "$e0 $e1" | awk '{ if(!($4 == 0 && $12 == 0 && $14 < $6 && $16 < $8)) exit 1 }' || fail "the augmented map is not closer to the truth"
    python3 - "$tmp" "$t5 $t6 $t7" <<'PY' || fail "the pairs added by --augment"
import json, sys
d, tips = sys.argv[1], [int(x) for x in sys.argv[2].split()]
r0, r1 = json.load(open(d + "/r0.json")), json.load(open(d + "/r1.json"))
assert "augmentation" not in r0, "a report without --augment has an augmentation block"
aug = r1["augmentation"]
added = aug["added"]
assert r1["landmarks"] == 7 + len(added) and sorted(r1["landmark_order"]) == list(range(7 + len(added))), r1["landmark_order"]
assert aug["source_extremities"] >= len(added) and aug["target_extremities"] >= len(added) and aug["seconds"] >= 0
assert 0 <= aug["matched_along_map"] <= len(added), aug
for t in tips:  # one pair on each tip's cap, on both meshes
    on_cap = [(a, b) for a, b in added if t - 64 <= a <= t]
    assert len(on_cap) == 1 and t - 64 <= on_cap[0][1] <= t, (t, added)
def read_off(path):
    w = open(path).read().split()
    n = int(w[1])
    return [tuple(map(float, w[4 + 3 * i:7 + 3 * i])) for i in range(n)], [tuple(map(int, w[5 + 3 * n + 4 * j:8 + 3 * n + 4 * j])) for j in range(int(w[2]))]
P, F = read_off(d + "/t.off")
lines = open(d + "/m1.txt").read().split("\n")
for a, b in added:  # the map interpolates every added pair
    f, *bary = lines[a].split()
    q = [sum(float(bary[k]) * P[F[int(f)][k]][c] for k in range(3)) for c in range(3)]
    assert sum((q[c] - P[b][c]) ** 2 for c in range(3)) < 1e-16, (a, b, q, P[b])
PY
    # refusals: with stored embeddings (usage, exit 2); on disk-type meshes (one line, no file)
    "$prog" map --source-embedding x.obj --target-embedding y.obj --out "$tmp/m2.txt" --augment 2> "$tmp/stderr"; [ $? -eq 2 ] || fail "--augment with stored embeddings: not a usage error"
    grep -q -- "--augment" "$tmp/stderr" || fail "the usage error does not name --augment: $(cat "$tmp/stderr")"
    echo "1166 1785 147 932 2251 139" > "$tmp/m.cones"
    expect_error "$tmp/m2.txt" map --source "$data/meshes/mushroom.off" --source-cones "$tmp/m.cones" --target "$data/meshes/mushroom.off" \
      --target-cones "$tmp/m.cones" --out "$tmp/m2.txt" --augment
    grep -q "augment" "$tmp/stderr" || fail "the disk's refusal does not name --augment"
    "$prog" map "${args[@]}" --out "$tmp/m2.txt" --augment --no-augment 2> "$tmp/stderr"; [ $? -eq 2 ] || fail "--augment --no-augment: not a usage error"
    [ ! -e "$tmp/m2.txt" ] || fail "--augment --no-augment: MAP.txt left behind"
    echo ok ;;
  collection_refine)
    # collection --refine: cow.off and two copies bent by bend.awk (radii 4 and 6 times its
    # height; vertex i <-> vertex i): every mesh's embedding fitted to the first mesh's metric,
    # the maps still cycle consistent (compositions through the one orbifold), the symmetric
    # Dirichlet energy of each refined map lower and not below 4, the worst error against the
    # truth lower than the unrefined collection's
    command -v python3 >/dev/null || fail "python3 is needed to read the report"
    d="$(dirname "${BASH_SOURCE[0]}")"
    cow="$data/meshes/cow.off"
    h=$(awk 'NR == 2 { n = $1 } NR > 2 && NR <= 2 + n { if(NR == 3 || $3 < lo) lo = $3; if(NR == 3 || $3 > hi) hi = $3 } END { print hi - lo }' "$cow")
    awk -v R="$(awk -v h="$h" 'BEGIN { print 4 * h }')" -f "$d/bend.awk" "$cow" > "$tmp/c1.off"
    awk -v R="$(awk -v h="$h" 'BEGIN { print 6 * h }')" -f "$d/bend.awk" "$cow" > "$tmp/c2.off"
    "$prog" landmarks --mesh "$cow" --count 12 --out "$tmp/cow.cones" > /dev/null || fail "landmarks"
    printf '%s %s\n%s %s\n%s %s\n' "$cow" "$tmp/cow.cones" "$tmp/c1.off" "$tmp/cow.cones" "$tmp/c2.off" "$tmp/cow.cones" > "$tmp/list.txt"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/c0" --all-pairs > /dev/null 2>&1 || fail "collection failed"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/cr" --all-pairs --refine 30 > /dev/null 2> "$tmp/stderr" \
      || fail "collection --refine failed: $(cat "$tmp/stderr")"
    [ "$(grep -c '^  refined .* certified iterations' "$tmp/stderr")" -eq 2 ] || fail "stderr does not say what was refined"
    python3 - "$tmp/c0/report.json" "$tmp/cr/report.json" <<'PY' || fail "the report of collection --refine"
import json, sys
r0, r = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert "refinement" not in r0
f = r["refinement"]
assert f["reference"] == 0 and [m["mesh"] for m in f["meshes"]] == [1, 2], f
for m in f["meshes"]:
    assert m["iterations"] >= 1 and 4 - 1e-9 <= m["tempered_energy_after"] < m["tempered_energy_before"], m
    assert m["symmetric_dirichlet_energy_after"] >= 4 - 1e-9, m
assert r["triples_checked"] == 6 and r["cycle_consistency_max_rel_error"] < 1e-8, r["cycle_consistency_max_rel_error"]
PY
    for pair in "1_to_0 $cow" "2_to_1 $tmp/c1.off"; do
      set -- $pair
      e0=$(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/c0/$1.map.txt" "$2" "$2")
      e1=$(awk -f "$d/off_reader.awk" -f "$d/map_error.awk" "$tmp/cr/$1.map.txt" "$2" "$2")
      echo "$1: unrefined $e0; refined $e1"
      echo "$e0 $e1" | awk '{ if(!($4 == 0 && $12 == 0 && $14 < $6)) exit 1 }' || fail "$1: the refined worst error is not lower"
    done
    # as separate jobs (the stages embed, refine, maps, merge, each with --refine 30, refine in
    # two shards): the files of the single-process run, byte for byte (report.json apart from
    # its times)
    expect_error "$tmp/cs/1_c1.obj" collection --manifest "$tmp/list.txt" --out "$tmp/cs" --all-pairs --refine 30 --stage refine
    grep -q "run the embed stage" "$tmp/stderr" || fail "the refine stage before the embed stage should say so"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/cs" --all-pairs --refine 30 --stage embed >/dev/null 2>&1 || fail "--stage embed --refine"
    expect_error "$tmp/cs/0_to_1.map.txt" collection --manifest "$tmp/list.txt" --out "$tmp/cs" --all-pairs --refine 30 --stage maps
    grep -q "was not refined" "$tmp/stderr" || fail "the maps stage before the refine stage should say so"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/cs" --all-pairs --stage refine 2> "$tmp/stderr"; [ $? -eq 2 ] || fail "--stage refine without --refine: not a usage error"
    for i in 0 1; do
      "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/cs" --all-pairs --refine 30 --stage refine --shard $i/2 >/dev/null 2>&1 || fail "--stage refine --shard $i/2"
    done
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/cs" --all-pairs --refine 30 --stage maps >/dev/null 2>&1 || fail "--stage maps --refine"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/cs" --all-pairs --refine 30 --stage merge >/dev/null 2>&1 || fail "--stage merge --refine"
    [ ! -e "$tmp/cs/.parts" ] || fail "the merge leaves the jobs' parts behind"
    same_files "$tmp/cr" "$tmp/cs"
    echo ok ;;
  map_distortion)
    # the report's per-face distortion ("distortion"): a mesh onto the same file with the same
    # landmarks maps every vertex onto itself, so every face has sigma1 = sigma2 = 1: conformal
    # and area distortion 1 on every face; onto a copy scaled by 2 (exact in binary: the same
    # embedding bit for bit) the images are the scaled vertices: conformal 1, and area 1 since it
    # is normalised by the ratio of the total areas (unnormalised it would be 4)
    command -v python3 >/dev/null || fail "python3 is needed to read the report"
    src="$data/meshes/hand.off"
    "$prog" landmarks --mesh "$src" --count 7 --out "$tmp/hand.cones" >/dev/null || fail "landmarks"
    # (OFF: the header line, the counts, the vertices, the faces; blank and comment lines kept)
    awk '/^[ \t]*(#|$)/ { print; next } { k++ } k == 2 { n = $1 } k > 2 && k <= 2 + n { printf "%.17g %.17g %.17g\n", 2 * $1, 2 * $2, 2 * $3; next } { print }' \
      "$src" > "$tmp/hand2.off"
    [ "$(grep -c '' "$tmp/hand2.off")" -eq "$(grep -c '' "$src")" ] || fail "the scaled copy"
    nf=$(sed -n 2p "$src" | awk '{print $2}')
    for target in "$src" "$tmp/hand2.off"; do
      "$prog" map --source "$src" --source-cones "$tmp/hand.cones" --target "$target" --target-cones "$tmp/hand.cones" \
        --out "$tmp/m.txt" --report "$tmp/r.json" >/dev/null || fail "map onto $target"
      python3 - "$tmp/r.json" "$nf" <<'PY' || fail "distortion of the map onto $target"
import json, sys
r = json.load(open(sys.argv[1]))
nf = int(sys.argv[2])
d = r["distortion"]
for k in ("source", "target", "source_vertices", "target_vertices", "time_seconds", "squeezed_regions",
          "unreliable_vertex_count", "unreliable_vertices"):
    assert k in r, "key %s is gone" % k
for k in ("embedding_source", "embedding_target", "map", "reliability", "distortion"):
    assert isinstance(r["time_seconds"][k], float) or isinstance(r["time_seconds"][k], int), "time_seconds." + k
for fig in ("conformal", "area"):
    for k in ("p50", "p90", "p99", "max", "mean"):
        v = d[fig][k]
        assert isinstance(v, (int, float)), "%s.%s = %r is not a number" % (fig, k, v)
        assert abs(v - 1) <= 1e-9, "%s.%s = %r, not 1" % (fig, k, v)
assert d["degenerate_faces"] == 0, d
assert d["faces"] == nf, (d["faces"], nf)
print("distortion: conformal max %.17g, area max %.17g over %d faces" % (d["conformal"]["max"], d["area"]["max"], d["faces"]))
PY
    done
    echo ok ;;
  collection)
    # hand.off and two smooth deformations of it (same triangulation, same landmarks)
    nv=$(awk 'NR==2 {print $1}' "$data/meshes/hand.off")
    make_hands a b c
    "$prog" landmarks --mesh "$tmp/hand_a.off" --count 9 --out "$tmp/cones.txt" >/dev/null || fail "landmarks"
    printf '# a collection\nhand_a.off cones.txt\nhand_b.off cones.txt\nhand_c.off cones.txt\n' > "$tmp/list.txt"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs || fail "collection"
    [ "$(ls "$tmp/out"/*.obj | wc -l)" -eq 3 ] || fail "3 embeddings"
    [ "$(ls "$tmp/out"/*.map.txt | wc -l)" -eq 6 ] || fail "6 ordered pairs"
    for f in "$tmp/out"/*.map.txt; do [ "$(wc -l < "$f")" -eq "$nv" ] || fail "$f lines"; done
    cc=$(sed -n 's/.*"cycle_consistency_max_rel_error": \([^ ,}]*\).*/\1/p' "$tmp/out/report.json")
    awk -v c="$cc" 'BEGIN { exit !(c != "" && c + 0 < 1e-8) }' || fail "cycle consistency $cc"
    grep -q '"triples_checked": 6' "$tmp/out/report.json" || fail "triples"
    # errors: a missing manifest, a mesh with another number of landmarks
    expect_error "$tmp/o2/report.json" collection --manifest "$tmp/none.txt" --out "$tmp/o2"
    echo "1 2 3 4 5" > "$tmp/five.txt"
    printf 'hand_a.off cones.txt\nhand_b.off five.txt\n' > "$tmp/bad.txt"
    expect_error "$tmp/o3/report.json" collection --manifest "$tmp/bad.txt" --out "$tmp/o3"
    echo "ok (cycle consistency $cc)" ;;
  collection_shards)
    # the collection as separate jobs (--stage embed|maps --shard I/N, then --stage merge) writes
    # the files of the single-process run, byte for byte (report.json apart from its times)
    make_hands a b c e
    "$prog" landmarks --mesh "$tmp/hand_a.off" --count 9 --out "$tmp/cones.txt" >/dev/null || fail "landmarks"
    printf 'hand_a.off cones.txt\nhand_b.off cones.txt\nhand_c.off cones.txt\nhand_e.off cones.txt\n' > "$tmp/list.txt"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/one" --all-pairs 2>/dev/null || fail "collection"
    [ "$(ls "$tmp/one"/*.map.txt | wc -l)" -eq 12 ] || fail "12 ordered pairs"
    for i in 0 1; do "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage embed --shard $i/2 2>/dev/null || fail "embed shard $i"; done
    [ "$(ls "$tmp/jobs"/*.obj | wc -l)" -eq 4 ] || fail "4 embeddings after the embed stage"
    expect_error "$tmp/jobs/report.json" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage merge
    grep -q "not computed" "$tmp/stderr" || fail "the merge before the maps should say a map is missing"
    for i in 0 1 2; do "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage maps --shard $i/3 2>/dev/null || fail "maps shard $i"; done
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage merge > "$tmp/stdout" || fail "merge"
    [ ! -e "$tmp/jobs/.parts" ] || fail "the merge leaves the jobs' parts behind"
    same_files "$tmp/one" "$tmp/jobs"
    # with --repair (holes filled, isolated vertices) and cones of orders (2,3,7)
    echo "10138 5326 2877" > "$tmp/c3.txt"
    awk -v centres=1000,6000 -v rings=1 -f "$(dirname "$0")/punch_holes.awk" "$data/meshes/bear.off" > "$tmp/holes.off"
    awk -v R=3 -f "$(dirname "$0")/bend.awk" "$data/meshes/bear.off" > "$tmp/bent.off"
    printf 'holes.off c3.txt\nbent.off c3.txt\nholes.off c3.txt\n' > "$tmp/l2.txt"
    "$prog" collection --manifest "$tmp/l2.txt" --out "$tmp/one2" --repair --cone-orders 2,3,7 --all-pairs >/dev/null 2>&1 || fail "collection --repair"
    "$prog" collection --manifest "$tmp/l2.txt" --out "$tmp/jobs2" --repair --cone-orders 2,3,7 --all-pairs --stage embed >/dev/null 2>&1 || fail "embed stage --repair"
    "$prog" collection --manifest "$tmp/l2.txt" --out "$tmp/jobs2" --all-pairs --stage maps >/dev/null 2>&1 || fail "maps stage"
    "$prog" collection --manifest "$tmp/l2.txt" --out "$tmp/jobs2" --all-pairs --stage merge >/dev/null || fail "merge"
    same_files "$tmp/one2" "$tmp/jobs2"
    grep -q '^-1 0 0 0$' "$tmp/jobs2/0_to_1.map.txt" || fail "the isolated vertices of holes.off have no image"
    # usage errors
    expect_error "$tmp/x/report.json" collection --manifest "$tmp/list.txt" --out "$tmp/x" --shard 0/2
    expect_error "$tmp/x/report.json" collection --manifest "$tmp/list.txt" --out "$tmp/x" --stage maps --shard 2/2
    expect_error "$tmp/x/report.json" collection --manifest "$tmp/list.txt" --out "$tmp/x" --stage embed --shard a/2
    expect_error "$tmp/x/report.json" collection --manifest "$tmp/list.txt" --out "$tmp/x" --stage sideways
    expect_error "$tmp/x/report.json" collection --manifest "$tmp/list.txt" --out "$tmp/x" --stage merge --shard 0/2
    echo ok ;;
  map_stored)
    # map --source-embedding/--target-embedding: the numbers of map on the meshes, without embedding again
    off="$data/meshes/bear.off"
    echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/c.txt"
    awk -v R=3 -f "$(dirname "$0")/bend.awk" "$off" > "$tmp/bent.off"
    "$prog" map --source "$off" --source-cones "$tmp/c.txt" --target "$tmp/bent.off" --target-cones "$tmp/c.txt" --out "$tmp/m.txt" >/dev/null || fail "map"
    "$prog" embed --mesh "$off" --cones "$tmp/c.txt" --out "$tmp/a.obj" --report "$tmp/a.json" >/dev/null || fail "embed source"
    grep -q '^# hot orbifold sphere genus 0 cones 7 reversed 0$' "$tmp/a.obj" || fail "no orbifold line"
    [ "$(grep -c '^# hot cone ' "$tmp/a.obj")" -eq 7 ] || fail "7 cone lines"
    pos=$(sed -n 's/.*"landmark_positions_used": \[\(.*\)\].*/\1/p' "$tmp/a.json" | tr -d ' ')
    [ -n "$pos" ] || fail "no landmark_positions_used"
    # each cone line names the landmark at that cone: its vertex is that line of the landmark file
    awk 'NR==FNR { for(i = 1; i <= NF; ++i) v[i-1] = $i; next } /^# hot cone / { if(v[$5] != $6) bad++ } END { exit bad > 0 }' \
      "$tmp/c.txt" "$tmp/a.obj" || fail "a cone line's vertex is not its landmark's"
    "$prog" embed --mesh "$tmp/bent.off" --cones "$tmp/c.txt" --order "$pos" --out "$tmp/b.obj" --report "$tmp/b.json" >/dev/null || fail "embed target --order $pos"
    grep -q '"order": "explicit"' "$tmp/b.json" || fail "the report's order is not explicit"
    [ "$(grep -o '"cones": \[[^]]*\]' "$tmp/b.json")" = "$(grep -o '"cones": \[[^]]*\]' "$tmp/a.json")" ] || fail "the report's cones are not as given"
    [ "$(grep -o '"landmark_positions_used": \[[^]]*\]' "$tmp/b.json")" = "$(grep -o '"landmark_positions_used": \[[^]]*\]' "$tmp/a.json")" ] || fail "not the order asked for"
    "$prog" map --source-embedding "$tmp/a.obj" --target-embedding "$tmp/b.obj" --out "$tmp/s.txt" --report "$tmp/s.json" >/dev/null || fail "map from stored embeddings"
    cmp -s "$tmp/m.txt" "$tmp/s.txt" || fail "the map from stored embeddings differs from map's"
    grep -q '"unreliable_vertex_count": 0' "$tmp/s.json" || fail "report"
    "$prog" map --source "$off" --source-cones "$tmp/c.txt" --target "$tmp/bent.off" --target-cones "$tmp/c.txt" --out "$tmp/m.txt" --report "$tmp/m.json" >/dev/null || fail "map --report"
    [ "$(grep -o '"distortion": {.*}' "$tmp/s.json")" = "$(grep -o '"distortion": {.*}' "$tmp/m.json")" ] || fail "the stored map's distortion differs from map's"
    # another cone order: refused
    rev=$(echo "$pos" | tr ',' '\n' | tac | paste -sd, -)
    "$prog" embed --mesh "$tmp/bent.off" --cones "$tmp/c.txt" --order "$rev" --out "$tmp/r.obj" >/dev/null || fail "embed --order $rev"
    expect_error "$tmp/x.txt" map --source-embedding "$tmp/a.obj" --target-embedding "$tmp/r.obj" --out "$tmp/x.txt"
    grep -q "different cones" "$tmp/stderr" || fail "the other cone order is not named"
    # a file without the orbifold line, a mix with meshes, a wrong --order
    grep -v '^# hot orbifold' "$tmp/b.obj" > "$tmp/n.obj"
    expect_error "$tmp/x.txt" map --source-embedding "$tmp/a.obj" --target-embedding "$tmp/n.obj" --out "$tmp/x.txt"
    grep -q "orbifold" "$tmp/stderr" || fail "the missing orbifold line is not named"
    expect_error "$tmp/x.txt" map --source-embedding "$tmp/a.obj" --target "$tmp/bent.off" --out "$tmp/x.txt"
    expect_error "$tmp/x.txt" map --source-embedding "$tmp/a.obj" --out "$tmp/x.txt"
    expect_error "$tmp/x.obj" embed --mesh "$off" --cones "$tmp/c.txt" --order 0,1,2,3,4,5,5 --out "$tmp/x.obj"
    expect_error "$tmp/x.obj" embed --mesh "$off" --cones "$tmp/c.txt" --order 0,1,2 --out "$tmp/x.obj"
    echo ok ;;
  cut)
    # CGAL's selection file of the cut of bear.off through 7 landmarks: line 1 the cones in the
    # cut's order, line 2 empty, line 3 the seam as vertex pairs "s0 t0 s1 t1 ...", which must be
    # mesh edges forming one simple path from the first cone to the last through every cone in order
    off="$data/meshes/bear.off"
    nv=$(sed -n 2p "$off" | awk '{print $1}')
    check_selection() { # check_selection FILE: the file's format and its seam
      [ "$(grep -c '' "$1")" -eq 3 ] || fail "$1: not 3 lines"
      [ -z "$(sed -n 2p "$1")" ] || fail "$1: line 2 is not empty"
      awk -v n="$nv" '
        NR == FNR { if(FNR > 2 + n && NF >= 4) { e[$2 " " $3]; e[$3 " " $2]; e[$3 " " $4]; e[$4 " " $3]; e[$4 " " $2]; e[$2 " " $4] } next }
        FNR == 1 { k = NF; for(i = 1; i <= NF; i++) { cone[i] = $i; rank[$i] = i } next }
        FNR == 3 {
          if(NF == 0 || NF % 2) { print "line 3 is not a list of vertex pairs"; exit 1 }
          if($1 != cone[1]) { print "the seam does not start at the first cone"; exit 1 }
          cur = $1; seen[cur]; next_cone = 2
          for(i = 1; i < NF; i += 2) {
            if($i != cur) { print "pair " (i + 1) / 2 " does not continue the path"; exit 1 }
            if(!(($i " " $(i + 1)) in e)) { print $i " " $(i + 1) " is not an edge of the mesh"; exit 1 }
            cur = $(i + 1)
            if(cur in seen) { print "vertex " cur " is twice on the seam: not a simple path"; exit 1 }
            seen[cur]
            if(cur in rank) { if(rank[cur] != next_cone) { print "cone " cur " out of order"; exit 1 } next_cone++ }
          }
          if(next_cone != k + 1 || cur != cone[k]) { print "the seam does not pass every cone to end at the last"; exit 1 }
          ok = 1
        }
        END { if(!ok) exit 1 }' "$off" "$1" || fail "$1: the seam is not a simple path of mesh edges through the cones"
    }
    echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/bear.cones"
    "$prog" cut --mesh "$off" --cones "$tmp/bear.cones" --out "$tmp/b.selection.txt" || fail "cut failed"
    [ "$(sed -n 1p "$tmp/b.selection.txt")" = "$(cat "$tmp/bear.cones")" ] || fail "line 1 is not the given cones"
    check_selection "$tmp/b.selection.txt"
    # the paper's tour: line 1 is the cones in another order, the seam follows it
    "$prog" cut --mesh "$off" --cones "$tmp/bear.cones" --order tsp --out "$tmp/t.selection.txt" || fail "cut --order tsp failed"
    [ "$(sed -n 1p "$tmp/t.selection.txt" | tr ' ' '\n' | sort)" = "$(tr ' ' '\n' < "$tmp/bear.cones" | sort)" ] \
      || fail "--order tsp: line 1 is not a permutation of the cones"
    check_selection "$tmp/t.selection.txt"
    # errors: a disk (3), too few cones (3), a cone out of range (3), no output folder (1), usage (2)
    echo "1166 1785 147 932 2251 139" > "$tmp/m.cones"
    echo "1 2 3 4" > "$tmp/four.cones"
    echo "1 2 3 4 99999999" > "$tmp/range.cones"
    expect_error "$tmp/x.selection.txt" cut --mesh "$data/meshes/mushroom.off" --cones "$tmp/m.cones" --out "$tmp/x.selection.txt"
    grep -q "closed genus-0" "$tmp/stderr" || fail "the refusal of a disk does not say why"
    "$prog" cut --mesh "$data/meshes/mushroom.off" --cones "$tmp/m.cones" --out "$tmp/x.selection.txt" 2>/dev/null; [ $? -eq 3 ] || fail "status for a disk"
    expect_error "$tmp/x.selection.txt" cut --mesh "$off" --cones "$tmp/four.cones" --out "$tmp/x.selection.txt"
    "$prog" cut --mesh "$off" --cones "$tmp/four.cones" --out "$tmp/x.selection.txt" 2>/dev/null; [ $? -eq 3 ] || fail "status for too few cones"
    expect_error "$tmp/x.selection.txt" cut --mesh "$off" --cones "$tmp/range.cones" --out "$tmp/x.selection.txt"
    expect_error "$tmp/nodir/x.selection.txt" cut --mesh "$off" --cones "$tmp/bear.cones" --out "$tmp/nodir/x.selection.txt"
    "$prog" cut --mesh "$off" --cones "$tmp/bear.cones" --out "$tmp/nodir/x.selection.txt" 2>/dev/null; [ $? -eq 1 ] || fail "status for a missing folder"
    expect_error "$tmp/x.selection.txt" cut --mesh "$off" --cones "$tmp/bear.cones" --order random --out "$tmp/x.selection.txt"
    "$prog" cut --mesh "$off" --cones "$tmp/bear.cones" --order random --out "$tmp/x.selection.txt" 2>/dev/null; [ $? -eq 2 ] || fail "status for a usage error"
    echo ok ;;
  job_help)
    # JOB --help (or -h, or help JOB): the job's own usage on stdout, exit 0, whatever else is
    # given, before anything is checked or written. The jobs, their sections and which of them take
    # [REPAIR] are read from the top-level usage text, which must be the jobs' texts in a row.
    "$prog" --help > "$tmp/all.txt" 2> "$tmp/stderr" || fail "--help failed"
    [ ! -s "$tmp/stderr" ] || fail "--help wrote on stderr"
    for h in -h help; do "$prog" $h 2>/dev/null | cmp -s - "$tmp/all.txt" || fail "'$h' is not --help"; done
    [ "$(head -n 1 "$tmp/all.txt")" = "usage:" ] || fail "--help does not start with 'usage:'"
    jobs=$(sed -n 's/^  hyperbolic_orbifold_tutte \([a-z]*\) .*/\1/p' "$tmp/all.txt" | awk '!seen[$0]++')
    [ "$(echo "$jobs" | wc -l)" -ge 7 ] || fail "fewer than 7 jobs in --help: $jobs"
    sed -n '/^  REPAIR (/,$p' "$tmp/all.txt" > "$tmp/repair.txt"
    [ -s "$tmp/repair.txt" ] || fail "no REPAIR section in --help"
    repair_jobs=" $(sed -n 's/^  REPAIR (\(.*\)):$/\1/p' "$tmp/all.txt" | tr -d ',') "
    mkdir "$tmp/scratch" "$tmp/in"
    echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/in/bear.cones"
    s="$tmp/scratch"
    : > "$tmp/concat.txt"
    for job in $jobs; do
      n=0
      for args in "$job --help" "$job -h" "help $job" "$job --out $s/o --help" "$job --help --out $s/o" \
                  "$job --bogus 1 -h" "$job --mesh $data/meshes/bear.off --cones $tmp/in/bear.cones --out $s/o.obj --svg $s/o.svg --report $s/o.json --help" \
                  "$job --out $s/o --svg $s/o.svg --report $s/o.json --orbifold sphere --cones 7 --count 7 --manifest $tmp/in/none --help"; do
        n=$((n + 1))
        "$prog" $args > "$tmp/help_${job}_$n.txt" 2> "$tmp/stderr"; rc=$?
        [ $rc -eq 0 ] || fail "exit $rc for: $args -- $(cat "$tmp/stderr")"
        [ ! -s "$tmp/stderr" ] || fail "stderr for: $args -- $(cat "$tmp/stderr")"
        [ -z "$(ls -A "$s")" ] || fail "files written for: $args -- $(ls -A "$s")"
        [ $n -eq 1 ] || cmp -s "$tmp/help_${job}_1.txt" "$tmp/help_${job}_$n.txt" || fail "'$args' is not '$job --help'"
      done
      help="$tmp/help_${job}_1.txt"
      [ "$(head -n 1 "$help")" = "usage:" ] || fail "$job --help does not start with 'usage:'"
      grep -q "^  hyperbolic_orbifold_tutte $job " "$help" || fail "$job --help has no line 'hyperbolic_orbifold_tutte $job'"
      for other in $jobs; do
        [ "$other" = "$job" ] && continue
        ! grep -q -E "hyperbolic_orbifold_tutte $other( |\$)" "$help" || fail "$job --help shows $other's usage"
      done
      # the job's own text: after 'usage:', up to the REPAIR section, which it has iff REPAIR names the job
      awk 'NR > 1 && /^  REPAIR \(/ { exit } NR > 1' "$help" > "$tmp/body.txt"
      [ -s "$tmp/body.txt" ] || fail "$job --help is empty"
      cat "$tmp/body.txt" >> "$tmp/concat.txt"
      if [ "${repair_jobs#* $job }" != "$repair_jobs" ]; then
        grep -q -F "[REPAIR]" "$tmp/body.txt" || fail "REPAIR names $job but its usage does not take [REPAIR]"
        { echo "usage:"; cat "$tmp/body.txt" "$tmp/repair.txt"; } | cmp -s - "$help" || fail "$job --help is not its text and the REPAIR section"
      else
        ! grep -q -F "[REPAIR]" "$tmp/body.txt" || fail "$job's usage takes [REPAIR] but REPAIR does not name it"
        { echo "usage:"; cat "$tmp/body.txt"; } | cmp -s - "$help" || fail "$job --help is not its text alone"
      fi
      [[ "$(cat "$tmp/all.txt")" == *"$(cat "$tmp/body.txt")"* ]] || fail "$job's text is not in --help"
      echo "ok: $job --help ($(wc -l < "$help") lines)"
    done
    # --help is the jobs' texts in a row (its order) and the REPAIR section, nothing else
    { echo "usage:"; cat "$tmp/concat.txt" "$tmp/repair.txt"; } | cmp -s - "$tmp/all.txt" || fail "--help is not the jobs' texts in a row"
    # an unknown job stays an error, --help or not
    for args in "nosuchjob --help" "nosuchjob -h" "help nosuchjob"; do
      expect_error "$s/o" $args
      "$prog" $args 2>/dev/null; [ $? -eq 2 ] || fail "status for: $args"
      grep -q "unknown command 'nosuchjob'" "$tmp/stderr" || fail "the reason for: $args"
    done
    echo ok ;;
  progress)
    # --progress: 'embed: PHASE NN%' lines on stderr, the phases in order, percentages that never
    # decrease within a phase and end at 100%; stdout (apart from its time) and OUT.obj as without
    # it; without it, stderr not a terminal: no progress output at all
    echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/bear.cones"
    args=(embed --mesh "$data/meshes/bear.off" --cones "$tmp/bear.cones" --out "$tmp/b.obj")
    "$prog" "${args[@]}" > "$tmp/plain.stdout" 2> "$tmp/plain.stderr" || fail "embed failed"
    [ ! -s "$tmp/plain.stderr" ] || fail "stderr without --progress: $(cat "$tmp/plain.stderr")"
    mv "$tmp/b.obj" "$tmp/plain.obj"
    "$prog" "${args[@]}" --progress > "$tmp/p.stdout" 2> "$tmp/p.stderr" || fail "embed --progress failed: $(cat "$tmp/p.stderr")"
    cmp -s "$tmp/plain.obj" "$tmp/b.obj" || fail "OUT.obj differs with --progress"
    untimed() { sed -E 's/ in [0-9.e+-]+ s,/ in T s,/' "$1"; }
    [ "$(untimed "$tmp/plain.stdout")" = "$(untimed "$tmp/p.stdout")" ] || fail "stdout differs with --progress: $(cat "$tmp/p.stdout")"
    grep -q -F "embedded " "$tmp/p.stdout" || fail "no 'embedded' line on stdout"
    ! grep -q $'\r' "$tmp/p.stderr" || fail "carriage returns in --progress lines (stderr is not a terminal)"
    awk -v want="read input cut initialization optimization certificate write" '
      !/^embed: [a-z ]+ [0-9]+%$/ { print "not a progress line: " $0; bad = 1; next }
      { pc = $NF; sub(/%$/, "", pc); pc += 0; ph = $0; sub(/^embed: /, "", ph); sub(/ [0-9]+%$/, "", ph)
        if(ph != cur) {
          if(cur != "" && last != 100) { print cur " ends at " last "%"; bad = 1 }
          order = order (order == "" ? "" : " ") ph; cur = ph
        } else if(pc < last) { print ph " goes down: " last "% -> " pc "%"; bad = 1 }
        last = pc; n++ }
      END {
        if(cur != "" && last != 100) { print cur " ends at " last "%"; bad = 1 }
        if(order != want) { print "phases: " order; bad = 1 }
        if(n < 14) { print n " lines"; bad = 1 }
        exit bad }' "$tmp/p.stderr" || fail "progress lines: $(cat "$tmp/p.stderr")"
    echo "ok: $(wc -l < "$tmp/p.stderr") progress lines: $(tr '\n' '|' < "$tmp/p.stderr")"
    # certify --progress: its phases too, nothing else changes
    "$prog" certify --mesh "$data/meshes/bear.off" --embedding "$tmp/b.obj" --cones "$tmp/bear.cones" --progress \
      > "$tmp/c.stdout" 2> "$tmp/c.stderr" || fail "certify --progress failed"
    grep -q -x "certify: certificate 100%" "$tmp/c.stderr" || fail "certify --progress: $(cat "$tmp/c.stderr")"
    grep -q "^certified: " "$tmp/c.stdout" || fail "certify's stdout: $(cat "$tmp/c.stdout")"
    # a terminal (script(1) of util-linux gives one): one line updated in place with '\r', without
    # --progress, cleared before the 'embedded' line
    if command -v script >/dev/null 2>&1 && script -qec true /dev/null >/dev/null 2>&1; then
      printf '%q ' "$prog" "${args[@]}" > "$tmp/cmd.sh"
      script -qec "bash $tmp/cmd.sh" /dev/null < /dev/null > "$tmp/tty.out" 2>&1 || fail "embed on a terminal failed: $(cat "$tmp/tty.out")"
      grep -q -a $'\rembed: optimization [0-9]*%' "$tmp/tty.out" || fail "no line updated in place on a terminal: $(cat -A "$tmp/tty.out" | head -c 2000)"
      grep -q -a $'\rembed: write 100%' "$tmp/tty.out" || fail "the terminal's line does not reach 'write 100%'"
      grep -q -a "embedded " "$tmp/tty.out" || fail "no 'embedded' line on the terminal"
      # (the terminal's last line before 'embedded', cleared: what follows its last '\r')
      grep -a "embedded " "$tmp/tty.out" | sed 's/\r$//' | awk -F'\r' '{ print $NF }' | grep -q "^embedded " ||
        fail "the progress line is not cleared before stdout: $(grep -a "embedded " "$tmp/tty.out" | cat -A)"
      cmp -s "$tmp/plain.obj" "$tmp/b.obj" || fail "OUT.obj differs on a terminal"
      echo "ok: terminal"
    else
      echo "(no script(1): the terminal's line is not checked)"
    fi
    echo ok ;;
  *) fail "unknown case $case_name" ;;
esac
