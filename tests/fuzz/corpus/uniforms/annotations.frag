#version 330 core
uniform float gain;          // @range 0 2 @step 0.05
uniform vec3 tint, glow[2];  // @color
uniform int mode[3];         // @range 0 4
uniform mat4 m; /* uniform float hidden; */
// uniform float commented;
uniform bool enabled; // @range 1 0 @step -1
uniform vec2 offset[N]; // @step 1e-3 @range -1e9 1e9
layout(location = 0) uniform highp float precise; // @color @range
#if 0
uniform float inIfZero;
#endif
out vec4 color;
void main() { color = vec4(tint * gain, 1.0); }
