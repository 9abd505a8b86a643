# The edge distance (rings) of every vertex of an OFF triangle mesh from vertex `from` (or
# from the nearest of several, comma-separated); prints the vertices at exactly `rings` edges,
# one per line (none if there is none), or with -v farthest=1 the vertex farthest from them
# and its distance ("V D"):
#   awk -v from=V[,V...] -v rings=R -f ring_distance.awk IN.off
#   awk -v from=V[,V...] -v farthest=1 -f ring_distance.awk IN.off
/^[ \t]*#/ || NF == 0 { next }
stage == 0 { stage = 1; if($1 == "OFF" && NF == 1) next; sub(/^OFF/, "") }
stage == 1 { nv = $1; stage = 2; next }
stage == 2 { if(++k == nv) stage = 3; next }
stage == 3 { for(i = 2; i <= 4; ++i) { u = $i; v = $(i == 4 ? 2 : i + 1); adj[u] = adj[u] " " v; adj[v] = adj[v] " " u } }
END {
  n = split(from, sources, ",")
  for(i = 1; i <= n; ++i) { d[sources[i]] = 0; front[sources[i]] = 1 }
  if(farthest) rings = nv
  for(r = 1; r <= rings && length(front) > 0; ++r) {
    delete next_front
    for(u in front) { n = split(adj[u], t, " "); for(i = 1; i <= n; ++i) if(!(t[i] in d)) { d[t[i]] = r; next_front[t[i]] = 1 } }
    delete front; for(u in next_front) front[u] = 1
  }
  if(farthest) { best = sources[1]; for(v in d) if(d[v] > d[best] || (d[v] == d[best] && v + 0 < best + 0)) best = v; print best, d[best]; exit }
  for(v in d) if(d[v] == rings) print v
}
