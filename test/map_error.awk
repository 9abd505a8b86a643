# Error of a map against the identity correspondence (source vertex i <-> truth vertex i):
#   awk -f off_reader.awk -f map_error.awk MAP.txt TARGET.off TRUTH.off
# MAP.txt: one line 'face b0 b1 b2' per source vertex ('-1 ...': no image, counted apart);
# TARGET.off: the mesh whose faces MAP.txt refers to; TRUTH.off: the mesh whose vertex i is the
# true image of source vertex i. Prints "mapped N unmapped U max E mean M" with E and M
# relative to the bounding box diagonal of TRUTH.off. With -v per_vertex=FILE, FILE receives
# "i e" per mapped source vertex i (e: its error in diagonals).
BEGIN {
  map = ARGV[1]; target = ARGV[2]; truth = ARGV[3]; ARGC = 1
  read_off(target, TP, TF)
  nt = read_off(truth, GP, GF)
  for(i = 0; i < nt; ++i) for(d = 0; d < 3; ++d) {
    if(i == 0 || GP[i, d] < lo[d]) lo[d] = GP[i, d]
    if(i == 0 || GP[i, d] > hi[d]) hi[d] = GP[i, d]
  }
  diag = sqrt((hi[0] - lo[0])^2 + (hi[1] - lo[1])^2 + (hi[2] - lo[2])^2)
  i = 0; mapped = 0; unmapped = 0; max = 0; sum = 0
  while((getline line < map) > 0) {
    split(line, t, " ")
    if(t[1] < 0) { unmapped++; i++; continue }
    if(i < nt) {
      e2 = 0
      for(d = 0; d < 3; ++d) {
        x = t[2] * TP[TF[t[1], 0], d] + t[3] * TP[TF[t[1], 1], d] + t[4] * TP[TF[t[1], 2], d]
        e2 += (x - GP[i, d])^2
      }
      e = sqrt(e2) / diag; sum += e; mapped++; if(e > max) max = e
      if(per_vertex != "") printf "%d %.9g\n", i, e > per_vertex
    }
    i++
  }
  printf "mapped %d unmapped %d max %.6f mean %.6f\n", mapped, unmapped, max, (mapped ? sum / mapped : 0)
}
