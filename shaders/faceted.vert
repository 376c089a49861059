#version 330 core
// Faceted shading, vertex stage: passes the camera-space position on.
// Faceted shading takes its normal from the triangle itself (faceted.frag),
// so the vertex normals are not used; `normal` and `normalMatrix` are declared
// only so every method reads the same inputs as phong.vert.

layout(location = 0) in vec3 position; // object coordinates
layout(location = 1) in vec3 normal;   // object coordinates; unused here

uniform mat4 modelViewMatrix;   // object -> camera
uniform mat3 normalMatrix;      // unused here: no vertex normals to carry
uniform mat4 projectionMatrix;  // camera -> clip

out vec3 positionCam;

void main()
{
    vec4 p = modelViewMatrix * vec4(position, 1.0); // a point: w = 1
    positionCam = p.xyz;
    gl_Position = projectionMatrix * p;
}
