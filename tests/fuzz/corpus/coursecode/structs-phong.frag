#version 300 es
precision highp float;

struct Light {
    vec3 position;   // world coordinates
    vec3 color;      // one colour for the diffuse and the specular part
    float constant;
    float linear;
    float quadratic;
};

struct Material {
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    int shininess;
};

uniform Light lights[2];
uniform Material material;
uniform vec3 ambientLight;
uniform mat4 uView;
uniform int mode; // the page's switch: 0 normals, 1 Phong

in vec3 vPosition;
in vec3 vNormal;
out vec4 fragColor;

void main()
{
    vec3 N = normalize(vNormal);
    if (mode == 0) {
        fragColor = vec4(0.5 * N + 0.5, 1.0);
        return;
    }
    vec3 V = normalize(-vPosition);
    vec3 result = ambientLight * material.ambient;
    for (int i = 0; i < 2; i++) {
        vec3 lightPos = (uView * vec4(lights[i].position, 1.0)).xyz;
        float d = length(lightPos - vPosition);
        vec3 L = normalize(lightPos - vPosition);
        float NdotL = max(dot(N, L), 0.0);
        float spec = 0.0;
        if (NdotL > 0.0)
            spec = pow(max(dot(reflect(-L, N), V), 0.0), float(material.shininess));
        float att = min(1.0 / (lights[i].constant + lights[i].linear * d
                               + lights[i].quadratic * d * d), 1.0);
        result += att * lights[i].color * (material.diffuse * NdotL + material.specular * spec);
    }
    fragColor = vec4(result, 1.0);
}
