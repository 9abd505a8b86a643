#!/usr/bin/env bash
# The `view` job (label viewer): test_view.sh PROGRAM CASE DATA_DIR. Each case writes a view
# folder, opens it in headless Chromium (Debian's chromium, WebGL through SwiftShader) as
# index.html?selftest=1[&pick=I,J,...], and checks the page's report (<pre id="selftest">, written by
# tools/viewer/viewer.js) against facts from outside the viewer: WebGL ran and drew every view,
# no console error, each landmark marker's pixel has its colour at the landmark's projected
# position, the landmarks are the landmark file's (numbers and vertices), and the image the
# picking returns for vertex I is line I of the MAP.txt the `map` job (or the collection) wrote.
# Without WebGL (a control run with --disable-3d-apis) the page's report must say it failed.
#   embedding: bear.off, 7 landmarks; errors: bad options, a missing file, --out an existing
#     folder that is not a view (left as it was), no DIR.tmp left; a view replaced in place
#   map: bear onto its bent copy (test/bend.awk); colours of B against map --colors-out, the
#     distortion against map's report
#     (and no unreliable point drawn: the map has none)
#   unreliable: a capsule without a landmark at its far tip onto a bent copy: the page's
#     unreliable vertices are those of map's report, and drawn (magenta pixels in both views)
#   collection: four hands (test/cli_lib.sh), picking against 0_to_1, 0_to_2 and 0_to_3.map.txt
#   genus: eight.off (genus 2, two cones): drawn without the tiling (coloured by position), cut
#     along embed's cut graph;
#     a map between two such files refused
set -u
prog="$1"; case_name="$2"; data="${3:-}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
. "$here/cli_lib.sh"   # make_hands
command -v chromium >/dev/null || fail "chromium is not installed (scripts/install-deps.sh installs it)"
command -v python3 >/dev/null || fail "python3 is needed to read the page's JSON report"

# selftest DIR QUERY OUT.json [CHROMIUM_FLAGS...]: the page's report
selftest() {
  local dir="$1" query="$2" out="$3"; shift 3
  timeout 90 chromium --headless=new --no-sandbox --disable-gpu --use-angle=swiftshader --enable-unsafe-swiftshader \
    --user-data-dir="$tmp/profile" --window-size=1200,600 --virtual-time-budget=10000 "$@" \
    --dump-dom "file://$dir/index.html?$query" 2>"$tmp/chromium.log" > "$tmp/dom.html" || fail "chromium failed: $(tail -3 "$tmp/chromium.log")"
  python3 - "$tmp/dom.html" "$out" <<'EOF' || fail "no self-test report in the page"
import html, re, sys
m = re.search(r'<pre id="selftest">(.*?)</pre>', open(sys.argv[1], encoding='utf-8').read(), re.S)
if not m or not m.group(1).strip():
    sys.exit(1)
open(sys.argv[2], 'w').write(html.unescape(m.group(1)))
EOF
}

# check REPORT.json CONES VIEWS [PICK_ARGS]: python checks of the report; see check.py below
check() {
  python3 "$tmp/check.py" "$@" || fail "self-test report: $(head -c 1500 "$1")"
}
cat > "$tmp/check.py" <<'EOF'
# check.py REPORT.json CONES VIEWS [MAP.txt SHAPE]...: the page's report against outside facts
import json, sys
r = json.load(open(sys.argv[1]))
cones = [int(x) for x in open(sys.argv[2]).read().split()]
views = int(sys.argv[3])
def bad(msg):
    print('FAIL:', msg); sys.exit(1)
if not r.get('webgl'): bad('no WebGL')
if r.get('errors') != 0: bad('console errors: %s' % r.get('error_messages'))
if len(r['views']) != views: bad('%d views, expected %d' % (len(r['views']), views))
for v in r['views']:
    if v['covered_fraction'] < 0.03 or v['distinct_colours'] < 10:
        bad('view %s drew almost nothing: %s' % (v['kind'], v))
