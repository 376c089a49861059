#version 300 es
precision highp float;
struct L { vec3 c; float k[2]; };
uniform vec3 tint, beacon;
uniform float gloss, gain;
uniform int lamps;
uniform mat4 uA, uB;
in vec3 pos, nrm;
out vec4 o;
vec3 g[2];
void f(out L l) { l.c = vec3(1.0); }
void main() {
  vec3 acc; float a[3]; L l; f(l);
  for (int i = 0; i < lamps; i++) { vec3 Lv = normalize(beacon - pos); acc += tint * gain * max(dot(nrm, Lv), 0.0) + pow(max(dot(reflect(-Lv, nrm), -pos), 0.0), gloss); }
  o = vec4(acc + g[0], 1.0);
}
