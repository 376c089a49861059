# The class the grade benchmarks grade, sourced by scripts/bench-grade.sh
# and scripts/bench-grade-moodle.sh so that both grade the same mistakes.
#
#   bench_student_fragment I FRAG AMBIENT OUT
#       student I's fragment shader, written to OUT from the correct FRAG: a
#       quarter each correct, reflect(L, N), L not normalised, and the
#       ambient term (AMBIENT: the shader's own Ia·ka) added once per light.
bench_student_fragment() {
  local i="$1" frag="$2" ambient="$3" out="$4"
  case $((i % 4)) in
    0) cp "$frag" "$out" ;;
    1) sed 's/reflect(-L, N)/reflect(L, N)/' "$frag" > "$out" ;;
    2) sed 's|vec3 L = toLight / d;|vec3 L = toLight;|' "$frag" > "$out" ;;
    3) sed "s|I += fatt \\* (|I += $ambient + fatt * (|" "$frag" > "$out" ;;
  esac
}
