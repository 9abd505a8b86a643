# Punches holes into an OFF triangle mesh: removes every face with a vertex within `rings`
# edges of one of the centre vertices (comma-separated 0-based indices). The vertices are all
# kept, in order (the centres become isolated), so vertex numbers stay those of the input.
#   awk -v centres=10,200 -v rings=1 -f punch_holes.awk IN.off > OUT.off
BEGIN { n = split(centres, c, ","); for(i = 1; i <= n; ++i) near[c[i]] = 1; if(rings == "") rings = 1 }
/^[ \t]*#/ || NF == 0 { next }
stage == 0 { stage = 1; if($1 == "OFF" && NF == 1) next; sub(/^OFF/, "") }
stage == 1 { nv = $1; nf = $2; stage = 2; next }
stage == 2 { v[k++] = $0; if(k == nv) stage = 3; next }
stage == 3 { f[m++] = $0; next }
END {
  for(r = 1; r < rings; ++r) { # grow the set of centre vertices by one ring
    delete add
    for(j = 0; j < m; ++j) {
      split(f[j], t, " "); hit = 0
      for(a = 2; a <= t[1] + 1; ++a) if(t[a] in near) hit = 1
      if(hit) for(a = 2; a <= t[1] + 1; ++a) add[t[a]] = 1
    }
    for(x in add) near[x] = 1
  }
  kept = 0
  for(j = 0; j < m; ++j) {
    split(f[j], t, " "); hit = 0
    for(a = 2; a <= t[1] + 1; ++a) if(t[a] in near) hit = 1
    if(!hit) keep[kept++] = f[j]
  }
  print "OFF"; print nv, kept, 0
  for(i = 0; i < nv; ++i) print v[i]
  for(j = 0; j < kept; ++j) print keep[j]
}
