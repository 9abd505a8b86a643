# Adds a handle to an OFF triangle mesh as fused limbs do: face `face` and the face nearest to
# it (centroid distance) among those farther than `min_rings` edges from it are removed and
# their boundaries joined by a tube of six triangles. The vertices are kept (the same numbers:
# the identity is the ground truth), the genus grows by one:
#   awk -v face=F -v min_rings=K [-v stats=FILE] -f add_handle.awk IN.off > OUT.off
# stats receives "faces F G distance D" (D: between the two centroids).
BEGIN { k = 0; m = 0 }
/^[ \t]*#/ || NF == 0 { next }
stage == 0 { stage = 1; if($1 == "OFF" && NF == 1) next; sub(/^OFF/, "") }
stage == 1 { nv = $1; stage = 2; next }
stage == 2 { x[k] = $1; y[k] = $2; z[k] = $3; k++; if(k == nv) stage = 3; next }
stage == 3 { a[m] = $2; b[m] = $3; c[m] = $4; m++ }
function cx(j) { return (x[a[j]] + x[b[j]] + x[c[j]]) / 3 }
function cy(j) { return (y[a[j]] + y[b[j]] + y[c[j]]) / 3 }
function cz(j) { return (z[a[j]] + z[b[j]] + z[c[j]]) / 3 }
END {
  near[a[face]] = 1; near[b[face]] = 1; near[c[face]] = 1
  for(r = 0; r < min_rings; ++r) {
    delete add
    for(j = 0; j < m; ++j)
      if((a[j] in near) || (b[j] in near) || (c[j] in near)) { add[a[j]] = 1; add[b[j]] = 1; add[c[j]] = 1 }
    for(v in add) near[v] = 1
  }
  best = -1
  for(j = 0; j < m; ++j) {
    if((a[j] in near) || (b[j] in near) || (c[j] in near)) continue
    d = (cx(j) - cx(face))^2 + (cy(j) - cy(face))^2 + (cz(j) - cz(face))^2
    if(best < 0 || d < bd) { best = j; bd = d }
  }
  if(best < 0) { print "add_handle.awk: no face beyond " min_rings " rings" > "/dev/stderr"; exit 1 }
  # a <-> e, b <-> d, c <-> f: every new edge has its two sides in opposite directions
  A = a[face]; B = b[face]; C = c[face]; D = a[best]; E = b[best]; F = c[best]
  print "OFF"; print nv, m - 2 + 6, 0
  for(i = 0; i < nv; ++i) print x[i], y[i], z[i]
  for(j = 0; j < m; ++j) if(j != face && j != best) print 3, a[j], b[j], c[j]
  print 3, A, B, D; print 3, A, D, E; print 3, B, C, F; print 3, B, F, D; print 3, C, A, E; print 3, C, E, F
  if(stats != "") printf "faces %d %d distance %.6g\n", face, best, sqrt(bd) > stats
}
