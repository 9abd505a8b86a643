# Gives an OFF triangle mesh the defects of a scan, keeping its vertex numbers, so that the
# identity is the ground truth between the clean mesh and the defective copy:
#   awk -v openings=C:R,C:R -v debris=K [-v stats=FILE] -f scan_defects.awk IN.off > OUT.off
# openings: for each centre vertex C, the faces with a vertex within R-1 edges of C are
#   removed (an opening whose rim is about R edges from C; its inner vertices stay, on no face);
# debris: K stray triangles, each a small triangle (a thousandth of the bounding box diagonal)
#   beside an input vertex, with 3 new vertices appended after the input's;
# stats: receives "removed_faces N removed_area_fraction A debris_vertices D".
BEGIN { if(debris == "") debris = 0; k = 0; m = 0 }
/^[ \t]*#/ || NF == 0 { next }
stage == 0 { stage = 1; if($1 == "OFF" && NF == 1) next; sub(/^OFF/, "") }
stage == 1 { nv = $1; nf = $2; stage = 2; next }
stage == 2 { x[k] = $1; y[k] = $2; z[k] = $3; k++; if(k == nv) stage = 3; next }
stage == 3 { a[m] = $2; b[m] = $3; c[m] = $4; m++; next }
function area(j,    ux, uy, uz, vx, vy, vz, cx, cy, cz) {
  ux = x[b[j]] - x[a[j]]; uy = y[b[j]] - y[a[j]]; uz = z[b[j]] - z[a[j]]
  vx = x[c[j]] - x[a[j]]; vy = y[c[j]] - y[a[j]]; vz = z[c[j]] - z[a[j]]
  cx = uy * vz - uz * vy; cy = uz * vx - ux * vz; cz = ux * vy - uy * vx
  return sqrt(cx * cx + cy * cy + cz * cz) / 2
}
END {
  n = split(openings, o, ",")
  for(i = 1; i <= n; ++i) {
    split(o[i], cr, ":")
    delete near; near[cr[1]] = 1
    for(r = 1; r < cr[2]; ++r) { # grow by one ring
      delete add
      for(j = 0; j < m; ++j)
        if((a[j] in near) || (b[j] in near) || (c[j] in near)) { add[a[j]] = 1; add[b[j]] = 1; add[c[j]] = 1 }
      for(v in add) near[v] = 1
    }
    for(j = 0; j < m; ++j)
      if((a[j] in near) || (b[j] in near) || (c[j] in near)) removed[j] = 1
  }
  lo_x = hi_x = x[0]; lo_y = hi_y = y[0]; lo_z = hi_z = z[0]
  for(i = 1; i < nv; ++i) {
    if(x[i] < lo_x) lo_x = x[i]; if(x[i] > hi_x) hi_x = x[i]
    if(y[i] < lo_y) lo_y = y[i]; if(y[i] > hi_y) hi_y = y[i]
    if(z[i] < lo_z) lo_z = z[i]; if(z[i] > hi_z) hi_z = z[i]
  }
  s = sqrt((hi_x - lo_x)^2 + (hi_y - lo_y)^2 + (hi_z - lo_z)^2) / 1000
  total = 0; gone = 0; kept = 0
  for(j = 0; j < m; ++j) { w = area(j); total += w; if(j in removed) gone += w; else kept++ }
  print "OFF"; print nv + 3 * debris, kept + debris, 0
  for(i = 0; i < nv; ++i) print x[i], y[i], z[i]
  for(d = 0; d < debris; ++d) { # beside vertex i, a little off the surface
    i = int((d + 0.5) * nv / debris)
    print x[i] + 2 * s, y[i] + 2 * s, z[i] + 2 * s
    print x[i] + 3 * s, y[i] + 2 * s, z[i] + 2 * s
    print x[i] + 2 * s, y[i] + 3 * s, z[i] + 2 * s
  }
  for(j = 0; j < m; ++j) if(!(j in removed)) print 3, a[j], b[j], c[j]
  for(d = 0; d < debris; ++d) print 3, nv + 3 * d, nv + 3 * d + 1, nv + 3 * d + 2
  if(stats != "") printf "removed_faces %d removed_area_fraction %.6f debris_vertices %d\n", m - kept, gone / total, 3 * debris > stats
}
