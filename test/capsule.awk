# A capsule: a tube of radius 1 and length L with S segments per ring, closed by
# hemispheres, as an OFF mesh on standard output; on standard error, four landmarks
# around a ring of the bottom hemisphere (a fifth at the bottom pole: vertex 0).
#   awk -v L=50 -v S=24 -f capsule.awk > tube.off 2> tube.cones
# Used by test_cli.sh (embed_recentre) and scripts/same_bits.sh.
BEGIN {
  pi = atan2(0, -1); h = 2 * pi / S; nh = int((pi / 2) / h + 0.5); nc = int(L / h + 0.5); R = 0
  for(i = 1; i <= nh; i++) { a = -pi / 2 + i * (pi / 2) / nh; rz[R] = sin(a); rr[R++] = cos(a) }
  for(i = 1; i <= nc; i++) { rz[R] = L * i / nc; rr[R++] = 1 }
  for(i = 1; i < nh; i++) { a = i * (pi / 2) / nh; rz[R] = L + sin(a); rr[R++] = cos(a) }
  nv = 2 + R * S; nf = 2 * S + 2 * S * (R - 1)
  print "OFF"; print nv, nf, 0; print 0, 0, -1
  for(k = 0; k < R; k++) for(j = 0; j < S; j++) { t = 2 * pi * (j + 0.5 * (k % 2)) / S; printf "%.17g %.17g %.17g\n", rr[k] * cos(t), rr[k] * sin(t), rz[k] }
  print 0, 0, L + 1
  for(j = 0; j < S; j++) print 3, 0, 1 + (j + 1) % S, 1 + j
  for(k = 0; k + 1 < R; k++) for(j = 0; j < S; j++) {
    a0 = 1 + k * S + j; a1 = 1 + k * S + (j + 1) % S; b0 = 1 + (k + 1) * S + j; b1 = 1 + (k + 1) * S + (j + 1) % S
    if(k % 2 == 0) { print 3, a0, a1, b0; print 3, a1, b1, b0 } else { print 3, a0, a1, b1; print 3, a0, b1, b0 }
  }
  for(j = 0; j < S; j++) print 3, nv - 1, 1 + (R - 1) * S + j, 1 + (R - 1) * S + (j + 1) % S
  q = int(nh / 3); printf "0 %d %d %d %d\n", 1 + q * S, 1 + q * S + S / 4, 1 + q * S + S / 2, 1 + q * S + 3 * S / 4 > "/dev/stderr"

}
