// Pieces joined around what the page computes: each becomes a placeholder.
function makeSources(lights) {
  const vs = '#define N ' + lights.length + '\n' +
    'attribute vec4 aPosition;\n' +
    'uniform vec3 lightPos[' + this.num_lights + '];\n' +
    'void main() {\n' +
    '  gl_Position = aPosition + vec4(lightPos[' + (N - 1) + '], 0.0);\n' +
    '}\n';
  const fs = `precision mediump float;
uniform vec3 lightColor[${this.numLights}];
#define SCALE ${String(scale.toFixed(2))}
void main() { gl_FragColor = vec4(lightColor[${`${0}`}] * SCALE, 1.0); }
`;
  const broken = 'void main() {' + f(a, [b + 'x'
  return initShaderProgram(gl, vs, fs);
}
