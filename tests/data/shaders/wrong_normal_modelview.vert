#version 330 core
// DELIBERATELY WRONG: transforms normals with the model-view matrix instead of
// its inverse transpose. Under non-uniform scale the normals tilt; the render
// test must catch this.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 modelViewMatrix;
uniform mat3 normalMatrix;
uniform mat4 projectionMatrix;
out vec3 positionCam;
out vec3 normalCam;
void main()
{
    vec4 p = modelViewMatrix * vec4(position, 1.0);
    positionCam = p.xyz;
    normalCam = mat3(modelViewMatrix) * normal;
    gl_Position = projectionMatrix * p;
}
