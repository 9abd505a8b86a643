#!/usr/bin/env bash
# Command-line tests of the landmark order map and collection choose for all their meshes
# (--order auto|tsp|given):
#   test_cli_order.sh PROGRAM CASE DATA_DIR
# The expected orders are computed here, independently of the program (order.py below):
# Dijkstra over the meshes' edges, the shortest closed tour by trying every permutation, opened
# at its longest edge, and the candidates (each mesh's tour) ranked by the longest, over the
# meshes, of the length of the path through the landmarks in that order over the mesh's own
# tour's. The refusals are facts of the meshes: a 12-vertex icosahedron has no simple path
# through 7 of its vertices in most orders that zigzag, which a finely subdivided sphere has.
set -u
prog="$1"; case_name="$2"; data="${3:-}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$here/cli_expect.sh" # fail, expect_error
command -v python3 > /dev/null || fail "python3 not found (scripts/install-deps.sh installs it)"

# icosphere.py: the icosahedron on the unit sphere (V, F) and split(V, F), which splits every
# face in 4 (the midpoints pushed onto the sphere; the old vertices keep their numbers)
cat > "$tmp/icosphere.py" <<'PY'
import math
t = (1 + 5 ** 0.5) / 2
V = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
V = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in V]
F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
     (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
def split(V, F):
    V = list(V); mid = {}
    def m(a, b):
        k = (min(a, b), max(a, b))
        if k not in mid:
            p = [(V[a][i] + V[b][i]) / 2 for i in range(3)]; n = math.sqrt(sum(x * x for x in p))
            V.append(tuple(x / n for x in p)); mid[k] = len(V) - 1
        return mid[k]
    G = []
    for a, b, c in F:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        G += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    return V, G
PY

# spheres.py: ico.off (an icosahedron) and fine.off (the same, its faces split in 4 twice, 162
# vertices, on the unit sphere; the icosahedron's vertices keep their numbers 0..11), both with
# their vertices moved by up to 4% of the radius (a fixed generator), so that no two paths
# between landmarks have the same length
cat > "$tmp/spheres.py" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from icosphere import V, F, split
seed = [12345]
def rnd():
    seed[0] = (seed[0] * 1103515245 + 12345) % 2147483648
    return seed[0] / 2147483648.0
def write(path, V, F):
    with open(path, 'w') as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        for v in V:
            f.write("%.17g %.17g %.17g\n" % tuple(x * (1 + 0.04 * (rnd() - 0.5)) for x in v))
        for a, b, c in F:
            f.write("3 %d %d %d\n" % (a, b, c))
write(sys.argv[1] + "/ico.off", V, F)
for _ in range(2):
    V, F = split(V, F)
write(sys.argv[1] + "/fine.off", V, F)
PY

# order.py MESH1 CONES1 MESH2 CONES2 ...: the candidate orders, best first, one line each:
# "<mesh> <longest ratio> <order>" (ties to the mesh listed first; equal or reversed orders once)
cat > "$tmp/order.py" <<'PY'
import heapq, itertools, math, sys
def read_off(path):
    w = open(path).read().split()
    i = 1 if w[0] == 'OFF' else 0
    n, f = int(w[i]), int(w[i + 1]); i += 3
    P = [tuple(float(x) for x in w[i + 3 * j:i + 3 * j + 3]) for j in range(n)]; i += 3 * n
    adj = [dict() for _ in range(n)]
    for _ in range(f):
        k = int(w[i]); vs = [int(x) for x in w[i + 1:i + 1 + k]]; i += 1 + k
        for a, b in zip(vs, vs[1:] + vs[:1]):
            d = math.dist(P[a], P[b]); adj[a][b] = d; adj[b][a] = d
    return adj
def distances(adj, L):
    D = []
    for s in L:
        dist = {s: 0.0}; q = [(0.0, s)]
        while q:
            d, u = heapq.heappop(q)
            if d > dist[u]: continue
            for v, l in adj[u].items():
                if d + l < dist.get(v, math.inf):
                    dist[v] = d + l; heapq.heappush(q, (d + l, v))
        D.append([dist[t] for t in L])
    return D
def tour(D):
    k = len(D); best = None
    for p in itertools.permutations(range(1, k)):
        c = (0,) + p
        l = sum(D[c[i]][c[(i + 1) % k]] for i in range(k))
        if best is None or l < best[0]: best = (l, c)
    c = best[1]
    j = max(range(k), key=lambda i: D[c[i]][c[(i + 1) % k]])  # the longest edge, removed
    return [c[(j + 1 + i) % k] for i in range(k)]
def path(D, o): return sum(D[o[i]][o[i + 1]] for i in range(len(o) - 1))
a = sys.argv[1:]
Ds = [distances(read_off(a[i]), [int(x) for x in open(a[i + 1]).read().split()]) for i in range(0, len(a), 2)]
tours = [tour(D) for D in Ds]
cands = []
for m, o in enumerate(tours):
    if any(o == c[2] or o == c[2][::-1] for c in cands): continue
    cands.append((max(path(D, o) / path(D, t) for D, t in zip(Ds, tours)), m, o))
cands.sort(key=lambda c: c[0])  # (stable: ties to the mesh listed first)
for r, m, o in cands: print(m, "%.12g" % r, " ".join(map(str, o)))
PY

# same_order "A B ..." "C D ...": the same path, in either direction
same_order() { [ "$1" = "$2" ] || [ "$1" = "$(echo "$2" | tr ' ' '\n' | tac | tr '\n' ' ' | sed 's/ $//')" ]; }
# report_order REPORT.json: the "landmark_order" as "i j k ..."
report_order() { grep -o '"landmark_order": \[[0-9, ]*\]' "$1" | sed 's/.*\[//; s/\]//; s/,//g'; }
json_field() { grep -o "\"$2\": \"\\?[a-z0-9 ]*" "$1" | head -1 | sed 's/.*: "\?//'; }
# landmarks_onto_landmarks MAP B.off CA CB: landmark i of A maps onto landmark i of B (its line
# in MAP names a face of B with barycentric coordinate 1 at that vertex)
landmarks_onto_landmarks() {
  python3 - "$@" <<'PY' || fail "a landmark does not map onto its landmark: $*"
import sys
m, b, ca, cb = sys.argv[1:5]
lines = open(m).read().split('\n')
w = open(b).read().split(); n, f = int(w[1]), int(w[2]); i = 4 + 3 * n
faces = [[int(x) for x in w[i + 4 * j + 1:i + 4 * j + 4]] for j in range(f)]
for la, lb in zip(open(ca).read().split(), open(cb).read().split()):
    face, *bc = lines[int(la)].split(); bc = [float(x) for x in bc]
    j = faces[int(face)].index(int(lb))
    assert abs(bc[j] - 1) < 1e-9, (la, lb, lines[int(la)])
PY
}

case "$case_name" in
  map_fallback)
    # fine -> ico: the source's tour zigzags on the icosahedron, which has no simple path
    # through its landmarks in that order; the target's tour is a path on both
    python3 "$tmp/spheres.py" "$tmp" || fail "spheres.py"
    printf '2\n9\n1\n4\n10\n3\n6\n' > "$tmp/a.cones"  # (vertices of the icosahedron, numbered alike in both files)
    printf '1\n10\n2\n9\n6\n3\n4\n' > "$tmp/b.cones"  # (landmark i of fine.off corresponds to landmark i of ico.off)
    python3 "$tmp/order.py" "$tmp/fine.off" "$tmp/a.cones" "$tmp/ico.off" "$tmp/b.cones" > "$tmp/cand_ab" || fail "order.py"
    cat "$tmp/cand_ab"
    [ "$(wc -l < "$tmp/cand_ab")" -eq 2 ] || fail "expected two different tours: $(cat "$tmp/cand_ab")"
    first="$(sed -n 1p "$tmp/cand_ab" | cut -d' ' -f3-)"; second="$(sed -n 2p "$tmp/cand_ab" | cut -d' ' -f3-)"
    [ "$(sed -n 1p "$tmp/cand_ab" | cut -d' ' -f1)" = 0 ] || fail "the source's tour should rank first here: $(cat "$tmp/cand_ab")"
    # the source's tour alone (the old behaviour, --order tsp) is refused by the target, in one line, no file
    expect_error "$tmp/m.txt" "target: no path from landmark" map --order tsp --source "$tmp/fine.off" --source-cones "$tmp/a.cones" \
      --target "$tmp/ico.off" --target-cones "$tmp/b.cones" --out "$tmp/m.txt" --report "$tmp/r.json"
    [ ! -e "$tmp/r.json" ] || fail "report left behind"
    # by default the target's tour is tried next, and works
    "$prog" map --source "$tmp/fine.off" --source-cones "$tmp/a.cones" --target "$tmp/ico.off" --target-cones "$tmp/b.cones" \
      --out "$tmp/m.txt" --report "$tmp/r.json" > "$tmp/stdout" 2> "$tmp/stderr" || fail "map fine -> ico: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    grep -q "^landmark order: .*(the target's tour; the source's tour (.*) was refused by the target: " "$tmp/stdout" || fail "stdout: $(cat "$tmp/stdout")"
    same_order "$(report_order "$tmp/r.json")" "$second" || fail "order $(report_order "$tmp/r.json"), expected $second"
    [ "$(json_field "$tmp/r.json" landmark_order_from)" = target ] || fail "landmark_order_from: $(json_field "$tmp/r.json" landmark_order_from)"
    [ "$(json_field "$tmp/r.json" orders_tried)" = 2 ] || fail "orders_tried: $(json_field "$tmp/r.json" orders_tried)"
    [ "$(wc -l < "$tmp/m.txt")" -eq 162 ] || fail "map lines"
    landmarks_onto_landmarks "$tmp/m.txt" "$tmp/ico.off" "$tmp/a.cones" "$tmp/b.cones"
    # the other way: the source (now ico) ranks second; the target's tour (fine's, first) is refused by the source
    python3 "$tmp/order.py" "$tmp/ico.off" "$tmp/b.cones" "$tmp/fine.off" "$tmp/a.cones" > "$tmp/cand_ba" || fail "order.py"
    cat "$tmp/cand_ba"
    "$prog" map --source "$tmp/ico.off" --source-cones "$tmp/b.cones" --target "$tmp/fine.off" --target-cones "$tmp/a.cones" \
      --out "$tmp/m2.txt" --report "$tmp/r2.json" > "$tmp/stdout" 2> "$tmp/stderr" || fail "map ico -> fine: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    same_order "$(report_order "$tmp/r2.json")" "$second" || fail "back: order $(report_order "$tmp/r2.json"), expected $second"
    [ "$(json_field "$tmp/r2.json" landmark_order_from)" = source ] || fail "back: landmark_order_from"
    [ "$(json_field "$tmp/r2.json" orders_tried)" = 2 ] || fail "back: orders_tried"
    landmarks_onto_landmarks "$tmp/m2.txt" "$tmp/fine.off" "$tmp/b.cones" "$tmp/a.cones"
    # --order given: the files' order (a path on the icosahedron too)
    "$prog" map --order given --source "$tmp/fine.off" --source-cones "$tmp/a.cones" --target "$tmp/ico.off" --target-cones "$tmp/b.cones" \
      --out "$tmp/m3.txt" --report "$tmp/r3.json" > /dev/null || fail "map --order given"
    [ "$(report_order "$tmp/r3.json")" = "0 1 2 3 4 5 6" ] || fail "--order given: $(report_order "$tmp/r3.json")"
    [ "$(json_field "$tmp/r3.json" landmark_order_from)" = given ] || fail "--order given: landmark_order_from"
    [ "$(json_field "$tmp/r3.json" orders_tried)" = 1 ] || fail "--order given: orders_tried"
    expect_error "$tmp/m4.txt" "order must be given, tsp or auto" map --order best --source "$tmp/fine.off" --source-cones "$tmp/a.cones" \
      --target "$tmp/ico.off" --target-cones "$tmp/b.cones" --out "$tmp/m4.txt"
    ;;
  map_certificate_fallback)
    # An order the target's embedding cannot certify (not a cut failure): an octopus (test/
    # octopus.awk, tentacles of length 6 to 12) with landmarks at its poles and, on every
    # tentacle, at the tip and 5 rings below it, against an icosphere whose landmarks lie on the
    # equator in a chosen circular order, so that its tour is that order (points on a circle,
    # the shortest closed tour goes round it; opened at the one wider gap, after the last). That
    # order is the octopus's own tour except that tentacle 0's tip (landmark 3) comes after the
    # north pole (0) instead of next to its partner (2): the cut then leaves the thin tentacle
    # between two far parts of the border, where double precision flips triangles. The
    # sphere's tour ranks first (its cut is short on both meshes), the octopus refuses it, and
    # the octopus's own tour is taken.
    awk -v L=12 -f "$here/octopus.awk" > "$tmp/oct.off" 2> "$tmp/oct.std" || fail "octopus.awk"
    # (ring width: 16 vertices at FINE=1; the tip's cap has 4 rings of them, then the tip)
    awk '{ printf "%d\n%d\n", $1, $2; for(i = 3; i < NF; i += 2) printf "%d\n%d\n", $(i + 1) - 96, $(i + 1) }' "$tmp/oct.std" > "$tmp/oct.cones"
    [ "$(wc -l < "$tmp/oct.cones")" -eq 18 ] || fail "octopus landmarks: $(cat "$tmp/oct.std")"
    order="5 4 2 10 11 17 16 9 8 0 3 6 7 14 15 1 13 12"
    python3 - "$tmp" "$order" <<'PY' || fail "sphere"
