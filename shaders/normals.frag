#version 330 core
// Normals view: no lighting, the unit camera-space normal N shown as a
// colour. Each component lies in [-1, 1]; 0.5*N + 0.5 maps it to [0, 1]:
//
//   red   = x: right (1) .. left (0)
//   green = y: up (1)    .. down (0)
//   blue  = z: towards the eye (1) .. away (0)
//
// A surface facing the camera is light blue (0.5, 0.5, 1). Useful to check
// normals: wrong-way normals, bad smoothing and a wrong normal matrix are
// visible at a glance. The lighting uniforms are not declared: nothing here
// reads them, and setting a uniform the program lacks is a no-op.

in vec3 normalCam;

out vec4 fragColor;

void main()
{
    vec3 N = normalize(normalCam);   // interpolation shortens it: renormalise
    fragColor = vec4(0.5 * N + 0.5, 1.0);
}