for view in range(views):
    ls = [l for l in r['landmarks'] if l['view'] == view]
    if r['views'][view]['kind'] == 'surface':
        if sorted((l['number'], l['vertex']) for l in ls) != sorted(enumerate(cones)):
            bad('view %d: landmarks %s, not the file\'s %s' % (view, [(l['number'], l['vertex']) for l in ls], cones))
    elif sorted(set(l['number'] for l in ls)) != list(range(len(cones))):
        bad('view %d: not every landmark is drawn' % view)
    free = [l for l in ls if not l['covered']]
    if len(free) * 2 < len(ls): bad('view %d: most markers cover each other' % view)
    for l in free:
        if not l['match']: bad('view %d: landmark %d at (%s, %s): pixel %s, not its colour %s' % (view, l['number'], l['x'], l['y'], l['found'], l['expected']))
if not r.get('ok'): bad('the page says not ok')
args = sys.argv[4:]
for k in range(0, len(args), 2):
  lines, shape = open(args[k]).read().split('\n'), int(args[k + 1])
  if not r.get('picks'): bad('no pick in the report')
  for p in r['picks']:
    want = lines[p['vertex']].split()
    im = [i for i in p['images'] if i['shape'] == shape]
    if len(im) != 1: bad('no image on shape %d' % shape)
    im = im[0]
    if im['face'] != int(want[0]) or max(abs(a - float(b)) for a, b in zip(im['bary'], want[1:])) > 1e-9:
        bad('pick %d on shape %d: face %d %s, %s says %s' % (p['vertex'], shape, im['face'], im['bary'], args[k], want))
    print('ok: vertex %d -> shape %d face %d, as line %d of %s' % (p['vertex'], shape, im['face'], p['vertex'], args[k].split('/')[-1]))
print('ok: %d views, %d landmark markers' % (views, len(r['landmarks'])))
EOF

# the page's data (data.js) as JSON
data_json() { sed -e '1d' -e 's/^window.HOT_VIEW = //' -e '$ s/;$//' "$1/data.js" > "$2"; }

off="$data/meshes/bear.off"
echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/c.txt"

case "$case_name" in
  embedding)
    "$prog" embed --mesh "$off" --cones "$tmp/c.txt" --out "$tmp/a.obj" >/dev/null || fail "embed"
    "$prog" view --embedding "$tmp/a.obj" --out "$tmp/v" > "$tmp/stdout" || fail "view"
    for f in index.html data.js viewer.js three.min.js; do [ -s "$tmp/v/$f" ] || fail "no $f"; done
    cmp -s "$tmp/v/three.min.js" /usr/share/javascript/three/three.min.js || fail "three.min.js is not Debian's"
    grep -q '<script src="data.js"></script>' "$tmp/v/index.html" || fail "index.html does not load data.js as a classic script"
    ! grep -v '^ *//' "$tmp/v/index.html" "$tmp/v/viewer.js" | grep -q 'type="module"\|fetch(\|import ' || fail "modules or fetch() do not work from file://"
    selftest "$tmp/v" "selftest=1" "$tmp/r.json"
    check "$tmp/r.json" "$tmp/c.txt" 2
    # the disk's markers: each landmark at its cone, a corner of the tile, inside the unit disk
    data_json "$tmp/v" "$tmp/d.json"
    python3 - "$tmp/d.json" "$tmp/a.obj" <<'EOF' || fail "the page's data is not the embedding's"
