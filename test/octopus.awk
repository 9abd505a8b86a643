# An octopus-like closed mesh: a sphere of radius 1 (latitude-longitude grid, 48 x 24) with
# eight tentacles, tubes of radius about 0.3 closed by hemispheres, of lengths L * (0.5 to 1),
# each grown from a square block of 4 x 4 grid cells (its boundary, 16 vertices, is the
# tube's first ring), four around the upper latitudes and four around the lower ones.
# OFF mesh on standard output; on standard error, 18 landmarks: every tentacle's base (a
# vertex of its first ring) and tip, and the two poles.
#   awk -v L=25 -f octopus.awk > octopus.off 2> octopus.cones
# With -v FINE=f (an integer, default 1), the same shape with f times as many vertices along
# every grid line and around every tentacle (f^2 times as many vertices in all).
# With -v TWIRL=b, every point is turned about the z axis by b times its distance to the axis
# (the same triangulation and vertex order: a bent copy, whose vertex i corresponds to vertex i).
# Used by test_cli.sh (map_octopus) and test_maps.cpp.
function vid(i, j) { return 1 + (i - 1) * NLON + ((j % NLON) + NLON) % NLON }  # grid vertex (rings 1..NLAT-1)
function emit(x, y, z,    r, t, c, s) {
  if(TWIRL != 0) { r = sqrt(x * x + y * y); t = TWIRL * r; c = cos(t); s = sin(t); PX[NV] = c * x - s * y; PY[NV] = s * x + c * y }
  else { PX[NV] = x; PY[NV] = y }
  PZ[NV] = z
  return NV++
}
function face(a, b, c) { FA[NFACE] = a; FB[NFACE] = b; FC[NFACE] = c; NFACE++ }
# a, b, c counterclockwise seen from outside when (b - a) x (c - a) . (a - centre) > 0
function oriented(a, b, c, cx, cy, cz,    ux, uy, uz, vx, vy, vz, nx, ny, nz) {
  ux = QX[b] - QX[a]; uy = QY[b] - QY[a]; uz = QZ[b] - QZ[a]
  vx = QX[c] - QX[a]; vy = QY[c] - QY[a]; vz = QZ[c] - QZ[a]
  nx = uy * vz - uz * vy; ny = uz * vx - ux * vz; nz = ux * vy - uy * vx
  return nx * (QX[a] - cx) + ny * (QY[a] - cy) + nz * (QZ[a] - cz) > 0
}
function tri(a, b, c, cx, cy, cz) { if(oriented(a, b, c, cx, cy, cz)) face(a, b, c); else face(a, c, b) }
BEGIN {
  if(L == "") L = 25
  if(FINE == "") FINE = 1
  pi = atan2(0, -1); NLON = 48 * FINE; NLAT = 24 * FINE; A = 4 * FINE; NV = 0; NFACE = 0
  # grid points (untwirled copies in QX, QY, QZ for the orientation tests)
  north = NV; QX[NV] = 0; QY[NV] = 0; QZ[NV] = 1; emit(0, 0, 1)
  for(i = 1; i < NLAT; i++) for(j = 0; j < NLON; j++) {
    th = pi * i / NLAT; ph = 2 * pi * j / NLON
    QX[NV] = sin(th) * cos(ph); QY[NV] = sin(th) * sin(ph); QZ[NV] = cos(th); emit(QX[NV], QY[NV], QZ[NV])
  }
  south = NV; QX[NV] = 0; QY[NV] = 0; QZ[NV] = -1; emit(0, 0, -1)
  # the blocks: rows i0 (cells i0..i0+A-1), columns j0
  nt = 0
  for(r = 0; r < 2; r++) for(q = 0; q < 4; q++) {
    I0[nt] = FINE * ((r == 0) ? 6 : 14); J0[nt] = FINE * (12 * q + 6 * r); LEN[nt] = L * (0.5 + 0.5 * ((3 * nt) % 8) / 7); nt++
  }
  for(t = 0; t < nt; t++) for(i = I0[t]; i < I0[t] + A; i++) for(j = J0[t]; j < J0[t] + A; j++) HOLE[i, (j + NLON) % NLON] = 1
  # the sphere's faces: polar fans and grid cells, minus the blocks
  for(j = 0; j < NLON; j++) { tri(north, vid(1, j), vid(1, j + 1), 0, 0, 0); tri(south, vid(NLAT - 1, j), vid(NLAT - 1, j + 1), 0, 0, 0) }
  for(i = 1; i < NLAT - 1; i++) for(j = 0; j < NLON; j++) {
    if(HOLE[i, j]) continue
    tri(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), 0, 0, 0); tri(vid(i, j), vid(i + 1, j + 1), vid(i, j + 1), 0, 0, 0)
  }
  for(t = 0; t < nt; t++) {
    # the block's boundary loop (4A vertices), its centre and axis
    n = 0
    for(j = J0[t]; j < J0[t] + A; j++) R0[n++] = vid(I0[t], j)
    for(i = I0[t]; i < I0[t] + A; i++) R0[n++] = vid(i, J0[t] + A)
    for(j = J0[t] + A; j > J0[t]; j--) R0[n++] = vid(I0[t] + A, j)
    for(i = I0[t] + A; i > I0[t]; i--) R0[n++] = vid(i, J0[t])
    th = pi * (I0[t] + A / 2) / NLAT; ph = 2 * pi * (J0[t] + A / 2) / NLON
    ax = sin(th) * cos(ph); ay = sin(th) * sin(ph); az = cos(th)
    # an orthonormal basis (e1, e2) of the plane across the axis
    e1x = -sin(ph); e1y = cos(ph); e1z = 0
    e2x = ay * e1z - az * e1y; e2y = az * e1x - ax * e1z; e2z = ax * e1y - ay * e1x
    rho = 0; for(k = 0; k < n; k++) { v = R0[k]; dx = QX[v] - ax; dy = QY[v] - ay; dz = QZ[v] - az; rho += sqrt(dx * dx + dy * dy + dz * dz) / n }
    for(k = 0; k < n; k++) { v = R0[k]; ANG[k] = atan2((QX[v] - ax) * e2x + (QY[v] - ay) * e2y + (QZ[v] - az) * e2z, (QX[v] - ax) * e1x + (QY[v] - ay) * e1y + (QZ[v] - az) * e1z) }
    h = 2 * pi * rho / n; nc = int(LEN[t] / h + 0.5); nh = int((pi / 2) * rho / h + 0.5)
    for(k = 0; k < n; k++) PREV[k] = R0[k]
    base[t] = R0[0]
    for(s = 1; s <= nc + nh - 1; s++) {
      if(s <= nc) { off = LEN[t] * s / nc; rr = rho }
      else { a = (s - nc) * (pi / 2) / nh; off = LEN[t] + rho * sin(a); rr = rho * cos(a) }
      cx = ax * (1 + off); cy = ay * (1 + off); cz = az * (1 + off)
      for(k = 0; k < n; k++) {
        x = cx + rr * (cos(ANG[k]) * e1x + sin(ANG[k]) * e2x); y = cy + rr * (cos(ANG[k]) * e1y + sin(ANG[k]) * e2y); z = cz + rr * (cos(ANG[k]) * e1z + sin(ANG[k]) * e2z)
        QX[NV] = x; QY[NV] = y; QZ[NV] = z; CUR[k] = emit(x, y, z)
      }
      for(k = 0; k < n; k++) {
        k1 = (k + 1) % n
        tri(PREV[k], PREV[k1], CUR[k1], cx - ax * h, cy - ay * h, cz - az * h); tri(PREV[k], CUR[k1], CUR[k], cx - ax * h, cy - ay * h, cz - az * h)
      }
      for(k = 0; k < n; k++) PREV[k] = CUR[k]
    }
    off = LEN[t] + rho; QX[NV] = ax * (1 + off); QY[NV] = ay * (1 + off); QZ[NV] = az * (1 + off)
    tip[t] = emit(QX[NV], QY[NV], QZ[NV])
    for(k = 0; k < n; k++) tri(tip[t], PREV[k], PREV[(k + 1) % n], ax * (1 + LEN[t]), ay * (1 + LEN[t]), az * (1 + LEN[t]))
  }
  # the grid vertices inside the blocks are on no face: numbered out
  for(f = 0; f < NFACE; f++) { USED[FA[f]] = 1; USED[FB[f]] = 1; USED[FC[f]] = 1 }
  m = 0; for(v = 0; v < NV; v++) if(USED[v]) NEW[v] = m++
  print "OFF"; print m, NFACE, 0
  for(v = 0; v < NV; v++) if(USED[v]) printf "%.17g %.17g %.17g\n", PX[v], PY[v], PZ[v]
  for(f = 0; f < NFACE; f++) print 3, NEW[FA[f]], NEW[FB[f]], NEW[FC[f]]
  line = NEW[north] " " NEW[south]; for(t = 0; t < nt; t++) line = line " " NEW[base[t]] " " NEW[tip[t]]
  print line > "/dev/stderr"
}
