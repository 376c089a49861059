#version 300 es
// A student's Phong shader as a WebGL 2 course writes it: its own names,
// given the model and the view matrix, making the normal matrix itself.
// PhongLab binds every name by what it says (phonglab check --help).

in vec3 aPosition;              // object coordinates
in vec3 aNormal;                // object coordinates

uniform mat4 uModelMatrix;      // object -> world
uniform mat4 uViewMatrix;       // world -> camera
uniform mat4 uProjectionMatrix; // camera -> clip

out vec3 vPositionCam;
out vec3 vNormalCam;

void main()
{
    mat4 modelView = uViewMatrix * uModelMatrix;
    vec4 p = modelView * vec4(aPosition, 1.0);       // a point: w = 1
    vPositionCam = p.xyz;
    // N' = (T^T)^-1 * N: the inverse transpose keeps normals perpendicular.
    mat3 normalMatrix = transpose(inverse(mat3(modelView)));
    vNormalCam = normalMatrix * aNormal;
    gl_Position = uProjectionMatrix * p;
}
