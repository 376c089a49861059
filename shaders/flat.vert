#version 330 core
// Flat shading: Phong's illumination equation evaluated once per FACE, at a
// representative point of the face (its centroid) with the face's own
// normal, in camera coordinates. The rasteriser paints the whole triangle
// with that one colour: a `flat` output takes its value from the triangle's
// provoking vertex (the last one, GL's default convention) and is not
// interpolated.
//
//   I = Ia*ka + sum_i f_att,i * (Id,i*kd*max(0, N.L_i) + Is,i*ks*max(0, R_i.V)^n)
//   f_att = min(1 / (c1 + c2*d + c3*d^2), 1)
//
// Same rule as phong.frag: where N.L <= 0 there is no specular term either.
//
// Reading a `facePoint` attribute makes the renderer draw this program from
// the mesh's face layout (GpuMesh.h), where every triangle has a provoking
// vertex of its own carrying the face's normal (in `normal`) and centroid (in
// `facePoint`). A vertex provokes at most one triangle, so the equation runs
// about once per face: the cheapest of the methods, and the coarsest.

const int MAX_LIGHTS = 8;

layout(location = 0) in vec3 position;  // object coordinates
layout(location = 1) in vec3 normal;    // the face normal (object coordinates) on a provoking vertex
layout(location = 2) in vec3 facePoint; // the face's centroid (object coordinates) on the same

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

// Unclamped, as in gouraud.vert: clamping is part of writing the pixel.
flat out vec3 intensity;

void main()
{
    vec3 positionCam = (modelViewMatrix * vec4(facePoint, 1.0)).xyz; // a point: w = 1
    // A face normal is a normal like any other: the inverse transpose keeps
    // it perpendicular to the face under non-uniform scale.
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
    gl_Position = projectionMatrix * (modelViewMatrix * vec4(position, 1.0));
}