import math, sys
d, order = sys.argv[1], [int(x) for x in sys.argv[2].split()]
sys.path.insert(0, d)
from icosphere import V, F, split
for _ in range(3):
    V, F = split(V, F)
n = len(order); lm = [None] * n
for k, i in enumerate(order):  # landmark order[k] at longitude 2 pi k / (n + 1), slightly off the equator
    a = 2 * math.pi * k / (n + 1); p = (math.cos(a), math.sin(a), 0.05 * (-1) ** k)
    lm[i] = min(range(len(V)), key=lambda v: math.dist(V[v], p))
assert len(set(lm)) == n
with open(d + "/sphere.off", "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
    for v in V: f.write("%.17g %.17g %.17g\n" % v)
    for a, b, c in F: f.write("3 %d %d %d\n" % (a, b, c))
with open(d + "/sphere.cones", "w") as f:
    for v in lm: f.write("%d\n" % v)
PY
    args=(--source "$tmp/sphere.off" --source-cones "$tmp/sphere.cones" --target "$tmp/oct.off" --target-cones "$tmp/oct.cones")
    # the sphere's tour alone (--order tsp) is refused by the octopus's certificate, in one line, no file
    expect_error "$tmp/m.txt" "target: .*failed the certificate: NOT bijective" map --order tsp "${args[@]}" --out "$tmp/m.txt" --report "$tmp/r.json"
    [ ! -e "$tmp/r.json" ] || fail "report left behind"
    # by default the octopus's tour is tried next, and certified
    "$prog" map "${args[@]}" --out "$tmp/m.txt" --report "$tmp/r.json" > "$tmp/stdout" 2> "$tmp/stderr" || fail "map: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    grep -q "^landmark order: .*(the target's tour; the source's tour ($order) was refused by the target: .*failed the certificate" "$tmp/stdout" ||
      fail "stdout: $(cat "$tmp/stdout")"
    [ "$(json_field "$tmp/r.json" landmark_order_from)" = target ] || fail "landmark_order_from: $(json_field "$tmp/r.json" landmark_order_from)"
    [ "$(json_field "$tmp/r.json" orders_tried)" = 2 ] || fail "orders_tried: $(json_field "$tmp/r.json" orders_tried)"
    used="$(report_order "$tmp/r.json")"
    ! same_order "$used" "$order" || fail "the refused order was used: $used"
    [ "$(wc -l < "$tmp/m.txt")" -eq 642 ] || fail "map lines"
    landmarks_onto_landmarks "$tmp/m.txt" "$tmp/oct.off" "$tmp/sphere.cones" "$tmp/oct.cones"
    ;;
  map_none_works)
    # two icosahedra whose landmarks correspond so that each one's tour zigzags on the other:
    # every order is refused, and the message names both and why
    python3 "$tmp/spheres.py" "$tmp" || fail "spheres.py"
    printf '2\n9\n1\n4\n10\n3\n6\n' > "$tmp/a.cones"
    printf '1\n10\n2\n9\n6\n3\n4\n' > "$tmp/b.cones"
    python3 "$tmp/order.py" "$tmp/ico.off" "$tmp/a.cones" "$tmp/ico.off" "$tmp/b.cones" > "$tmp/cand" || fail "order.py"
    cat "$tmp/cand"
    [ "$(wc -l < "$tmp/cand")" -eq 2 ] || fail "expected two different tours"
    expect_error "$tmp/m.txt" "no landmark order works for both meshes (2 tried): the .*'s tour (.*) was refused by the .*; the .*'s tour (.*) was refused by the " \
      map --source "$tmp/ico.off" --source-cones "$tmp/a.cones" --target "$tmp/ico.off" --target-cones "$tmp/b.cones" \
      --out "$tmp/m.txt" --report "$tmp/r.json"
    [ ! -e "$tmp/r.json" ] || fail "report left behind"
    ;;
  map_ranking)
    # bear.off against itself with its landmarks listed in another order (landmark i of A is
    # landmark s(i) of B's file): the two tours differ; the order used is the best candidate
    [ -f "$data/meshes/bear.off" ] || { echo "bear.off not found: skipped"; exit 0; }
    B="$data/meshes/bear.off"
    printf '8768\n4116\n9726\n8409\n4292\n54\n13749\n' > "$tmp/a.cones"
    printf '4292\n9726\n54\n8768\n13749\n4116\n8409\n' > "$tmp/b.cones"
    for pair in "a b" "b a"; do
      set -- $pair
      python3 "$tmp/order.py" "$B" "$tmp/$1.cones" "$B" "$tmp/$2.cones" > "$tmp/cand" || fail "order.py"
      cat "$tmp/cand"
      [ "$(wc -l < "$tmp/cand")" -eq 2 ] || fail "expected two different tours"
      "$prog" map --source "$B" --source-cones "$tmp/$1.cones" --target "$B" --target-cones "$tmp/$2.cones" \
        --out "$tmp/m.txt" --report "$tmp/r.json" > "$tmp/stdout" 2> "$tmp/stderr" || fail "map $1 -> $2: $(cat "$tmp/stderr")"
      cat "$tmp/stdout"
      same_order "$(report_order "$tmp/r.json")" "$(sed -n 1p "$tmp/cand" | cut -d' ' -f3-)" || fail "$1 -> $2: order $(report_order "$tmp/r.json"), expected the first of: $(cat "$tmp/cand")"
      from="$(sed -n 1p "$tmp/cand" | cut -d' ' -f1 | sed 's/0/source/; s/1/target/')"
      [ "$(json_field "$tmp/r.json" landmark_order_from)" = "$from" ] || fail "$1 -> $2: landmark_order_from, expected $from"
      [ "$(json_field "$tmp/r.json" orders_tried)" = 1 ] || fail "$1 -> $2: orders_tried"
      landmarks_onto_landmarks "$tmp/m.txt" "$B" "$tmp/$1.cones" "$tmp/$2.cones"
      # --order tsp: the source's tour, as before
      python3 "$tmp/order.py" "$B" "$tmp/$1.cones" > "$tmp/own"
      "$prog" map --order tsp --source "$B" --source-cones "$tmp/$1.cones" --target "$B" --target-cones "$tmp/$2.cones" \
        --out "$tmp/m.txt" --report "$tmp/r.json" > /dev/null 2>&1 || fail "map --order tsp $1 -> $2"
      same_order "$(report_order "$tmp/r.json")" "$(cut -d' ' -f3- "$tmp/own")" || fail "--order tsp: not the source's tour"
      [ "$(json_field "$tmp/r.json" landmark_order_from)" = source ] || fail "--order tsp: landmark_order_from"
    done
    # the same landmarks on both: one tour, the source's, bit for bit the map of --order tsp
    "$prog" map --source "$B" --source-cones "$tmp/a.cones" --target "$B" --target-cones "$tmp/a.cones" --out "$tmp/m1.txt" \
      --report "$tmp/r1.json" > /dev/null || fail "map a -> a"
    "$prog" map --order tsp --source "$B" --source-cones "$tmp/a.cones" --target "$B" --target-cones "$tmp/a.cones" --out "$tmp/m2.txt" \
      > /dev/null || fail "map --order tsp a -> a"
    cmp -s "$tmp/m1.txt" "$tmp/m2.txt" || fail "auto and tsp differ on one landmark file"
    [ "$(json_field "$tmp/r1.json" landmark_order_from)" = source ] || fail "a -> a: landmark_order_from"
    # --order given
    "$prog" map --order given --source "$B" --source-cones "$tmp/a.cones" --target "$B" --target-cones "$tmp/b.cones" --out "$tmp/m.txt" \
      --report "$tmp/r.json" > /dev/null || fail "map --order given"
    [ "$(report_order "$tmp/r.json")" = "0 1 2 3 4 5 6" ] || fail "--order given: $(report_order "$tmp/r.json")"
    [ "$(json_field "$tmp/r.json" landmark_order_from)" = given ] || fail "--order given: landmark_order_from"
    ;;
  collection)
    # fine, ico, fine: mesh 0's tour ranks first and the icosahedron refuses it; the collection
    # takes mesh 1's (the icosahedron's own), which every mesh accepts
    python3 "$tmp/spheres.py" "$tmp" || fail "spheres.py"
    printf '2\n9\n1\n4\n10\n3\n6\n' > "$tmp/a.cones"
    printf '1\n10\n2\n9\n6\n3\n4\n' > "$tmp/b.cones"
    printf 'fine.off a.cones\nico.off b.cones\nfine.off a.cones\n' > "$tmp/list.txt"
    python3 "$tmp/order.py" "$tmp/fine.off" "$tmp/a.cones" "$tmp/ico.off" "$tmp/b.cones" "$tmp/fine.off" "$tmp/a.cones" > "$tmp/cand" || fail "order.py"
    cat "$tmp/cand"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" > "$tmp/stdout" 2> "$tmp/stderr" || fail "collection: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    grep -q "^landmark order: .*(the tour of mesh 1; the tour of mesh 0 was refused by mesh 1: " "$tmp/stdout" || fail "stdout"
    order="$(grep -o '"landmark_order_used": \[[0-9, ]*\]' "$tmp/out/report.json" | sed 's/.*\[//; s/\]//; s/,//g')"
    same_order "$order" "$(sed -n 2p "$tmp/cand" | cut -d' ' -f3-)" || fail "collection order $order"
    [ "$(json_field "$tmp/out/report.json" landmark_order_from)" = "mesh 1" ] || fail "landmark_order_from"
    [ "$(json_field "$tmp/out/report.json" orders_tried)" = 2 ] || fail "orders_tried"
    # --order tsp: mesh 0's tour alone, refused; no report
    expect_error "$tmp/o2/report.json" "ico.off: .*no path from landmark" collection --order tsp --manifest "$tmp/list.txt" --out "$tmp/o2"
    # separate jobs try only the first order, and say so
    expect_error "$tmp/o3/report.json" "separate jobs try no other" collection --manifest "$tmp/list.txt" --out "$tmp/o3" --stage embed
    # given order that works (the icosahedron's tour, written as the files' order) in separate jobs
    sed -n 2p "$tmp/cand" | cut -d' ' -f3- | tr ' ' '\n' > "$tmp/perm"
    awk 'NR == FNR { l[FNR - 1] = $1; next } { print l[$1] }' "$tmp/a.cones" "$tmp/perm" > "$tmp/a2.cones"
    awk 'NR == FNR { l[FNR - 1] = $1; next } { print l[$1] }' "$tmp/b.cones" "$tmp/perm" > "$tmp/b2.cones"
    printf 'fine.off a2.cones\nico.off b2.cones\nfine.off a2.cones\n' > "$tmp/list2.txt"
    for stage in embed maps merge; do
      "$prog" collection --order given --manifest "$tmp/list2.txt" --out "$tmp/o4" --stage $stage > /dev/null 2>&1 || fail "stage $stage"
    done
    [ "$(json_field "$tmp/o4/report.json" landmark_order_from)" = given ] || fail "jobs: landmark_order_from"
    [ "$(json_field "$tmp/o4/report.json" orders_tried)" = 1 ] || fail "jobs: orders_tried"
    ;;
  *)
    fail "unknown case $case_name"
    ;;
esac
echo "ok: $case_name"
