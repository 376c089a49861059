#version 330 core
// Blinn-Phong illumination, per fragment in camera coordinates. Phong's
// equation with the specular term built on the half vector H instead of the
// reflected ray R:
//
//   I = Ia*ka + sum_i f_att,i * (Id,i*kd*max(0, N.L_i) + Is,i*ks*max(0, N.H_i)^n')
//   H = normalize(L + V),   f_att = min(1 / (c1 + c2*d + c3*d^2), 1)
//
// Why n' = 4n: the angle between N and H is about half the angle between R
// and V, so for the same exponent the Blinn highlight is about twice as wide.
// Near the peak cos(a)^n ~ exp(-n a^2 / 2); with a(R,V) ~ 2 a(N,H) the two
// highlights match when n' = 4n. The material's `shininess` stays n (the
// docks edit one value for every method); the factor is applied here. It is
// a uniform so the Uniforms dock offers it: 4 (the default, and what the CPU
// reference and `phonglab bench` use) is the matched exponent, 1 puts Phong's
// n in unchanged and shows the highlight twice as wide.
//
// As in phong.frag, where N.L <= 0 the light is behind the surface and adds
// no specular term either.

const int MAX_LIGHTS = 8;

in vec3 positionCam;
in vec3 normalCam;

uniform mat4 viewMatrix;                  // world -> camera, for the lights

uniform vec3 Ia;                          // ambient intensity
uniform vec3 ka;                          // ambient reflection
uniform vec3 kd;                          // diffuse reflection
uniform vec3 ks;                          // specular reflection
uniform float shininess;                  // n (Phong's exponent)
uniform float exponentFactor = 4.0;       // n' = factor * n; 4 matches Phong  @range 1 8 @step 0.5

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
    float exponent = exponentFactor * shininess;

    vec3 I = Ia * ka;
    for (int i = 0; i < lightCount; ++i) {
        vec3 lightCam = (viewMatrix * vec4(lightPosition[i], 1.0)).xyz; // a point: w = 1
        vec3 toLight = lightCam - positionCam;
        float d = length(toLight);
        vec3 L = toLight / d;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0)
            continue;
        // Halfway between the directions to the light and to the eye: the
        // normal a mirror facet would need to reflect the light into the eye.
        // No reflect() needed, which is why Blinn proposed it.
        vec3 H = normalize(L + V);
        float NdotH = max(0.0, dot(N, H));
        vec3 c = attenuation[i];
        float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
        I += fatt * (Id[i] * kd * NdotL + Is[i] * ks * pow(NdotH, exponent));
    }
    fragColor = vec4(clamp(I, 0.0, 1.0), 1.0);    // alpha added here
}
