# Bends an OFF mesh along its z axis into a circular arc of radius R (default 10) in the
# x-z plane, keeping the triangulation and the vertex order (a target with a known ground
# truth: vertex i of the bent mesh corresponds to vertex i of the input):
#   awk -v R=12 -f bend.awk capsule.off > bent.off
# The axis point (0, 0, z) goes to the point of arc length z along the arc that leaves the
# origin in direction +z and turns towards +x around the centre (R, 0, 0) (angle t = z / R);
# the offset (x, y) from the axis becomes x times the arc's unit normal (cos t, 0, -sin t),
# which points to the centre, plus y. The map is smooth and one-to-one where x < R; it
# bends the axis without stretching it (a tube keeps its length and its radius).
# Comments and blank lines are dropped; faces are copied as they are.
BEGIN { if(R == "") R = 10; if(R + 0 <= 0) { print "bend.awk: R must be positive" > "/dev/stderr"; exit 2 } }
/^[ \t]*#/ || /^[ \t]*$/ { next }
stage == 0 {
  stage = 1; print "OFF"
  if($1 == "OFF" && NF == 1) next
  sub(/^OFF[ \t]*/, "")
}
stage == 1 { nv = $1 + 0; print; stage = (nv > 0) ? 2 : 3; next }
stage == 2 {
  x = $1; y = $2; z = $3; t = z / R; c = cos(t); s = sin(t)
  # centre line R (1 - cos t), R sin t; normal (cos t, 0, -sin t)
  printf "%.17g %.17g %.17g\n", R * (1 - c) + x * c, y, R * s - x * s
  if(++k == nv) stage = 3
  next
}
{ print }
