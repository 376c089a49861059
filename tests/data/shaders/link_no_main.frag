#version 330 core
// Compiles on its own (a stage may be split over several shaders) but cannot
// link: no shader of the fragment stage defines main().
out vec4 fragColor;
void shade()
{
    fragColor = vec4(1.0);
}
