// Phong-Lib.js: a student's own "library", its shaders in strings.
var PhongLib = {};
PhongLib.vertexShader =
  'attribute vec4 vPosition;\n' +
  'uniform vec4 lightPosition;\n' +
  'void main() {\n' +
  '  gl_Position = vPosition + lightPosition;\n' +
  '}\n';
PhongLib.fragmentShader =
  'precision mediump float;\n' +
  'uniform vec4 diffuseProduct;\n' +
  'void main() { gl_FragColor = diffuseProduct; }\n';
PhongLib.program = function(gl) {
  return createProgram(gl, PhongLib.vertexShader, PhongLib.fragmentShader);
};
