// The book's own: Blinn's halfway vector, and no attenuation.
precision mediump float;

uniform vec4 ambientProduct;
uniform vec4 diffuseProduct;
uniform vec4 specularProduct;
uniform float shininess;

varying vec3 N, L, E;
varying float dist;

void main()
{
    vec3 n = normalize(N);
    vec3 l = normalize(L);
    vec3 e = normalize(E);
    vec3 H = normalize(l + e);

    vec4 ambient = ambientProduct;
    float Kd = max(dot(l, n), 0.0);
    vec4 diffuse = Kd * diffuseProduct;
    float Ks = pow(max(dot(n, H), 0.0), shininess);
    vec4 specular = Ks * specularProduct;
    if (dot(l, n) < 0.0)
        specular = vec4(0.0, 0.0, 0.0, 1.0);

    vec4 fColor = ambient + diffuse + specular;
    fColor.a = 1.0;
    gl_FragColor = fColor;
}
