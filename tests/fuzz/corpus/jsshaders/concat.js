var vs = 'attribute vec4 p;\n' +
  'void main() {\n' +
  '  gl_Position = p;\u0020\n' +
  '}\n';
var t = `a${ {x: `in${1}`}.x }b`; // `
initShaders(gl, vs, "fs");
