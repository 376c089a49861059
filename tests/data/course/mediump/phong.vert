// A student's Phong shader as a WebGL 1 course writes it (GLSL ES 1.00: no
// #version line, attribute/varying). GLSL ES 1.00 has no inverse(), so the
// normal matrix comes in as a uniform.

precision mediump float;      // both stages: a uniform they share must agree

attribute vec3 a_position;
attribute vec3 a_normal;

uniform mat4 u_model;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform mat3 u_normalMatrix;   // inverse transpose of the model-view matrix

varying vec3 v_position;       // camera coordinates
varying vec3 v_normal;

void main()
{
    vec4 p = u_view * u_model * vec4(a_position, 1.0);
    v_position = p.xyz;
    v_normal = u_normalMatrix * a_normal;
    gl_Position = u_projection * p;
}
