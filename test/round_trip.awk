# Round trip of two maps between meshes A and B against the identity on A:
#   awk -f off_reader.awk -f round_trip.awk A_to_B.map.txt B_to_A.map.txt A.off B.off
# A_to_B: one line 'face b0 b1 b2' per vertex of A, faces of B; B_to_A likewise per vertex of B.
# Each vertex v of A goes to the point sum_j b_j B[c_j] of B; that point comes back as the same
# combination of the images on A of B's corners c_j; prints "round trip max E mean M" relative
# to A's bounding box diagonal (a map and its inverse: 0 up to interpolation).
function read_map(file, M,    line, t, i) {
  i = 0
  while((getline line < file) > 0) { split(line, t, " "); M[i, 0] = t[1]; M[i, 1] = t[2]; M[i, 2] = t[3]; M[i, 3] = t[4]; i++ }
  close(file)
  return i
}
BEGIN {
  na = read_off(ARGV[3], PA, FA); nb = read_off(ARGV[4], PB, FB)
  read_map(ARGV[1], AB); read_map(ARGV[2], BA)
  for(d = 0; d < 3; d++) { lo[d] = 1e300; hi[d] = -1e300 }
  for(v = 0; v < na; v++) for(d = 0; d < 3; d++) { if(PA[v, d] < lo[d]) lo[d] = PA[v, d]; if(PA[v, d] > hi[d]) hi[d] = PA[v, d] }
  diag = sqrt((hi[0] - lo[0])^2 + (hi[1] - lo[1])^2 + (hi[2] - lo[2])^2)
  # the image on A of every vertex of B
  for(u = 0; u < nb; u++) { f = BA[u, 0]; for(d = 0; d < 3; d++) { G[u, d] = 0; for(j = 0; j < 3; j++) G[u, d] += BA[u, j + 1] * PA[FA[f, j], d] } }
  mx = 0; sum = 0
  for(v = 0; v < na; v++) {
    f = AB[v, 0]; e = 0
    for(d = 0; d < 3; d++) { r = 0; for(j = 0; j < 3; j++) r += AB[v, j + 1] * G[FB[f, j], d]; e += (r - PA[v, d])^2 }
    e = sqrt(e) / diag; sum += e; if(e > mx) mx = e
  }
  printf "round trip max %.6f mean %.6f\n", mx, sum / na
  exit
}
