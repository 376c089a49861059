#version 330 core
// Flat shading, fragment stage: the lighting already happened once for the
// whole face (flat.vert); every pixel of the triangle gets that one colour,
// taken from the provoking vertex without interpolation.

flat in vec3 intensity;

out vec4 fragColor;

void main()
{
    // Not clamped here: the 8-bit target clamps to [0, 1] as it stores the
    // pixel, and a float target keeps a NaN or an infinity visible.
    fragColor = vec4(intensity, 1.0);    // alpha added here
}