import json, sys
d = json.load(open(sys.argv[1])); s = d['shapes'][0]
v = [l for l in open(sys.argv[2]) if l.startswith('v ')]
f = [l for l in open(sys.argv[2]) if l.startswith('f ')]
vt = [[float(x) for x in l.split()[1:3]] for l in open(sys.argv[2]) if l.startswith('vt ')]
assert len(s['positions']) == 3 * len(v) and len(s['faces']) == 3 * len(f), 'sizes'
# face 0 as the OBJ has it: its vertices and their vt points
c = [t.split('/') for t in f[0].split()[1:]]
assert [int(a[0]) - 1 for a in c] == s['faces'][0:3], 'face 0'
assert all(abs(vt[int(a[1]) - 1][k] - s['uv'][2 * j + k]) < 1e-12 for j, a in enumerate(c) for k in range(2)), 'uv of face 0'
assert len(s['cut']) > 0 and len(s['fold']) == 14, 'cut or the folding polygon (7 corners)'
print('ok: the data is the OBJ file\'s (%d vertices, %d faces, %d cut edges)' % (len(v), len(f), len(s['cut']) // 2))
EOF
    # a control: without WebGL the page must say so (the check above can fail)
    selftest "$tmp/v" "selftest=1" "$tmp/nogl.json" --disable-3d-apis
    python3 -c "import json,sys; r=json.load(open(sys.argv[1])); sys.exit(0 if not r.get('ok') else 1)" "$tmp/nogl.json" ||
      fail "the page says ok without WebGL"
    echo "ok: without WebGL the page reports a failure"
    # errors: one line, non-zero status, nothing written
    expect() { # expect STATUS ARGS...
      local want="$1"; shift
      "$prog" "$@" > "$tmp/stdout" 2> "$tmp/stderr"; local rc=$?
      [ $rc -eq "$want" ] || fail "exit $rc (not $want) for: $* -- $(cat "$tmp/stderr")"
      [ "$(wc -l < "$tmp/stderr")" -eq 1 ] || fail "stderr is not one line for: $*"
      echo "ok (exit $rc): $(cat "$tmp/stderr")"
    }
    expect 2 view --embedding "$tmp/a.obj"
    expect 2 view --embedding "$tmp/a.obj" --collection "$tmp" --out "$tmp/x"
    expect 2 view --source-embedding "$tmp/a.obj" --out "$tmp/x"
    expect 2 view --embedding "$tmp/a.obj" --out "$tmp/x" --bogus 1
    expect 3 view --embedding "$tmp/none.obj" --out "$tmp/x"
    grep -v '^# hot orbifold' "$tmp/a.obj" > "$tmp/n.obj"
    expect 3 view --embedding "$tmp/n.obj" --out "$tmp/x"
    expect 3 view --collection "$tmp/v" --out "$tmp/x"
    [ ! -e "$tmp/x" ] && [ ! -e "$tmp/x.tmp" ] || fail "output left behind"
    mkdir "$tmp/other"; echo keep > "$tmp/other/notes.txt"
    expect 1 view --embedding "$tmp/a.obj" --out "$tmp/other"
    [ "$(ls -A "$tmp/other")" = notes.txt ] || fail "the folder that is not a view was changed"
    HOT_THREE_JS="$tmp/none.js" "$prog" view --embedding "$tmp/a.obj" --out "$tmp/x" 2> "$tmp/stderr" >/dev/null && fail "no three.js: exit 0"
    grep -q "libjs-three" "$tmp/stderr" || fail "no three.js: the reason does not name libjs-three"
    [ ! -e "$tmp/x" ] && [ ! -e "$tmp/x.tmp" ] || fail "output left behind without three.js"
    # a view written again over itself
    "$prog" view --embedding "$tmp/a.obj" --out "$tmp/v" > /dev/null || fail "view over a view"
    [ "$(ls "$tmp/v" | tr '\n' ' ')" = "data.js index.html three.min.js viewer.js " ] || fail "files after writing again: $(ls "$tmp/v")"
    [ -z "$(ls -d "$tmp"/v.* 2>/dev/null)" ] || fail "left behind: $(ls -d "$tmp"/v.*)"
    echo ok ;;
  map)
    awk -v R=3 -f "$here/bend.awk" "$off" > "$tmp/bent.off"
    "$prog" embed --mesh "$off" --cones "$tmp/c.txt" --out "$tmp/a.obj" --report "$tmp/a.json" >/dev/null || fail "embed source"
    pos=$(sed -n 's/.*"landmark_positions_used": \[\(.*\)\].*/\1/p' "$tmp/a.json" | tr -d ' ')
    "$prog" embed --mesh "$tmp/bent.off" --cones "$tmp/c.txt" --order "$pos" --out "$tmp/b.obj" >/dev/null || fail "embed target"
    "$prog" map --source-embedding "$tmp/a.obj" --target-embedding "$tmp/b.obj" --out "$tmp/m.txt" --report "$tmp/m.json" >/dev/null || fail "map"
    "$prog" map --source "$off" --source-cones "$tmp/c.txt" --target "$tmp/bent.off" --target-cones "$tmp/c.txt" --out "$tmp/m2.txt" \
      --colors-out "$tmp/b.ply" >/dev/null || fail "map --colors-out"
    "$prog" view --source-embedding "$tmp/a.obj" --target-embedding "$tmp/b.obj" --out "$tmp/v" >/dev/null || fail "view"
    selftest "$tmp/v" "selftest=1&pick=5000,12345,121" "$tmp/r.json"
    check "$tmp/r.json" "$tmp/c.txt" 2 "$tmp/m.txt" 1
    data_json "$tmp/v" "$tmp/d.json"
    python3 - "$tmp/d.json" "$tmp/b.ply" "$tmp/m.json" <<'EOF' || fail "the page's data against map's outputs"
import json, sys
d = json.load(open(sys.argv[1]))
# B's colours: map --colors-out colours B by the same field carried by the map from B onto A
lines = open(sys.argv[2]).read().split('\n')
n = int([l for l in lines if l.startswith('element vertex')][0].split()[2])
start = lines.index('end_header') + 1
ply = [[int(x) / 255 for x in l.split()[3:6]] for l in lines[start:start + n]]
col = d['shapes'][1]['colors']
worst = max(abs(col[3 * i + k] - ply[i][k]) for i in range(n) for k in range(3))
assert worst <= 0.5 / 255 + 1e-4, 'colours of B differ from map --colors-out by %g' % worst
# the distortion of A's faces: the report's percentiles
rep = json.load(open(sys.argv[3]))['distortion']
conf = sorted(x for x in d['shapes'][0]['distortion']['conformal'] if x is not None)
assert abs(conf[-1] - rep['conformal']['max']) <= 1e-4 * rep['conformal']['max'], 'max %g, report %g' % (conf[-1], rep['conformal']['max'])
assert len(conf) == rep['faces'], 'faces'
assert len(d['maps'][0]['unreliable']) == json.load(open(sys.argv[3]))['unreliable_vertex_count'], 'unreliable count'
print('ok: B coloured as map --colors-out (within %.2g), conformal max %.6g as the report' % (worst, conf[-1]))
EOF
    python3 -c "import json,sys; r=json.load(open(sys.argv[1])); sys.exit(0 if all(v['magenta_pixels'] == 0 for v in r['views']) else 1)" "$tmp/r.json" ||
      fail "unreliable points drawn, but the map has none"
    echo ok ;;
  unreliable)
    # a capsule (length 20, five landmarks on one cap) onto a bent copy: the map cannot resolve
    # most of the tube (map's report lists the vertices); the page marks them (magenta points)
    awk -v L=20 -v S=24 -f "$here/capsule.awk" > "$tmp/c.off" 2> "$tmp/cc.txt"
    awk -v R=20 -f "$here/bend.awk" "$tmp/c.off" > "$tmp/b.off"
    "$prog" embed --mesh "$tmp/c.off" --cones "$tmp/cc.txt" --out "$tmp/a.obj" --report "$tmp/a.json" >/dev/null || fail "embed source"
    pos=$(sed -n 's/.*"landmark_positions_used": \[\(.*\)\].*/\1/p' "$tmp/a.json" | tr -d ' ')
    "$prog" embed --mesh "$tmp/b.off" --cones "$tmp/cc.txt" --order "$pos" --out "$tmp/b.obj" >/dev/null || fail "embed target"
    "$prog" map --source-embedding "$tmp/a.obj" --target-embedding "$tmp/b.obj" --out "$tmp/m.txt" --report "$tmp/m.json" >/dev/null 2>&1 || fail "map"
    "$prog" view --source-embedding "$tmp/a.obj" --target-embedding "$tmp/b.obj" --out "$tmp/v" > "$tmp/stdout" || fail "view"
    grep -q "unreliable images marked" "$tmp/stdout" || fail "view does not say it marks unreliable images: $(cat "$tmp/stdout")"
    data_json "$tmp/v" "$tmp/d.json"
    python3 - "$tmp/d.json" "$tmp/m.json" <<'EOF2' || fail "the unreliable vertices are not map's"
