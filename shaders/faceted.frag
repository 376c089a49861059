#version 330 core
// Faceted shading: Phong's illumination equation per fragment with ONE
// normal per triangle, the geometric face normal. It is the plane of the
// triangle, found from how the camera-space position changes between
// neighbouring pixels:
//
//   N = normalize(cross(dFdx(p), dFdy(p)))
//
// dFdx(p) and dFdy(p) both lie in the triangle's plane, so their cross
// product is perpendicular to it. This ignores the mesh's vertex normals
// entirely: a smooth sphere looks faceted, a box looks exactly right.
// L and V are still evaluated per fragment (the light and the eye are at a
// finite distance), so a face is not one uniform colour, but every pixel of
// it uses the same normal. It costs what Phong costs; flat.vert/.frag is the
// classic flat shading that evaluates the equation once per face.
//
//   I = Ia*ka + sum_i f_att,i * (Id,i*kd*max(0, N.L_i) + Is,i*ks*max(0, R_i.V)^n)
//   f_att = min(1 / (c1 + c2*d + c3*d^2), 1)
//
// Same rule as phong.frag: where N.L <= 0 there is no specular term either.

const int MAX_LIGHTS = 8;

in vec3 positionCam;

uniform mat4 viewMatrix;                  // world -> camera, for the lights

uniform vec3 Ia;                          // ambient intensity
uniform vec3 ka;                          // ambient reflection
uniform vec3 kd;                          // diffuse reflection
uniform vec3 ks;                          // specular reflection
uniform float shininess;                  // n

uniform int lightCount;
uniform vec3 lightPosition[MAX_LIGHTS];   // world coordinates
uniform vec3 Id[MAX_LIGHTS];              // diffuse intensity
uniform vec3 Is[MAX_LIGHTS];              // specular intensity
uniform vec3 attenuation[MAX_LIGHTS];     // c1, c2, c3

out vec4 fragColor;

void main()
{
    // Window x and y grow right and up, like camera x and y, so this normal
    // always points towards the eye. A back face's outward normal points
    // away from it: flip there, as the vertex normals of a closed mesh would.
    vec3 N = normalize(cross(dFdx(positionCam), dFdy(positionCam)));
    if (!gl_FrontFacing)
        N = -N;
    vec3 V = normalize(-positionCam);     // towards the eye at the origin

    vec3 I = Ia * ka;
    for (int i = 0; i < lightCount; ++i) {
        vec3 lightCam = (viewMatrix * vec4(lightPosition[i], 1.0)).xyz; // a point: w = 1
        vec3 toLight = lightCam - positionCam;
        float d = length(toLight);
        vec3 L = toLight / d;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0)
            continue;
        vec3 R = reflect(-L, N);          // reflect() takes the incident vector -L
        float RdotV = max(0.0, dot(R, V));
        vec3 c = attenuation[i];
        float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
        I += fatt * (Id[i] * kd * NdotL + Is[i] * ks * pow(RdotV, shininess));
    }
    // Not clamped here: the 8-bit target clamps to [0, 1] as it stores the
    // pixel, and a float target keeps a NaN or an infinity visible.
    fragColor = vec4(I, 1.0);    // alpha added here
}
