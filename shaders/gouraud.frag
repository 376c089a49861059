#version 330 core
// Gouraud shading, fragment stage: the lighting already happened per vertex
// (gouraud.vert); here arrives the colour the rasteriser interpolated
// (perspective-correct) between the triangle's three vertex colours.

in vec3 intensity;

out vec4 fragColor;

void main()
{
    // Not clamped here: the 8-bit target clamps to [0, 1] as it stores the
    // pixel, and a float target keeps a NaN or an infinity visible.
    fragColor = vec4(intensity, 1.0);    // alpha added here
}
