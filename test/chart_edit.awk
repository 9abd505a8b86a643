# Edits an OBJ embedding that embed wrote with charts around cone images ('# hot chart' and
# '# hot vtc' lines) into a wrong one, for test_cli_certify.sh (charts): read the file twice,
#   awk -v mode=MODE [-v depth=D] -f chart_edit.awk e.obj e.obj > wrong.obj
# MODE:
#   flip    two neighbouring vts of a face deep in a chart (|w| < depth, each its vertex's only
#           vt, not a cone) swap their chart points and their vt lines: faces turn over
#   seam    a vt deep in a chart (|w| < depth) of a vertex with two vts (one side of a seam)
#           moves by 1e-9 of its distance to the origin, along it: its vt line stays right
#   vt      the vt line of the shallowest chart point off the origin moves by 1e-9: no longer
#           its chart point's tile point
#   b       chart 0's b turns by 1e-6 radians (|b| kept, so the chart stays normalized): its
#           origin leaves its tile corner
#   corner  chart 0 is said to be centred at tile corner (its corner + 1) mod 2 ... (another)
#   cone    the chart point at the origin (the cone) moves to (1e-30, 0)
# The edited vt's (or chart's) number is written on standard error.
NR == FNR {
  if($1 == "vt") nvt++
  if($1 == "#" && $2 == "hot" && $3 == "vtc") { ch[$4] = 1; r[$4] = sqrt($6 * $6 + $7 * $7) }
  if($1 == "f") {
    nf++
    for(i = 2; i <= 4; i++) {
      split($i, a, "/"); c[i] = a[2]
      if(!((a[1] " " a[2]) in seen)) { seen[a[1] " " a[2]]; cnt[a[1]]++ }
      vof[a[2]] = a[1]
    }
    F[nf] = c[2] " " c[3] " " c[4]
  }
  next
}
FNR == 1 {
  if(mode == "flip" || mode == "seam") {
    for(k = 1; k <= nf && !ta; k++) {
      split(F[k], t, " ")
      if(mode == "flip") {
        if(ch[t[1]] && ch[t[2]] && ch[t[3]] && r[t[1]] < depth && r[t[2]] < depth && r[t[1]] > 0 && r[t[2]] > 0 &&
           cnt[vof[t[1]]] == 1 && cnt[vof[t[2]]] == 1) { ta = t[1]; tb = t[2] }
      } else {
        for(j = 1; j <= 3 && !ta; j++)
          if(ch[t[j]] && r[t[j]] < depth && r[t[j]] > 0 && cnt[vof[t[j]]] == 2) ta = t[j]
      }
    }
  } else if(mode == "vt") {
    for(k in r) if(r[k] > 0 && (!ta || r[k] > r[ta])) ta = k
  }
  if((mode == "flip" || mode == "seam" || mode == "vt") && !ta) { print "chart_edit.awk: nothing to edit" > "/dev/stderr"; exit 1 }
  if(ta) print "vt " ta " (|w| " r[ta] ")" (tb ? " and vt " tb " (|w| " r[tb] ")" : "") > "/dev/stderr"
}
{ line[FNR] = $0; if($1 == "vt") vt[++n] = FNR; if($1 == "#" && $2 == "hot" && $3 == "vtc") vtc[$4] = FNR; if($1 == "#" && $2 == "hot" && $3 == "chart" && $4 == 0) chart0 = FNR }
END {
  if(mode == "flip") {
    l = line[vt[ta]]; line[vt[ta]] = line[vt[tb]]; line[vt[tb]] = l
    split(line[vtc[ta]], A, " "); split(line[vtc[tb]], B, " ")
    line[vtc[ta]] = "# hot vtc " ta " " A[5] " " B[6] " " B[7]; line[vtc[tb]] = "# hot vtc " tb " " B[5] " " A[6] " " A[7]
  } else if(mode == "seam") {
    split(line[vtc[ta]], A, " ")
    line[vtc[ta]] = sprintf("# hot vtc %d %d %.17g %.17g", ta, A[5], A[6] * (1 + 1e-9), A[7] * (1 + 1e-9))
  } else if(mode == "vt") {
    split(line[vt[ta]], A, " ")
    line[vt[ta]] = sprintf("vt %.17g %.17g", A[2] + 1e-9, A[3])
  } else if(mode == "b") {
    split(line[chart0], A, " "); ang = 1e-6
    line[chart0] = sprintf("# hot chart 0 %.17g %.17g %.17g %.17g %d", A[5], A[6], A[7] * cos(ang) - A[8] * sin(ang), A[7] * sin(ang) + A[8] * cos(ang), A[9])
  } else if(mode == "corner") {
    split(line[chart0], A, " ")
    line[chart0] = sprintf("# hot chart 0 %s %s %s %s %d", A[5], A[6], A[7], A[8], A[9] == 0 ? 1 : A[9] - 1)
  } else if(mode == "cone") {
    for(k in vtc) { split(line[vtc[k]], A, " "); if(A[6] == 0 && A[7] == 0) { line[vtc[k]] = "# hot vtc " k " " A[5] " 1e-30 0"; done = 1 } }
    if(!done) { print "chart_edit.awk: no chart point at the origin" > "/dev/stderr"; exit 1 }
  }
  for(i = 1; i <= FNR; i++) print line[i]
}