import json, sys
d, rep = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
m = [x for x in d['maps'] if x['from'] == 0 and x['to'] == 1][0]
assert rep['unreliable_vertex_count'] > 0 and m['unreliable'] == sorted(rep['unreliable_vertices']), 'the lists differ'
print('ok: the page marks the %d unreliable vertices of map\'s report' % len(m['unreliable']))
EOF2
    selftest "$tmp/v" "selftest=1&pick=0" "$tmp/r.json"
    check "$tmp/r.json" "$tmp/cc.txt" 2 "$tmp/m.txt" 1
    python3 -c "import json,sys; r=json.load(open(sys.argv[1])); sys.exit(0 if all(v['magenta_pixels'] > 0 for v in r['views']) else 1)" "$tmp/r.json" ||
      fail "no unreliable points drawn: $(head -c 600 "$tmp/r.json")"
    echo ok ;;
  collection)
    make_hands a b c e
    "$prog" landmarks --mesh "$tmp/hand_a.off" --count 9 --out "$tmp/cones.txt" >/dev/null || fail "landmarks"
    printf 'hand_a.off cones.txt\nhand_b.off cones.txt\nhand_c.off cones.txt\nhand_e.off cones.txt\n' > "$tmp/list.txt"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs 2>/dev/null >/dev/null || fail "collection"
    "$prog" view --collection "$tmp/out" --out "$tmp/v" >/dev/null || fail "view"
    selftest "$tmp/v" "selftest=1&pick=700,3" "$tmp/r.json"
    check "$tmp/r.json" "$tmp/cones.txt" 4 "$tmp/out/0_to_1.map.txt" 1 "$tmp/out/0_to_2.map.txt" 2 "$tmp/out/0_to_3.map.txt" 3
    echo ok ;;
  genus)
    # a closed mesh of genus 2 with two cones (eight.off): drawn without the tiling (its tile
    # depends on the cut graph, which the OBJ file does not hold), with the cut graph embed wrote
    # as its cut
    echo "0 300" > "$tmp/two.cones"
    "$prog" embed --mesh "$data/meshes/eight.off" --cones "$tmp/two.cones" --out "$tmp/e.obj" --cut-graph-out "$tmp/e.cut" \
      >/dev/null || fail "embed eight"
    "$prog" view --embedding "$tmp/e.obj" --out "$tmp/v" >/dev/null || fail "view of a genus-2 embedding"
    selftest "$tmp/v" "selftest=1" "$tmp/r.json"
    check "$tmp/r.json" "$tmp/two.cones" 2
    data_json "$tmp/v" "$tmp/d.json"
    python3 - "$tmp/d.json" "$tmp/e.cut" <<'EOF2' || fail "the page's cut is not the cut graph"
