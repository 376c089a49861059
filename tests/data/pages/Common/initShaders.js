// A course's starter file, written for PhongLab's tests in the shape of
// Angel & Shreiner's Common/initShaders.js: compiles the two <script>
// elements named and links them.
function initShaders(gl, vertexShaderId, fragmentShaderId) {
  function compile(id, type) {
    const element = document.getElementById(id);
    if (!element) { alert('Unable to load shader ' + id); return null; }
    const shader = gl.createShader(type);
    gl.shaderSource(shader, element.text);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
      alert(id + ' failed to compile: ' + gl.getShaderInfoLog(shader));
      return null;
    }
    return shader;
  }
  const program = gl.createProgram();
  gl.attachShader(program, compile(vertexShaderId, gl.VERTEX_SHADER));
  gl.attachShader(program, compile(fragmentShaderId, gl.FRAGMENT_SHADER));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    alert('Shader program failed to link: ' + gl.getProgramInfoLog(program));
    return null;
  }
  return program;
}
