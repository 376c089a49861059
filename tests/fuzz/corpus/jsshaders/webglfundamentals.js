'use strict';
const vertexShaderSource = `#version 300 es
in vec4 a_position;
void main() {
  gl_Position = a_position;
}
`;
const fs = ['precision mediump float;', 'void main() {', '  gl_FragColor = vec4(1, 0, 0.5, 1);', '}'].join('\n');
var re = /`[^`]*`/g, d = a / b / c;
const vs = createShader(gl, gl.VERTEX_SHADER, vertexShaderSource);
const program = webglUtils.createProgramFromSources(gl, [vertexShaderSource, fs]);
const p2 = createProgram(gl, vs, createShader(gl, gl.FRAGMENT_SHADER, fs));
