#version 300 es
// A course that hands the light's parts over in one mat3, its columns Ia,
// Id and Is (one light): the illumination equation per fragment, in camera
// coordinates:
//   I = Ia*ka + sum_i f_att,i * (Id,i*kd*max(0, N.L_i) + Is,i*ks*max(0, R_i.V)^n)
//   f_att = min(1 / (c1 + c2*d + c3*d^2), 1)
precision highp float;

const int MAX_LIGHTS = 4;

in vec3 vPositionCam;
in vec3 vNormalCam;

uniform mat4 uViewMatrix;
uniform int uNumLights;
uniform vec3 uLightPosition[MAX_LIGHTS]; // world coordinates
uniform vec3 uAttenuation[MAX_LIGHTS];   // c1, c2, c3

uniform mat3 uLamp;                      // columns: Ia, Id, Is
uniform vec3 uKa;
uniform vec3 uKd;
uniform vec3 uKs;
uniform float uShininess;                // n

out vec4 outColor;

void main()
{
    vec3 N = normalize(vNormalCam);
    vec3 V = normalize(-vPositionCam);     // the eye sits at the origin
    vec3 I = uLamp[0] * uKa;
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= uNumLights)
            break;
        vec3 lightCam = (uViewMatrix * vec4(uLightPosition[i], 1.0)).xyz;
        vec3 toLight = lightCam - vPositionCam;
        float d = length(toLight);
        vec3 L = toLight / d;
        vec3 R = reflect(-L, N);           // reflect() takes the incident vector
        float diffuse = max(0.0, dot(N, L));
        float specular = diffuse > 0.0 ? pow(max(0.0, dot(R, V)), uShininess) : 0.0;
        vec3 c = uAttenuation[i];
        float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
        I += fatt * (uLamp[1] * uKd * diffuse + uLamp[2] * uKs * specular);
    }
    outColor = vec4(I, 1.0);
}
