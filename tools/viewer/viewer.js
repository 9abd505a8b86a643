// The viewer of `hyperbolic_orbifold_tutte view` (and of the Python module's view()): draws the
// shapes of window.HOT_VIEW (data.js, written by tools/view_job.h) side by side with three.js
// (Debian's libjs-three, r111, copied next to this file). Classic script, no modules, no fetch():
// the folder opens from file:// in any browser.
//
// HOT_VIEW = { kind: "embedding" | "map" | "collection", title, shapes: [shape], maps: [map] }
//   shape: name, positions [x y z ...] per vertex, faces [a b c ...] (vertices in the file's
//     order), colors [r g b ...] per vertex in [0, 1] (or null), landmark_numbers and
//     landmark_vertices (landmark i of the landmark file at a vertex), distortion
//     {conformal: [...], area: [...]} per face (or null), and for an embedding: uv [u v ...] per
//     face corner (Poincare disk), cut [a b ...] (vertex pairs of the cut's edges), cut_uv
//     [u0 v0 u1 v1 ...] (the same edges in the disk, both sides), fold [x y ...] (the polygon
//     whose reflections tile the disk)
//   map: from, to (shape indices), face [f ...] and bary [b0 b1 b2 ...] per vertex of `from`
//     (the face of `to` and the barycentric coordinates w.r.t. its vertices in file order:
//     MAP.txt's numbers), unreliable [vertices of `from` whose image cannot be trusted]
//
// index.html?selftest=1[&pick=I,J,...]: picks vertices I, J, ... of the first shape, renders once at the fixed camera, reads the pixels back and
// writes a JSON report into <pre id="selftest"> (see selfTest() below).
(function () {
  'use strict';
  var errors = [];
  var origError = console.error;
  console.error = function () {
    errors.push(Array.prototype.slice.call(arguments).join(' '));
    origError.apply(console, arguments);
  };
  window.addEventListener('error', function (e) { errors.push('error: ' + (e.message || e)); });

  var params = {};
  location.search.replace(/^\?/, '').split('&').forEach(function (kv) {
    if (!kv) return;
    var p = kv.split('=');
    params[decodeURIComponent(p[0])] = p.length > 1 ? decodeURIComponent(p[1]) : '1';
  });
  var selftest = params.selftest === '1';

  function report(obj) {
    document.getElementById('selftest').textContent = JSON.stringify(obj);
  }

  // distinct marker colours (exact bytes, drawn unlit): the self-test looks for them
  var PALETTE = [0xe6194b, 0x3cb44b, 0x4363d8, 0xffe119, 0xf58231, 0x911eb4, 0x42d4f4, 0xf032e6,
                 0xbfef45, 0xfabed4, 0x469990, 0xdcbeff, 0x9a6324, 0xfffac8, 0x800000, 0xaaffc3,
                 0x808000, 0xffd8b1, 0x000075, 0xa9a9a9];
  var BACKGROUND = 0x202428, DISK_BACKGROUND = 0x181a1c;

  function markerColour(i) { return PALETTE[i % PALETTE.length]; }

  var data = window.HOT_VIEW;
  if (!data || !window.THREE) {
    report({ ok: false, errors: ['data.js or three.min.js did not load'] });
    return;
  }

  // ---- shaders: one material for both modes (vertex colours, or the hyperbolic tiling over uv)
  var MAX_SIDES = 32;
  var vertexShader = [
    'attribute vec3 color;',
    'attribute vec2 hypuv;',
    'varying vec3 vColor;',
    'varying vec2 vUv;',
    'varying vec3 vNormal;',
    'void main() {',
    '  vColor = color; vUv = hypuv;',
    '  vNormal = normalize(normalMatrix * normal);',
    '  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);',
    '}'].join('\n');
  var fragmentShader = [
    'precision highp float;',
    'uniform int mode;', // 0: vertex colours, 1: the tiling over hypuv
    'uniform int lit;',
    'uniform int nSides;',
    'uniform vec4 sides[' + MAX_SIDES + '];', // (cx, cy, r, s) circle, or (nx, ny, 0, s) a diameter; s: the polygon's side
    'uniform vec2 centre;',
    'uniform int nInner;',
    'uniform vec4 inner[' + MAX_SIDES + '];', // geodesics through the polygon's centre and its corners and sides' midpoints
    'varying vec3 vColor;',
    'varying vec2 vUv;',
    'varying vec3 vNormal;',
    'vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }',
    'vec2 cdiv(vec2 a, vec2 b) { return vec2(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / dot(b, b); }',
    'vec2 cconj(vec2 a) { return vec2(a.x, -a.y); }',
    'vec3 hsv(float h, float s, float v) {',
    '  vec3 k = clamp(abs(mod(h * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);',
    '  return v * mix(vec3(1.0), k, s);',
    '}',
    'float sideValue(vec4 sd, vec2 z) {', // > 0 on the polygon's side of the geodesic
    '  if (sd.z > 0.0) { vec2 d = z - sd.xy; return sd.w * (dot(d, d) - sd.z * sd.z); }',
    '  return sd.w * dot(z, sd.xy);',
    '}',
    'vec3 tiling(vec2 z0) {',
    '  vec2 z = z0;',
    '  vec2 a = vec2(1.0, 0.0), b = vec2(0.0), c = vec2(0.0), d = vec2(1.0, 0.0);', // T(z) = (a w + b)/(c w + d), w = z or conj(z)
    '  float parity = 0.0;',
    '  for (int it = 0; it < 60; ++it) {',
    '    int found = -1; vec4 sd = vec4(0.0);',
    '    for (int i = 0; i < ' + MAX_SIDES + '; ++i) {',
    '      if (i >= nSides) break;',
    '      if (found < 0 && sideValue(sides[i], z) < 0.0) { found = i; sd = sides[i]; }',
    '    }',
    '    if (found < 0) break;',
    '    vec2 ma, mb, mc, md;', // the reflection: z -> (ma conj(z) + mb)/(mc conj(z) + md)
    '    if (sd.z > 0.0) { ma = sd.xy; mb = vec2(-1.0, 0.0); mc = vec2(1.0, 0.0); md = -cconj(sd.xy); }',
    '    else { vec2 t = vec2(-sd.y, sd.x); vec2 e = cmul(t, t); ma = e; mb = vec2(0.0); mc = vec2(0.0); md = vec2(1.0, 0.0); }',
    '    vec2 w = cconj(z);',
    '    z = cdiv(cmul(ma, w) + mb, cmul(mc, w) + md);',
    '    vec2 ca = cconj(a), cb = cconj(b), cc = cconj(c), cd = cconj(d);',
    '    a = cmul(ma, ca) + cmul(mb, cc); b = cmul(ma, cb) + cmul(mb, cd);',
    '    c = cmul(mc, ca) + cmul(md, cc); d = cmul(mc, cb) + cmul(md, cd);',
    '    parity = 1.0 - parity;',
    '  }',
    // the copy's centre in the disk: T^-1(centre)
    '  vec2 w0 = cdiv(cmul(d, centre) - b, a - cmul(c, centre));',
    '  vec2 cc0 = parity > 0.5 ? cconj(w0) : w0;',
    '  float hue = atan(cc0.y, cc0.x) / 6.2831853 + 0.5;',
    '  float rr = length(cc0);',
    '  vec3 col = hsv(hue, clamp(rr * 1.6, 0.0, 0.75), parity > 0.5 ? 0.78 : 0.95);',
    // the hyperbolic distance to the nearest side: geodesic grid lines
    '  float best = 1e9;',
    '  float q = max(1.0 - dot(z, z), 1e-7);',
    '  for (int i = 0; i < ' + MAX_SIDES + '; ++i) {',
    '    if (i >= nSides) break;',
    '    vec4 sd = sides[i]; float sh;',
    '    if (sd.z > 0.0) { vec2 dd = z - sd.xy; sh = abs(dot(dd, dd) - sd.z * sd.z) / (sd.z * q); }',
    '    else sh = 2.0 * abs(dot(z, sd.xy)) / q;',
    '    best = min(best, sh);',
    '  }',
    '  float dist = log(best + sqrt(best * best + 1.0));',
    // the subdivision of the polygon by the geodesics through its centre: alternate shades, thin lines
    '  float fine = 1e9, sector = 0.0;',
    '  for (int i = 0; i < ' + MAX_SIDES + '; ++i) {',
    '    if (i >= nInner) break;',
    '    vec4 sd = inner[i]; float sh;',
    '    if (sideValue(sd, z) < 0.0) sector = 1.0 - sector;',
    '    if (sd.z > 0.0) { vec2 dd = z - sd.xy; sh = abs(dot(dd, dd) - sd.z * sd.z) / (sd.z * q); }',
    '    else sh = 2.0 * abs(dot(z, sd.xy)) / q;',
    '    fine = min(fine, sh);',
    '  }',
    '  float fdist = log(fine + sqrt(fine * fine + 1.0));',
    '  col *= sector > 0.5 ? 0.86 : 1.0;',
    '  col *= mix(0.55, 1.0, smoothstep(0.008, 0.018, fdist));',
    '  col *= mix(0.2, 1.0, smoothstep(0.025, 0.05, dist));',
    '  return col;',
    '}',
    'void main() {',
    '  vec3 col = mode == 1 ? tiling(vUv) : vColor;',
    '  if (lit == 1) { float l = 0.35 + 0.65 * abs(normalize(vNormal).z); col *= l; }',
    '  gl_FragColor = vec4(col, 1.0);',
    '}'].join('\n');

  // complex numbers as [re, im]
  function cm(a, b) { return [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]]; }
  function cd(a, b) { var n = b[0] * b[0] + b[1] * b[1]; return [(a[0] * b[0] + a[1] * b[1]) / n, (a[1] * b[0] - a[0] * b[1]) / n]; }
  // the hyperbolic midpoint of p and q (Poincare disk)
  function midpoint(p, q) {
    var one = [1, 0], cp = [p[0], -p[1]];
    var t = cd([q[0] - p[0], q[1] - p[1]], [one[0] - cm(cp, q)[0], -cm(cp, q)[1]]); // T(q), T(z) = (z - p)/(1 - conj(p) z)
    var r = Math.sqrt(t[0] * t[0] + t[1] * t[1]);
    if (r < 1e-15) return p;
    var s = Math.tanh(Math.atanh(Math.min(r, 1 - 1e-15)) / 2) / r, w = [t[0] * s, t[1] * s];
    return cd([w[0] + p[0], w[1] + p[1]], [1 + cm(cp, w)[0], cm(cp, w)[1]]); // T^-1(w) = (w + p)/(1 + conj(p) w)
  }
  // the geodesic through p and q: (cx, cy, r, s) a circle orthogonal to the unit circle, or
  // (nx, ny, 0, s) a diameter of normal n; s: the sign of the side of (mx, my)
  function geodesic(px, py, qx, qy, mx, my) {
    var det = px * qy - py * qx;
    var len = Math.sqrt((qx - px) * (qx - px) + (qy - py) * (qy - py));
    if (Math.abs(det) < 1e-9 * Math.max(len, 1e-30)) {
      var nx = -(qy - py) / len, ny = (qx - px) / len;
      return new THREE.Vector4(nx, ny, 0, (mx * nx + my * ny) >= 0 ? 1 : -1);
    }
    var rp = (px * px + py * py + 1) / 2, rq = (qx * qx + qy * qy + 1) / 2; // 2 c.p = |p|^2 + 1, 2 c.q = |q|^2 + 1
    var cx = (rp * qy - rq * py) / det, cy = (px * rq - qx * rp) / det;
    var r = Math.sqrt(Math.max(cx * cx + cy * cy - 1, 0));
    var vm = (mx - cx) * (mx - cx) + (my - cy) * (my - cy) - r * r;
    return new THREE.Vector4(cx, cy, r, vm >= 0 ? 1 : -1);
  }

  // the geodesic sides of the folding polygon, for the shader
  function foldSides(fold) {
    var n = fold.length / 2, sides = [], mx = 0, my = 0, i;
    for (i = 0; i < n; ++i) { mx += fold[2 * i] / n; my += fold[2 * i + 1] / n; }
    for (i = 0; i < n && i < MAX_SIDES; ++i)
      sides.push(geodesic(fold[2 * i], fold[2 * i + 1], fold[2 * ((i + 1) % n)], fold[2 * ((i + 1) % n) + 1], mx, my));
    // the geodesics through the centre and each corner and side's midpoint (each once)
    var inner = [], through = [];
    for (i = 0; i < n; ++i) {
      var p = [fold[2 * i], fold[2 * i + 1]], q = [fold[2 * ((i + 1) % n)], fold[2 * ((i + 1) % n) + 1]];
      through.push(p, midpoint(p, q));
    }
    through.forEach(function (t) {
      var g = geodesic(mx, my, t[0], t[1], mx + 0.01, my + 0.013);
      var dup = inner.some(function (h) { return Math.abs(h.x - g.x) + Math.abs(h.y - g.y) + Math.abs(h.z - g.z) < 1e-6 ||
                                                   (g.z === 0 && h.z === 0 && Math.abs(h.x + g.x) + Math.abs(h.y + g.y) < 1e-6); });
      if (!dup && inner.length < MAX_SIDES) inner.push(g);
    });
    var nInner = inner.length;
    while (inner.length < MAX_SIDES) inner.push(new THREE.Vector4(0, 0, 0, 1));
    while (sides.length < MAX_SIDES) sides.push(new THREE.Vector4(0, 0, 0, 1));
    return { sides: sides, count: Math.min(n, MAX_SIDES), centre: new THREE.Vector2(mx, my), inner: inner, nInner: nInner };
  }

  function makeMaterial(mode, lit, fold) {
    var f = fold ? foldSides(fold) : { sides: [], count: 0, centre: new THREE.Vector2(0, 0), inner: [], nInner: 0 };
    while (f.sides.length < MAX_SIDES) f.sides.push(new THREE.Vector4(0, 0, 0, 1));
    while (f.inner.length < MAX_SIDES) f.inner.push(new THREE.Vector4(0, 0, 0, 1));
    return new THREE.ShaderMaterial({
      uniforms: { mode: { value: mode }, lit: { value: lit ? 1 : 0 }, nSides: { value: f.count },
                  sides: { value: f.sides }, centre: { value: f.centre }, nInner: { value: f.nInner }, inner: { value: f.inner } },
      vertexShader: vertexShader, fragmentShader: fragmentShader, side: THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }); // (lines on the surface stay in front)
  }

  // ---- geometry: one non-indexed triangle per face (per-face colours for the distortion)
  function smoothNormals(shape) {
    var P = shape.positions, F = shape.faces, n = new Float32Array(P.length), i, j;
    for (i = 0; i < F.length; i += 3) {
      var a = F[i] * 3, b = F[i + 1] * 3, c = F[i + 2] * 3;
      var ux = P[b] - P[a], uy = P[b + 1] - P[a + 1], uz = P[b + 2] - P[a + 2];
      var vx = P[c] - P[a], vy = P[c + 1] - P[a + 1], vz = P[c + 2] - P[a + 2];
      var nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      for (j = 0; j < 3; ++j) { var k = F[i + j] * 3; n[k] += nx; n[k + 1] += ny; n[k + 2] += nz; }
    }
    return n;
  }

  function heat(t) { // t in [0, 1]: blue, white, red
    t = Math.max(0, Math.min(1, t));
    return t < 0.5 ? [0.2 + 1.6 * t, 0.35 + 1.3 * t, 1.0] : [1.0, 1.0 - 1.3 * (t - 0.5), 1.0 - 1.6 * (t - 0.5)];
  }

  function faceColours(shape, what) {
    var F = shape.faces, out = new Float32Array(F.length * 3), i, j, c;
    var dist = shape.distortion;
    for (i = 0; i < F.length / 3; ++i) {
      if (what === 'field') {
        for (j = 0; j < 3; ++j) {
          var v = F[3 * i + j];
          c = shape.colors ? [shape.colors[3 * v], shape.colors[3 * v + 1], shape.colors[3 * v + 2]] : [0.8, 0.8, 0.8];
          out.set(c, 9 * i + 3 * j);
        }
        continue;
      }
      var x = dist ? dist[what][i] : null;
      if (x === null || x === undefined || typeof x === 'string') c = [0.1, 0.1, 0.1];
      else if (what === 'conformal') c = heat(Math.log(Math.max(x, 1)) / Math.log(1.5)); // 1: blue, 1.22: white, 1.5: red
      else c = heat(0.5 + Math.log(Math.max(x, 1e-12)) / Math.log(4)); // area ratio 1/2 .. 1 .. 2
      for (j = 0; j < 3; ++j) out.set(c, 9 * i + 3 * j);
    }
    return out;
  }

  function surfaceGeometry(shape, flat) {
    var F = shape.faces, P = shape.positions, nf = F.length / 3;
    var pos = new Float32Array(nf * 9), nor = new Float32Array(nf * 9), uv = new Float32Array(nf * 6);
    var sn = smoothNormals(shape), i, j;
    for (i = 0; i < nf; ++i)
      for (j = 0; j < 3; ++j) {
        var v = F[3 * i + j], o = 9 * i + 3 * j;
        if (flat) { pos[o] = shape.uv[6 * i + 2 * j]; pos[o + 1] = shape.uv[6 * i + 2 * j + 1]; pos[o + 2] = 0; nor[o + 2] = 1; }
        else {
          pos[o] = P[3 * v]; pos[o + 1] = P[3 * v + 1]; pos[o + 2] = P[3 * v + 2];
          nor[o] = sn[3 * v]; nor[o + 1] = sn[3 * v + 1]; nor[o + 2] = sn[3 * v + 2];
        }
        if (shape.uv) { uv[6 * i + 2 * j] = shape.uv[6 * i + 2 * j]; uv[6 * i + 2 * j + 1] = shape.uv[6 * i + 2 * j + 1]; }
      }
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    g.setAttribute('normal', new THREE.BufferAttribute(nor, 3));
    g.setAttribute('hypuv', new THREE.BufferAttribute(uv, 2));
    g.setAttribute('color', new THREE.BufferAttribute(faceColours(shape, 'field'), 3));
    g.computeBoundingSphere();
    g.computeBoundingBox();
    return g;
  }

  function vertexPoint(shape, v) {
    var P = shape.positions;
    return new THREE.Vector3(P[3 * v], P[3 * v + 1], P[3 * v + 2]);
  }

  // ---- markers: landmark spheres (unlit, drawn over everything) and their numbers
  function label(text, colour, size) {
    var cv = document.createElement('canvas');
    cv.width = 64; cv.height = 32;
    var ctx = cv.getContext('2d');
    ctx.font = 'bold 26px sans-serif';
    ctx.fillStyle = '#000000';
    ctx.fillText(text, 3, 27);
    ctx.fillStyle = '#' + ('000000' + colour.toString(16)).slice(-6);
    ctx.fillText(text, 1, 25);
    var tex = new THREE.CanvasTexture(cv);
    var sp = new THREE.Sprite(new THREE.SpriteMaterial({ map: tex, depthTest: false, transparent: true }));
    sp.center.set(-0.25, -0.35); // beside the marker, not over it
    sp.scale.set(size * 4, size * 2, 1);
    sp.renderOrder = 20;
    return sp;
  }

  function markerSphere(colour, radius) {
    var m = new THREE.Mesh(new THREE.SphereBufferGeometry(radius, 16, 12),
                           new THREE.MeshBasicMaterial({ color: colour, depthTest: false, transparent: true, opacity: 1 }));
    m.renderOrder = 10; // (transparent: drawn after the dimmed disk and the edges, in this order)
    return m;
  }

  // ---- the views
  var views = [];   // {scene, camera, group, kind: 'surface'|'disk', shapeIndex, mesh, markers: [...], radius}
  var shapes = data.shapes;

  // the fixed camera of every surface: along the first shape's thinnest bounding box axis (from
  // its positive side), the longest of the two others up: the shape seen at its largest
  var axes = null;
  function cameraAxes() {
    if (axes) return axes;
    var P = shapes[0].positions, lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity], i, k;
    for (i = 0; i < P.length; i += 3)
      for (k = 0; k < 3; ++k) { lo[k] = Math.min(lo[k], P[i + k]); hi[k] = Math.max(hi[k], P[i + k]); }
    var ext = [0, 1, 2].map(function (k) { return hi[k] - lo[k]; });
    var order = [0, 1, 2].sort(function (a, b) { return ext[a] - ext[b] || a - b; });
    var unit = function (k) { var v = new THREE.Vector3(); v.setComponent(k, 1); return v; };
    axes = { dir: unit(order[0]), up: unit(order[2]) };
    return axes;
  }

  function addSurfaceView(si) {
    var shape = shapes[si];
    var scene = new THREE.Scene();
    var group = new THREE.Group();
    scene.add(group);
    var tiled = data.kind === 'embedding' && shape.uv && shape.fold; // (genus >= 1: no fold, the colour field)
    var geom = surfaceGeometry(shape, false);
    var mesh = new THREE.Mesh(geom, makeMaterial(tiled ? 1 : 0, true, shape.fold));
    var centre = geom.boundingSphere.center.clone(), radius = geom.boundingSphere.radius;
    mesh.position.copy(centre).multiplyScalar(-1);
    group.add(mesh);
    var view = { scene: scene, group: group, mesh: mesh, kind: 'surface', shapeIndex: si, markers: [], radius: radius,
                 offset: centre, background: BACKGROUND };
    if (shape.cut && shape.cut.length) { // the cut, on the surface
      var cp = new Float32Array(shape.cut.length * 3);
      for (var i = 0; i < shape.cut.length; ++i) cp.set(vertexPoint(shape, shape.cut[i]).sub(centre).toArray(), 3 * i);
      var cg = new THREE.BufferGeometry();
      cg.setAttribute('position', new THREE.BufferAttribute(cp, 3));
      group.add(new THREE.LineSegments(cg, new THREE.LineBasicMaterial({ color: 0xd01010 })));
    }
    var mr = radius * 0.03;
    (shape.landmark_vertices || []).forEach(function (v, i) {
      var colour = markerColour(i);
      var p = vertexPoint(shape, v).sub(centre);
      var s = markerSphere(colour, mr);
      s.position.copy(p);
      group.add(s);
      var l = label(String(shape.landmark_numbers[i]), colour, mr * 1.6);
      l.position.copy(p);
      group.add(l);
      s.renderOrder = 10 + view.markers.length / 1000; // (in the list's order: the self-test knows which covers which)
      view.markers.push({ object: s, colour: colour, number: shape.landmark_numbers[i], vertex: v, radius: mr });
    });
    var camera = new THREE.PerspectiveCamera(35, 1, radius * 0.05, radius * 20);
    var ax = cameraAxes();
    camera.up.copy(ax.up);
    camera.position.copy(ax.dir).multiplyScalar(radius / Math.tan(35 / 2 * Math.PI / 180) * 1.05);
    camera.lookAt(0, 0, 0);
    view.camera = camera;
    view.home = camera.position.clone();
    views.push(view);
    return view;
  }

  function addDiskView(si) {
    var shape = shapes[si];
    var scene = new THREE.Scene();
    var group = new THREE.Group();
    scene.add(group);
    // the whole disk, tiled (dimmed), then the mesh in it
    var circle = new THREE.CircleBufferGeometry(1, 256);
    var cuv = new Float32Array(circle.attributes.position.count * 2);
    for (var i = 0; i < circle.attributes.position.count; ++i) {
      cuv[2 * i] = circle.attributes.position.getX(i) * 0.9999; cuv[2 * i + 1] = circle.attributes.position.getY(i) * 0.9999;
    }
    circle.setAttribute('hypuv', new THREE.BufferAttribute(cuv, 2));
    circle.setAttribute('color', new THREE.BufferAttribute(new Float32Array(circle.attributes.position.count * 3), 3));
    var back = new THREE.Mesh(circle, makeMaterial(1, false, shape.fold));
    back.position.z = -0.01;
    group.add(back);
    var dim = new THREE.Mesh(new THREE.CircleBufferGeometry(1, 256),
                             new THREE.MeshBasicMaterial({ color: 0x000000, transparent: true, opacity: 0.55 }));
    dim.position.z = -0.005;
    group.add(dim);
    var geom = surfaceGeometry(shape, true);
    var mesh = new THREE.Mesh(geom, makeMaterial(shape.fold ? 1 : 0, false, shape.fold));
    group.add(mesh);
    // the mesh's edges in the disk, and the cut (the tile's boundary)
    var F = shape.faces, nf = F.length / 3, ep = new Float32Array(nf * 18), j;
    for (i = 0; i < nf; ++i)
      for (j = 0; j < 3; ++j) {
        var k = (j + 1) % 3, o = 18 * i + 6 * j;
        ep[o] = shape.uv[6 * i + 2 * j]; ep[o + 1] = shape.uv[6 * i + 2 * j + 1]; ep[o + 2] = 0.001;
        ep[o + 3] = shape.uv[6 * i + 2 * k]; ep[o + 4] = shape.uv[6 * i + 2 * k + 1]; ep[o + 5] = 0.001;
      }
    var eg = new THREE.BufferGeometry();
    eg.setAttribute('position', new THREE.BufferAttribute(ep, 3));
    group.add(new THREE.LineSegments(eg, new THREE.LineBasicMaterial({ color: 0x000000, transparent: true, opacity: params.edges === "0" ? 0 : 0.12 })));
    if (shape.cut_uv && shape.cut_uv.length) {
      var cp = new Float32Array(shape.cut_uv.length / 2 * 3);
      for (i = 0; i < shape.cut_uv.length / 2; ++i) { cp[3 * i] = shape.cut_uv[2 * i]; cp[3 * i + 1] = shape.cut_uv[2 * i + 1]; cp[3 * i + 2] = 0.002; }
      var cg = new THREE.BufferGeometry();
      cg.setAttribute('position', new THREE.BufferAttribute(cp, 3));
      group.add(new THREE.LineSegments(cg, new THREE.LineBasicMaterial({ color: 0xd01010 })));
    }
    var ring = [];
    for (i = 0; i <= 256; ++i) ring.push(new THREE.Vector3(Math.cos(i / 128 * Math.PI), Math.sin(i / 128 * Math.PI), 0.003));
    group.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(ring), new THREE.LineBasicMaterial({ color: 0xffffff })));
    var view = { scene: scene, group: group, mesh: mesh, kind: 'disk', shapeIndex: si, markers: [], radius: 1,
                 offset: new THREE.Vector3(0, 0, 0), background: DISK_BACKGROUND };
    var mr = 0.022;
    (shape.landmark_vertices || []).forEach(function (v, li) {
      var colour = markerColour(li), seen = {};
      for (var c = 0; c < F.length; ++c) {
        if (F[c] !== v) continue;
        var key = shape.uv[2 * c].toFixed(6) + ',' + shape.uv[2 * c + 1].toFixed(6);
        if (seen[key]) continue;
        seen[key] = true;
        var s = markerSphere(colour, mr);
        s.position.set(shape.uv[2 * c], shape.uv[2 * c + 1], 0.01);
        group.add(s);
        var l = label(String(shape.landmark_numbers[li]), colour, mr * 1.6);
        l.position.copy(s.position);
        group.add(l);
        s.renderOrder = 10 + view.markers.length / 1000; // (in the list's order: the self-test knows which covers which)
      view.markers.push({ object: s, colour: colour, number: shape.landmark_numbers[li], vertex: v, radius: mr });
      }
    });
    var camera = new THREE.OrthographicCamera(-1.05, 1.05, 1.05, -1.05, -10, 10);
    camera.position.set(0, 0, 5);
    camera.lookAt(0, 0, 0);
    view.camera = camera;
    views.push(view);
    return view;
  }

  var si;
  for (si = 0; si < shapes.length; ++si) addSurfaceView(si);
  if (data.kind === 'embedding' && shapes[0].uv) addDiskView(0);

  // unreliable vertices: points on the source, and their images on the targets
  var unreliablePoints = [];
  function pointsObject(points, colour, size) {
    var g = new THREE.BufferGeometry().setFromPoints(points);
    var o = new THREE.Points(g, new THREE.PointsMaterial({ color: colour, size: size, sizeAttenuation: false }));
    o.renderOrder = 5;
    return o;
  }

  // ---- the map: a point of a shape (face, barycentric coordinates) carried onto another shape
  function findMap(from, to) {
    var ms = data.maps || [];
    for (var i = 0; i < ms.length; ++i) if (ms[i].from === from && ms[i].to === to) return ms[i];
    return null;
  }

  function locationPoint(shape, face, bary) {
    var p = new THREE.Vector3();
    for (var j = 0; j < 3; ++j) p.addScaledVector(vertexPoint(shape, shape.faces[3 * face + j]), bary[j]);
    return p;
  }

  // the barycentric coordinates of the point of face `face` nearest to p
  function baryInFace(shape, face, p) {
    var tri = new THREE.Triangle(vertexPoint(shape, shape.faces[3 * face]), vertexPoint(shape, shape.faces[3 * face + 1]),
                                 vertexPoint(shape, shape.faces[3 * face + 2]));
    var q = new THREE.Vector3();
    tri.closestPointToPoint(p, q);
    var b = new THREE.Vector3();
    tri.getBarycoord(q, b);
    return [b.x, b.y, b.z];
  }

  // the image on map.to of the point (face, bary) of map.from: a vertex goes exactly where the
  // map sends it (MAP.txt's line); another point to the barycentric combination of its face's
  // corners' images (the map is piecewise linear in the orbifold, this is its chord: within a
  // face's size of the surface), located on the face of the corner of largest weight
  function carry(map, face, bary) {
    var from = shapes[map.from], to = shapes[map.to], j, best = 0;
    for (j = 1; j < 3; ++j) if (bary[j] > bary[best]) best = j;
    function image(v) { return { face: map.face[v], bary: [map.bary[3 * v], map.bary[3 * v + 1], map.bary[3 * v + 2]] }; }
    var vb = from.faces[3 * face + best];
    if (bary[best] >= 1 - 1e-12) {
      var im = image(vb);
      return { face: im.face, bary: im.bary, point: locationPoint(to, im.face, im.bary), vertex: vb };
    }
    var p = new THREE.Vector3();
    for (j = 0; j < 3; ++j) {
      var ij = image(from.faces[3 * face + j]);
      p.addScaledVector(locationPoint(to, ij.face, ij.bary), bary[j]);
    }
    var f = image(vb).face;
    return { face: f, bary: baryInFace(to, f, p), point: p };
  }

  // the images of the point (face, bary) of shape s on every other shape (through shape 0 when
  // no map joins the two directly)
  function pickImages(s, face, bary) {
    var out = [];
    for (var t = 0; t < shapes.length; ++t) {
      if (t === s) continue;
      var m = findMap(s, t), r;
      if (m) r = carry(m, face, bary);
      else {
        var m0 = findMap(s, 0), m1 = findMap(0, t);
        if (!m0 || !m1) continue;
        var r0 = carry(m0, face, bary);
        r = carry(m1, r0.face, r0.bary);
      }
      out.push({ shape: t, face: r.face, bary: r.bary, point: r.point.toArray() });
    }
    return out;
  }

  var pickMarkers = [];
  function showPick(s, face, bary) {
    pickMarkers.forEach(function (m) { m.parent.remove(m); });
    pickMarkers = [];
    var images = pickImages(s, face, bary);
    var at = [{ shape: s, point: locationPoint(shapes[s], face, bary) }];
    images.forEach(function (im) { at.push({ shape: im.shape, point: new THREE.Vector3().fromArray(im.point) }); });
    at.forEach(function (a) {
      views.forEach(function (v) {
        if (v.kind !== 'surface' || v.shapeIndex !== a.shape) return;
        var m = markerSphere(0xffffff, v.radius * 0.02);
        m.renderOrder = 9; // (under the landmarks' markers)
        m.position.copy(a.point).sub(v.offset);
        v.group.add(m);
        pickMarkers.push(m);
      });
    });
    var txt = 'picked shape ' + s + ' face ' + face + ' (' + bary.map(function (x) { return x.toFixed(3); }).join(' ') + ')';
    images.forEach(function (im) { txt += '\n -> shape ' + im.shape + ' face ' + im.face + ' (' + im.bary.map(function (x) { return x.toFixed(3); }).join(' ') + ')'; });
    document.getElementById('info').textContent = txt;
    return images;
  }

  // picks vertex v of the first shape (a corner of its first face: barycentric coordinates 1, 0, 0)
  function pickVertex(v) {
    var A = shapes[0], f = -1, c;
    for (c = 0; c < A.faces.length; ++c) if (A.faces[c] === v) { f = Math.floor(c / 3); break; }
    if (f < 0) return { shape: 0, vertex: v, images: [], error: 'vertex on no face' };
    var bary = [0, 0, 0];
    bary[c % 3] = 1;
    return { shape: 0, vertex: v, face: f, images: showPick(0, f, bary) };
  }

  // ---- layout and rendering
  var renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: !selftest, preserveDrawingBuffer: true });
  } catch (e) {
    document.getElementById('info').textContent = 'This page needs WebGL, which this browser does not offer: ' + e;
    report({ ok: false, webgl: false, errors: errors.length + 1, error_messages: errors.concat([String(e)]) });
    return;
  }
  renderer.setPixelRatio(selftest ? 1 : (window.devicePixelRatio || 1));
  renderer.autoClear = false;
  document.body.appendChild(renderer.domElement);
  var gl = renderer.getContext();

  function rects() {
    var W = window.innerWidth, H = window.innerHeight, n = views.length, w = Math.floor(W / n);
    return views.map(function (v, i) { return { x: i * w, y: 0, w: w, h: H }; });
  }

  function render() {
    var W = window.innerWidth, H = window.innerHeight;
    renderer.setSize(W, H);
    renderer.setScissorTest(true);
    var rs = rects(), names = document.getElementById('names');
    names.innerHTML = '';
    views.forEach(function (v, i) {
      var r = rs[i];
      renderer.setViewport(r.x, r.y, r.w, r.h);
      renderer.setScissor(r.x, r.y, r.w, r.h);
      renderer.setClearColor(v.background, 1);
      renderer.clear();
      var aspect = r.w / r.h;
      if (v.camera.isPerspectiveCamera) {
        v.camera.aspect = aspect;
        // a view narrower than tall (several shapes side by side) widens its vertical angle, so
        // that the shape fits across it as it fits in height
        v.camera.fov = aspect >= 1 ? 35 : 2 * Math.atan(Math.tan(35 / 2 * Math.PI / 180) / aspect) * 180 / Math.PI;
      } else { var s = 1.05; v.camera.left = -s * Math.max(aspect, 1); v.camera.right = s * Math.max(aspect, 1);
             v.camera.top = s / Math.min(aspect, 1); v.camera.bottom = -s / Math.min(aspect, 1); }
      v.camera.updateProjectionMatrix();
      renderer.render(v.scene, v.camera);
      var d = document.createElement('div');
      d.style.left = r.x + 'px'; d.style.width = r.w + 'px';
      d.textContent = shapes[v.shapeIndex].name + (v.kind === 'disk' ? ' (Poincare disk)' : '');
      names.appendChild(d);
    });
    renderer.setScissorTest(false);
  }

  // ---- controls: drag rotates every surface alike, the wheel zooms, a click picks
  var mode = 'field';
  function setColouring(what) {
    mode = what;
    views.forEach(function (v) {
      if (v.kind !== 'surface' || data.kind === 'embedding') return;
      var shape = shapes[v.shapeIndex];
      if (what !== 'field' && !shape.distortion) return;
      v.mesh.geometry.attributes.color.array.set(faceColours(shape, what));
      v.mesh.geometry.attributes.color.needsUpdate = true;
    });
    render();
  }
  var showUnreliable = true;
  function buildUnreliable() {
    unreliablePoints.forEach(function (o) { o.parent.remove(o); });
    unreliablePoints = [];
    if (!showUnreliable) return;
    (data.maps || []).forEach(function (m) {
      if (!m.unreliable || !m.unreliable.length) return;
      views.forEach(function (v) {
        if (v.kind !== 'surface') return;
        var pts = [];
        if (v.shapeIndex === m.from) m.unreliable.forEach(function (u) { pts.push(vertexPoint(shapes[m.from], u).sub(v.offset)); });
        else if (v.shapeIndex === m.to) m.unreliable.forEach(function (u) {
          pts.push(locationPoint(shapes[m.to], m.face[u], [m.bary[3 * u], m.bary[3 * u + 1], m.bary[3 * u + 2]]).sub(v.offset));
        });
        else return;
        var o = pointsObject(pts, 0xff00ff, 3);
        v.group.add(o);
        unreliablePoints.push(o);
      });
    });
  }
  buildUnreliable();

  var bar = document.getElementById('bar');
  function button(text, f) {
    var b = document.createElement('button');
    b.textContent = text;
    b.onclick = f;
    bar.appendChild(b);
  }
  var title = document.createElement('span');
  title.className = 'title';
  title.textContent = data.title || data.kind;
  bar.appendChild(title);
  var anyDistortion = shapes.some(function (s) { return s.distortion; });
  if (data.kind !== 'embedding') {
    button('colour field', function () { setColouring('field'); });
    if (anyDistortion) {
      button('conformal distortion', function () { setColouring('conformal'); });
      button('area distortion', function () { setColouring('area'); });
    }
    if ((data.maps || []).some(function (m) { return m.unreliable && m.unreliable.length; }))
      button('unreliable on/off', function () { showUnreliable = !showUnreliable; buildUnreliable(); render(); });
  }
  button('reset view', function () {
    views.forEach(function (v) { v.group.quaternion.set(0, 0, 0, 1); if (v.home) v.camera.position.copy(v.home); });
    render();
  });
  var help = document.createElement('span');
  help.textContent = data.kind === 'embedding' ? '  drag: rotate, wheel: zoom' :
    '  drag: rotate, wheel: zoom, click: a point and its image' + (shapes.length > 2 ? 's' : '') +
    (anyDistortion ? '; distortion: blue 1 .. red 1.5 (area: 1/2 .. 2)' : '');
  bar.appendChild(help);

  function viewAt(x, y) {
    var rs = rects();
    for (var i = 0; i < views.length; ++i) {
      var r = rs[i];
      if (x >= r.x && x < r.x + r.w) return { view: views[i], ndc: new THREE.Vector2(2 * (x - r.x) / r.w - 1, 1 - 2 * y / r.h) };
    }
    return null;
  }
  var drag = null;
  renderer.domElement.addEventListener('mousedown', function (e) { drag = { x: e.clientX, y: e.clientY, moved: false }; });
  window.addEventListener('mousemove', function (e) {
    if (!drag) return;
    var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    if (Math.abs(dx) + Math.abs(dy) < 2) return;
    drag.moved = true; drag.x = e.clientX; drag.y = e.clientY;
    var q = new THREE.Quaternion().setFromEuler(new THREE.Euler(dy * 0.01, dx * 0.01, 0));
    views.forEach(function (v) { if (v.kind === 'surface') v.group.quaternion.premultiply(q); });
    render();
  });
  window.addEventListener('mouseup', function (e) {
    if (drag && !drag.moved) {
      var hit = viewAt(e.clientX, e.clientY);
      if (hit && hit.view.kind === 'surface' && data.kind !== 'embedding') {
        var rc = new THREE.Raycaster();
        rc.setFromCamera(hit.ndc, hit.view.camera);
        var is = rc.intersectObject(hit.view.mesh);
        if (is.length) {
          var f = is[0].faceIndex, shape = shapes[hit.view.shapeIndex];
          var local = hit.view.mesh.worldToLocal(is[0].point.clone());
          showPick(hit.view.shapeIndex, f, baryInFace(shape, f, local));
          render();
        }
      }
    }
    drag = null;
  });
  renderer.domElement.addEventListener('wheel', function (e) {
    e.preventDefault();
    var k = e.deltaY > 0 ? 1.1 : 1 / 1.1;
    views.forEach(function (v) { if (v.kind === 'surface') v.camera.position.multiplyScalar(k); else v.camera.zoom /= k; });
    render();
  }, { passive: false });
  window.addEventListener('resize', render);

  // ---- the self-test: index.html?selftest=1[&pick=I]
  var frame = null; // the drawing buffer, read once (readPixels stalls the GPU)
  function pixel(x, y) { // (x, y) in CSS pixels from the top left (pixel ratio 1)
    var W = gl.drawingBufferWidth, H = gl.drawingBufferHeight;
    if (!frame) {
      frame = new Uint8Array(W * H * 4);
      gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, frame);
    }
    var px = Math.min(W - 1, Math.max(0, Math.round(x))), py = Math.min(H - 1, Math.max(0, H - 1 - Math.round(y)));
    var o = 4 * (py * W + px);
    return [frame[o], frame[o + 1], frame[o + 2]];
  }
  function rgb(c) { return [(c >> 16) & 255, (c >> 8) & 255, c & 255]; }

  function selfTest() {
    var out = { ok: false, webgl: !!gl, renderer: gl ? String(gl.getParameter(gl.VERSION)) : null, kind: data.kind,
                views: [], landmarks: [], errors: 0, error_messages: [] };
    if (params.pick !== undefined && shapes.length > 1) // pick=I or I,J,...: each vertex picked in turn
      out.picks = params.pick.split(',').map(function (v) { return pickVertex(parseInt(v, 10)); });
    render();
    out.width = gl.drawingBufferWidth;
    out.height = gl.drawingBufferHeight;
    var rs = rects();
    views.forEach(function (v, i) {
      var r = rs[i], seen = {}, n = 0, other = 0;
      for (var y = 0; y < 24; ++y)
        for (var x = 0; x < 24; ++x) {
          var p = pixel(r.x + (x + 0.5) * r.w / 24, r.y + (y + 0.5) * r.h / 24);
          var key = p.join(',');
          if (!seen[key]) { seen[key] = 1; ++n; }
          if (key !== rgb(v.background).join(',')) ++other;
        }
      var magenta = 0; // the unreliable vertices' points (0xff00ff, drawn unlit)
      for (var yy = 0; yy < r.h; ++yy)
        for (var xx = r.x; xx < r.x + r.w; ++xx) {
          var q = pixel(xx, yy);
          if (q[0] === 255 && q[1] === 0 && q[2] === 255) ++magenta;
        }
      out.views.push({ shape: v.shapeIndex, kind: v.kind, distinct_colours: n, covered_fraction: other / 576, magenta_pixels: magenta });
      v.scene.updateMatrixWorld(true);
      var screen = v.markers.map(function (m) {
        var p = m.object.getWorldPosition(new THREE.Vector3()).project(v.camera);
        var rim = m.object.getWorldPosition(new THREE.Vector3()).add(new THREE.Vector3(0, m.radius, 0).applyQuaternion(v.camera.quaternion)).project(v.camera);
        var sx = r.x + (p.x + 1) / 2 * r.w, sy = r.y + (1 - p.y) / 2 * r.h;
        var ry = Math.abs((rim.y - p.y) / 2 * r.h);
        return { x: sx, y: sy, r: ry };
      });
      v.markers.forEach(function (m, k) {
        var s = screen[k], covered = false;
        for (var l = 0; l < v.markers.length; ++l) {
          if (l === k) continue;
          var o = screen[l], d = Math.sqrt((o.x - s.x) * (o.x - s.x) + (o.y - s.y) * (o.y - s.y));
          if (l > k && d < o.r + 2) covered = true; // a marker drawn later
          // any marker's number (drawn over all markers): the sprite's box beside it, 6.4 r by 3.2 r
          if (s.x > o.x + 1.6 * o.r - 2 && s.x < o.x + 8 * o.r + 2 && s.y > o.y - 4.32 * o.r - 2 && s.y < o.y - 1.12 * o.r + 2) covered = true;
        }
        var inside = s.x >= r.x && s.x < r.x + r.w && s.y >= 0 && s.y < r.h;
        var found = inside ? pixel(s.x, s.y) : null, want = rgb(m.colour);
        var match = !!found && Math.abs(found[0] - want[0]) <= 2 && Math.abs(found[1] - want[1]) <= 2 && Math.abs(found[2] - want[2]) <= 2;
        out.landmarks.push({ view: i, kind: v.kind, shape: v.shapeIndex, number: m.number, vertex: m.vertex, x: Math.round(s.x * 10) / 10,
                             y: Math.round(s.y * 10) / 10, radius_px: Math.round(s.r * 10) / 10, expected: want, found: found,
                             covered: covered, match: match });
      });
    });
    out.errors = errors.length;
    out.error_messages = errors.slice(0, 5);
    var uncovered = out.landmarks.filter(function (l) { return !l.covered; });
    out.ok = out.webgl && errors.length === 0 && uncovered.length > 0 && uncovered.every(function (l) { return l.match; });
    report(out);
  }

  if (selftest) {
    try { selfTest(); } catch (e) { errors.push(String(e && e.stack || e)); report({ ok: false, errors: errors.length, error_messages: errors }); }
  } else {
    if (params.pick !== undefined && shapes.length > 1) pickVertex(parseInt(params.pick.split(',')[0], 10));
    if (params.colouring === 'conformal' || params.colouring === 'area') setColouring(params.colouring);
    render();
  }
})();
