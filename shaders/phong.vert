#version 330 core
// Phong shading, vertex stage: carries position and normal into camera
// coordinates; the illumination equation runs per fragment (phong.frag).

layout(location = 0) in vec3 position; // object coordinates
layout(location = 1) in vec3 normal;   // object coordinates, from the VBO

uniform mat4 modelViewMatrix;   // object -> camera
uniform mat3 normalMatrix;      // inverse transpose of modelViewMatrix's upper 3x3
uniform mat4 projectionMatrix;  // camera -> clip

out vec3 positionCam;
out vec3 normalCam;

void main()
{
    vec4 p = modelViewMatrix * vec4(position, 1.0); // a point: w = 1
    positionCam = p.xyz;
    // Normals are directions that must stay perpendicular to the surface:
    // the inverse transpose does that under non-uniform scale, the
    // model-view matrix itself does not.
    normalCam = normalMatrix * normal;
    gl_Position = projectionMatrix * p;
}
