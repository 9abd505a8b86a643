# read_off(FILE, P, F): the vertices (P[i, 0..2]) and triangles (F[j, 0..2]) of an OFF file,
# returns the number of vertices. Loaded before the scripts that use it:
#   awk -f off_reader.awk -f map_error.awk ...    awk -f off_reader.awk -f round_trip.awk ...
function read_off(file, P, F,    line, stage, k, m, t, nv) {
  stage = 0; k = 0; m = 0
  while((getline line < file) > 0) {
    if(line ~ /^[ \t]*#/ || line ~ /^[ \t]*$/) continue
    split(line, t, " ")
    if(stage == 0) { stage = 1; if(t[1] == "OFF" && length(t) == 1) continue; sub(/^OFF[ \t]*/, "", line); split(line, t, " ") }
    if(stage == 1) { nv = t[1]; stage = 2; continue }
    if(stage == 2) { P[k, 0] = t[1]; P[k, 1] = t[2]; P[k, 2] = t[3]; k++; if(k == nv) stage = 3; continue }
    F[m, 0] = t[2]; F[m, 1] = t[3]; F[m, 2] = t[4]; m++
  }
  close(file)
  return k
}
