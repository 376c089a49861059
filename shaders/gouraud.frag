#version 330 core
// Gouraud shading, fragment stage: the lighting already happened per vertex
// (gouraud.vert); here arrives the colour the rasteriser interpolated
// (perspective-correct) between the triangle's three vertex colours.

in vec3 intensity;

out vec4 fragColor;

void main()
{
    fragColor = vec4(clamp(intensity, 0.0, 1.0), 1.0);    // alpha added here
}
