# Subdivides a triangle OFF mesh once at its edges' midpoints (each triangle into four), keeping
# the input's vertices first and in their order (landmark files of vertex indices stay valid),
# then one new vertex per edge:
#   awk -f off_reader.awk -f midpoint_subdivide.awk mesh.off > finer.off
# The surface is the same (every new vertex lies on its edge); a source of n vertices and f
# faces gets about n + 3f/2 vertices and 4f faces.
BEGIN {
  if(ARGC != 2) { print "usage: awk -f off_reader.awk -f midpoint_subdivide.awk mesh.off" > "/dev/stderr"; exit 2 }
  nv = read_off(ARGV[1], P, F)
  nf = 0
  while((nf, 0) in F) nf++
  n = nv
  for(j = 0; j < nf; j++)
    for(k = 0; k < 3; k++) {
      a = F[j, k] + 0; b = F[j, (k + 1) % 3] + 0
      e = a < b ? a " " b : b " " a
      if(!(e in mid)) {
        mid[e] = n
        for(c = 0; c < 3; c++) P[n, c] = (P[a, c] + P[b, c]) / 2
        n++
      }
      M[j, k] = mid[e] # the midpoint of edge k (corners k, k + 1)
    }
  print "OFF"
  print n, 4 * nf, 0
  for(i = 0; i < n; i++) printf "%.17g %.17g %.17g\n", P[i, 0], P[i, 1], P[i, 2]
  for(j = 0; j < nf; j++) {
    print 3, F[j, 0], M[j, 0], M[j, 2]
    print 3, M[j, 0], F[j, 1], M[j, 1]
    print 3, M[j, 2], M[j, 1], F[j, 2]
    print 3, M[j, 0], M[j, 1], M[j, 2]
  }
  exit 0
}
