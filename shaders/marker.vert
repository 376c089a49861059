#version 330 core
// Light markers: small unlit spheres drawn at each light's world position.
layout(location = 0) in vec3 position;
uniform mat4 mvpMatrix;
void main()
{
    gl_Position = mvpMatrix * vec4(position, 1.0);
}
