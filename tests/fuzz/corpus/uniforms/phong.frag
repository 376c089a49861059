#version 330 core
// Phong illumination, evaluated per fragment in camera coordinates:
//
//   I = Ia*ka + sum_i f_att,i * (Id,i*kd*max(0, N.L_i) + Is,i*ks*max(0, R_i.V)^n)
//   f_att = min(1 / (c1 + c2*d + c3*d^2), 1)
//
// One deliberate addition: where N.L <= 0 the light is behind the surface
// and adds no specular term either; otherwise R.V can be positive for light
// hitting the back and paint a highlight on the unlit side.

const int MAX_LIGHTS = 8;

in vec3 positionCam;
in vec3 normalCam;

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
    // Directions, not points: normalised vec3 (w = 0 implied).
    vec3 N = normalize(normalCam);
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
    fragColor = vec4(clamp(I, 0.0, 1.0), 1.0);    // alpha added here
}
