precision mediump float;

uniform vec4 ambientProduct;
uniform vec4 diffuseProduct;
uniform vec4 specularProduct;
uniform float shininess;
uniform vec3 attenuation;

varying vec3 N, L, E;
varying float dist;

void main()
{
    vec3 n = normalize(N);
    vec3 l = normalize(L);
    vec3 e = normalize(E);
    vec3 r = reflect(-l, n);

    vec4 ambient = ambientProduct;
    float Kd = max(dot(l, n), 0.0);
    vec4 diffuse = Kd * diffuseProduct;
    float Ks = pow(max(dot(r, e), 0.0), shininess);
    vec4 specular = Ks * specularProduct;
    if (dot(l, n) < 0.0)
        specular = vec4(0.0, 0.0, 0.0, 1.0);
    float fatt = min(1.0 / (attenuation.x + attenuation.y * dist
                            + attenuation.z * dist * dist), 1.0);

    vec4 fColor = ambient + fatt * (diffuse + specular);
    fColor.a = 1.0;
    gl_FragColor = fColor;
}