import json, sys
s = json.load(open(sys.argv[1]))['shapes'][0]
assert s['fold'] is None, 'a folding polygon for genus 2: %s' % s['fold']
assert s['colors'] and len(s['colors']) == len(s['positions']), 'no colour field in place of the tiling'

page = {tuple(sorted(s['cut'][i:i + 2])) for i in range(0, len(s['cut']), 2)}
paths = [[int(x) for x in l.split()] for l in open(sys.argv[2]) if l.strip() and not l.startswith('#')]
graph = {tuple(sorted(p[j:j + 2])) for p in paths for j in range(len(p) - 1)}
assert page == graph, '%d cut edges on the page, %d on the cut graph, %d in common' % (len(page), len(graph), len(page & graph))
print('ok: the page cuts along the %d edges of the cut graph, without a tiling' % len(graph))
EOF2
    # a map between genus-2 embeddings still needs their cut graphs: refused, nothing written
    "$prog" view --source-embedding "$tmp/e.obj" --target-embedding "$tmp/e.obj" --out "$tmp/v2" 2> "$tmp/stderr" >/dev/null
    rc=$?
    [ $rc -eq 3 ] && grep -q "cut graph" "$tmp/stderr" && [ ! -e "$tmp/v2" ] || fail "the refusal (exit $rc): $(cat "$tmp/stderr")"
    echo "ok: refused: $(cat "$tmp/stderr")" ;;
  *) fail "unknown case $case_name" ;;
esac
