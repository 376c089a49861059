#version 330 core
// Gouraud shading: Phong's illumination equation evaluated once per VERTEX
// in camera coordinates; the rasteriser then interpolates the resulting
// colour across each triangle (gouraud.frag only writes it out).
//
//   I = Ia*ka + sum_i f_att,i * (Id,i*kd*max(0, N.L_i) + Is,i*ks*max(0, R_i.V)^n)
//   f_att = min(1 / (c1 + c2*d + c3*d^2), 1)
//
// Same rule as phong.frag: where N.L <= 0 there is no specular term either.
//
// Cheap (one evaluation per vertex, not per pixel), and exact at the
// vertices, but a highlight that falls between vertices is smeared or lost:
// a colour that is linear across a triangle cannot peak inside it.

const int MAX_LIGHTS = 8;

layout(location = 0) in vec3 position; // object coordinates
layout(location = 1) in vec3 normal;   // object coordinates, from the VBO

uniform mat4 modelViewMatrix;   // object -> camera
uniform mat3 normalMatrix;      // inverse transpose of modelViewMatrix's upper 3x3
uniform mat4 projectionMatrix;  // camera -> clip
uniform mat4 viewMatrix;        // world -> camera, for the lights

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

// Unclamped: clamping is part of writing the pixel (gouraud.frag), so the
// only difference from Phong is where the equation is evaluated.
out vec3 intensity;

void main()
{
    vec4 p = modelViewMatrix * vec4(position, 1.0); // a point: w = 1
    vec3 positionCam = p.xyz;
    // The inverse transpose keeps normals perpendicular under non-uniform scale.
    vec3 N = normalize(normalMatrix * normal);
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
    intensity = I;
    gl_Position = projectionMatrix * p;
}
