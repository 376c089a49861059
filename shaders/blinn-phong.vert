#version 330 core
// Blinn-Phong shading, vertex stage: identical to phong.vert. Only the
// specular term differs (blinn-phong.frag); position and normal still reach
// the fragment stage in camera coordinates.

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
    // The inverse transpose keeps normals perpendicular under non-uniform scale.
    normalCam = normalMatrix * normal;
    gl_Position = projectionMatrix * p;
}
