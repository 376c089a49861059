#version 330 core
// A fragment shader with exactly one error, on line 17 column 9 (the
// undeclared identifier `undeclaredThing`). Used to check that diagnostics
// land on the line the user wrote.

in vec3 positionCam;
in vec3 normalCam;

uniform vec3 kd;

out vec4 fragColor;

void main()
{
    vec3 N = normalize(normalCam);
    float x = dot(N, vec3(0.0, 0.0, 1.0));
    x = undeclaredThing * x;
    fragColor = vec4(kd * x, 1.0);
}
