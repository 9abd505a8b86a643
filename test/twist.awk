# Twists an OFF mesh about its z axis: the point (x, y, z) turns about the axis by the angle
# T z (T radians per unit of z, default 1), keeping the triangulation and the vertex order (a
# target with a known ground truth: vertex i of the twisted mesh corresponds to vertex i of the
# input). A smooth one-to-one map of space, so the twisted mesh has the input's topology:
#   awk -v T=1.5 -f twist.awk eight.off > eight-twisted.off
# Comments and blank lines are dropped; faces are copied as they are.
BEGIN { if(T == "") T = 1 }
/^[ \t]*#/ || /^[ \t]*$/ { next }
stage == 0 {
  stage = 1; print "OFF"
  if($1 == "OFF" && NF == 1) next
  sub(/^OFF[ \t]*/, "")
}
stage == 1 { nv = $1 + 0; print; stage = (nv > 0) ? 2 : 3; next }
stage == 2 {
  a = T * $3; c = cos(a); s = sin(a)
  printf "%.17g %.17g %.17g\n", c * $1 - s * $2, s * $1 + c * $2, $3
  if(--nv == 0) stage = 3
  next
}
{ print }
