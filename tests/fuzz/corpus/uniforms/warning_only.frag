#version 330 core
// Compiles, with a warning from Mesa: `unusedThing` is used uninitialised.
in vec3 positionCam;
in vec3 normalCam;
out vec4 fragColor;
void main()
{
    float unusedThing;
    fragColor = vec4(normalize(normalCam) * unusedThing, 1.0);
}
