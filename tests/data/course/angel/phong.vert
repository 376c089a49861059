// Angel & Shreiner, Interactive Computer Graphics: per-fragment lighting.
// The light position is given in eye (camera) coordinates by the page.
attribute vec4 vPosition;
attribute vec3 vNormal;

varying vec3 N, L, E;
varying float dist;

uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat3 normalMatrix;
uniform vec4 lightPosition;

void main()
{
    vec3 pos = (modelViewMatrix * vPosition).xyz;
    L = lightPosition.xyz - pos;
    dist = length(L);
    E = -pos;
    N = normalMatrix * vNormal;
    gl_Position = projectionMatrix * modelViewMatrix * vPosition;
}
