// A course's starter file, written for PhongLab's tests in the shape of
// Angel & Shreiner's Common/MV.js: vectors are arrays, a matrix is an array
// of its rows, flatten() hands WebGL the column-major floats it expects.
function vec3(x, y, z) { return [x, y, z]; }
function vec4(x, y, z, w) { return [x, y, z, w]; }
function subtract(a, b) { return a.map((v, i) => v - b[i]); }
function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
function dot(a, b) { return a.reduce((s, v, i) => s + v * b[i], 0); }
function length(a) { return Math.sqrt(dot(a, a)); }
function normalize(a) { const l = length(a); return a.map((v) => v / l); }
function asMatrix(rows) { rows.matrix = true; return rows; }
function mat4() { return asMatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]); }
function mult(a, b) {
  if (!Array.isArray(b[0])) return a.map((row) => dot(row, b));
  return asMatrix(a.map((row) => b[0].map((_, j) => row.reduce((s, v, k) => s + v * b[k][j], 0))));
}
function translate(x, y, z) { const m = mat4(); m[0][3] = x; m[1][3] = y; m[2][3] = z; return m; }
function scalem(x, y, z) { const m = mat4(); m[0][0] = x; m[1][1] = y; m[2][2] = z; return m; }
function rotateY(degrees) {
  const c = Math.cos(degrees * Math.PI / 180), s = Math.sin(degrees * Math.PI / 180);
  return asMatrix([[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, 0], [0, 0, 0, 1]]);
}
function rotateX(degrees) {
  const c = Math.cos(degrees * Math.PI / 180), s = Math.sin(degrees * Math.PI / 180);
  return asMatrix([[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1]]);
}
function lookAt(eye, at, up) {
  const n = normalize(subtract(eye, at));
  const u = normalize(cross(up, n));
  const v = cross(n, u);
  return asMatrix([[...u, -dot(u, eye)], [...v, -dot(v, eye)], [...n, -dot(n, eye)], [0, 0, 0, 1]]);
}
function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy * Math.PI / 360), d = far - near;
  return asMatrix([[f / aspect, 0, 0, 0], [0, f, 0, 0], [0, 0, -(near + far) / d, -2 * near * far / d], [0, 0, -1, 0]]);
}
function upper3(m) { return asMatrix([m[0].slice(0, 3), m[1].slice(0, 3), m[2].slice(0, 3)]); }
function transpose(m) { return asMatrix(m[0].map((_, j) => m.map((row) => row[j]))); }
function inverse3(m) {
  const [a, b, c] = m[0], [d, e, f] = m[1], [g, h, i] = m[2];
  const A = e * i - f * h, B = f * g - d * i, C = d * h - e * g;
  const det = a * A + b * B + c * C;
  return asMatrix([[A / det, (c * h - b * i) / det, (b * f - c * e) / det],
          [B / det, (a * i - c * g) / det, (c * d - a * f) / det],
          [C / det, (b * g - a * h) / det, (a * e - b * d) / det]]);
}
// The inverse transpose of the upper 3x3 of the model-view: what moves normals.
function normalMatrix(m) { return transpose(inverse3(upper3(m))); }
function flatten(v) {
  if (!v.matrix) return new Float32Array(v.flat());
  return new Float32Array(transpose(v).flat()); // column-major
}
