// phong.vert, loaded by <script src="phong.vert">: JavaScript, not GLSL.
var phongVS = `attribute vec4 vPosition;
uniform vec4 lightPosition;
varying vec3 L;
void main() {
    L = lightPosition.xyz;
    gl_Position = vPosition;
}
`;
const phongFS = "precision mediump float;\n" +
  "varying vec3 L;\n" +
  "void main() { gl_FragColor = vec4(normalize(L), 1.0); }";
