// The slide's equation taken literally: max(0, R.V)^n with no N.L guard.
// PhongLab passes it as well as the guarded one (phonglab check --equation).
precision mediump float;

uniform mat4 u_view;
uniform vec3 u_lightPos[2];    // world coordinates
uniform vec3 u_Id[2];
uniform vec3 u_Is[2];
uniform vec3 u_attenuation[2]; // c1, c2, c3
uniform vec3 u_Ia;
uniform vec3 u_ka;
uniform vec3 u_kd;
uniform vec3 u_ks;
uniform float u_n;

varying vec3 v_position;
varying vec3 v_normal;

void main()
{
    vec3 N = normalize(v_normal);
    vec3 V = normalize(-v_position);
    vec3 I = u_Ia * u_ka;
    for (int i = 0; i < 2; i++) {
        vec3 lightCam = (u_view * vec4(u_lightPos[i], 1.0)).xyz;
        vec3 L = normalize(lightCam - v_position);
        float d = length(lightCam - v_position);
        vec3 R = reflect(-L, N);
        vec3 c = u_attenuation[i];
        float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
        I += fatt * (u_Id[i] * u_kd * max(0.0, dot(N, L))
                     + u_Is[i] * u_ks * pow(max(0.0, dot(R, V)), u_n));
    }
    gl_FragColor = vec4(I, 1.0);
}
