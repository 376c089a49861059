uniform vec3 ambientLightColor;
uniform vec3 materialAmbient;
uniform vec3 materialDiffuse;
uniform vec3 materialSpecular;
uniform float shininess;
uniform vec3 lightPositions[NUM_LIGHTS];   // world coordinates
uniform vec3 lightColors[NUM_LIGHTS];
uniform vec3 lightAttenuation[NUM_LIGHTS];

varying vec3 vNormal;
varying vec3 vViewPosition;

void main() {
    vec3 N = normalize(vNormal);
    vec3 V = normalize(-vViewPosition);
    vec3 color = ambientLightColor * materialAmbient;
    for (int i = 0; i < NUM_LIGHTS; i++) {
        vec3 lightView = (viewMatrix * vec4(lightPositions[i], 1.0)).xyz;
        vec3 toLight = lightView - vViewPosition;
        float d = length(toLight);
        vec3 L = toLight / d;
        float NdotL = dot(N, L);
        if (NdotL > 0.0) {
            vec3 R = reflect(-L, N);
            vec3 c = lightAttenuation[i];
            float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
            color += fatt * lightColors[i]
                * (materialDiffuse * NdotL + materialSpecular * pow(max(dot(R, V), 0.0), shininess));
        }
    }
    gl_FragColor = vec4(color, 1.0);
}
