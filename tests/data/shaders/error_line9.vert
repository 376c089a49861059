#version 330 core
// A vertex shader whose only error is on line 9: a vec3 assigned to a float.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
void main()
{
    float wrong = position;
    gl_Position = projectionMatrix * modelViewMatrix * vec4(position, wrong);
}
