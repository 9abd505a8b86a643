# Sourced by test_cli.sh and test_cli_faults.sh, which set $data (the data folder), $tmp (a
# scratch folder) and fail():
#   make_hands LETTERS...: $tmp/hand_<letter>.off, smooth deformations of hand.off (the same
#     triangulation), one per letter of b c e f g
#   same_files DIR1 DIR2: the same file names and the same bytes, report.json apart from its times
make_hands() {
  local src="$data/meshes/hand.off" d
  local nv; nv=$(awk 'NR==2 {print $1}' "$src")
  for d in "$@"; do
    awk -v n="$nv" -v d="$d" 'NR<=2 || NF==0 {print; next}
      NF==3 && c<n { x=$1; y=$2; z=$3; c++;
        if(d=="b") { x=x+0.1*sin(3*y); z=1.2*z } else if(d=="c") { x=0.9*x; y=y+0.05*cos(4*x) }
        else if(d=="e") { y=1.1*y; z=z+0.05*sin(2*x) } else if(d=="f") { z=z+0.04*sin(3*x) } else if(d=="g") { x=1.05*x+0.03*cos(2*z) }
        printf "%.9g %.9g %.9g\n", x, y, z; next } {print}' "$src" > "$tmp/hand_$d.off"
  done
}

same_files() {
  [ "$(cd "$1" && ls -A)" = "$(cd "$2" && ls -A)" ] || fail "other files: $(cd "$1" && ls -A | tr '\n' ' ') / $(cd "$2" && ls -A | tr '\n' ' ')"
  local f
  for f in "$1"/*; do
    if [ "$(basename "$f")" = report.json ]; then
      local times='s/"(embedding_seconds|map_seconds|seconds|seconds_certificate)": [0-9.e+-]+/"\1": T/g'
      diff <(sed -E "$times" "$f") <(sed -E "$times" "$2/report.json") >/dev/null || fail "report.json differs beyond its times"
    else
      cmp -s "$f" "$2/$(basename "$f")" || fail "$(basename "$f") differs"
    fi
  done
}
