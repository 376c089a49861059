"use strict";
// The JavaScript half of the exercise: the cloud Blender exported, its
// normals in a VBO, every coefficient a uniform. The selects choose the
// mistakes PhongLab must find (tests/gl/tst_pagecheck.cpp).
let gl, program, vertexCount = 0, mesh = null;
const lightPosition = vec4(1.5, 2.0, 3.0, 1.0); // world coordinates
const eye = vec3(0.0, 0.4, 3.2), at = vec3(0, 0, 0), up = vec3(0, 1, 0);

function readObj(text) {
  const v = [], vn = [], positions = [], normals = [];
  for (const line of text.split('\n')) {
    const p = line.trim().split(/\s+/);
    if (p[0] === 'v') v.push(p.slice(1, 4).map(Number));
    else if (p[0] === 'vn') vn.push(p.slice(1, 4).map(Number));
    else if (p[0] === 'f') {
      const corners = p.slice(1).map((c) => c.split('/'));
      for (let k = 1; k + 1 < corners.length; ++k)
        for (const c of [corners[0], corners[k], corners[k + 1]]) {
          positions.push(v[Number(c[0]) - 1]);
          normals.push(vn[Number(c[2]) - 1]);
        }
    }
  }
  return { positions, normals };
}

function normalsToSend(choice) {
  const p = mesh.positions;
  if (choice === 'positions') return p.map((x) => [...x]);
  if (choice === 'long') return mesh.normals.map((n) => n.map((c) => 2.5 * c));
  if (choice === 'face') {
    const out = [];
    for (let i = 0; i < p.length; i += 3) {
      const n = normalize(cross(subtract(p[i + 1], p[i]), subtract(p[i + 2], p[i])));
      out.push(n, n, n);
    }
    return out;
  }
  return mesh.normals;
}

function upload() {
  const choice = document.getElementById('normals').value;
  const positions = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, positions);
  gl.bufferData(gl.ARRAY_BUFFER, flatten(mesh.positions.map((x) => [...x, 1.0])), gl.STATIC_DRAW);
  const vPosition = gl.getAttribLocation(program, 'vPosition');
  gl.vertexAttribPointer(vPosition, 4, gl.FLOAT, false, 0, 0);
  gl.enableVertexAttribArray(vPosition);
  const normals = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, normals);
  gl.bufferData(gl.ARRAY_BUFFER, flatten(normalsToSend(choice)), gl.STATIC_DRAW);
  const vNormal = gl.getAttribLocation(program, 'vNormal');
  gl.vertexAttribPointer(vNormal, 3, gl.FLOAT, false, 0, 0);
  gl.enableVertexAttribArray(vNormal);
  vertexCount = mesh.positions.length;
}

function render(time) {
  const view = lookAt(eye, at, up);
  const model = mult(rotateY(30 + time * 0.01), mult(rotateX(-20), scalem(1.0, 0.8, 1.2)));
  const modelView = mult(view, model);
  const choice = document.getElementById('normalMatrix').value;
  const normal = choice === 'transpose' ? transpose(upper3(modelView)) : normalMatrix(modelView);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.uniformMatrix4fv(gl.getUniformLocation(program, 'modelViewMatrix'), false, flatten(modelView));
  gl.uniformMatrix4fv(gl.getUniformLocation(program, 'projectionMatrix'), false,
                      flatten(perspective(45, 1, 0.1, 20)));
  gl.uniformMatrix3fv(gl.getUniformLocation(program, 'normalMatrix'), false, flatten(normal));
  gl.uniform4fv(gl.getUniformLocation(program, 'lightPosition'), flatten(mult(view, lightPosition)));
  gl.drawArrays(gl.TRIANGLES, 0, vertexCount);
  requestAnimationFrame(render);
}

window.onload = function init() {
  const canvas = document.getElementById('gl-canvas');
  gl = canvas.getContext('webgl');
  gl.viewport(0, 0, canvas.width, canvas.height);
  gl.clearColor(0.1, 0.1, 0.15, 1.0);
  gl.enable(gl.DEPTH_TEST);
  program = initShaders(gl, 'vertex-shader', 'fragment-shader');
  gl.useProgram(program);
  const lightAmbient = vec4(0.2, 0.2, 0.2, 1.0), lightColor = vec4(1.0, 1.0, 1.0, 1.0);
  const ka = vec4(1.0, 0.3, 0.2, 1.0), kd = vec4(1.0, 0.45, 0.3, 1.0), ks = vec4(0.9, 0.9, 0.9, 1.0);
  const product = (a, b) => a.map((x, i) => x * b[i]);
  gl.uniform4fv(gl.getUniformLocation(program, 'ambientProduct'), flatten(product(lightAmbient, ka)));
  gl.uniform4fv(gl.getUniformLocation(program, 'diffuseProduct'), flatten(product(lightColor, kd)));
  gl.uniform4fv(gl.getUniformLocation(program, 'specularProduct'), flatten(product(lightColor, ks)));
  gl.uniform1f(gl.getUniformLocation(program, 'shininess'), 40.0);
  gl.uniform3fv(gl.getUniformLocation(program, 'attenuation'), flatten(vec3(1.0, 0.0, 0.0)));
  const request = new XMLHttpRequest();
  request.open('GET', 'cloud.obj');
  request.onload = () => {
    mesh = readObj(request.responseText);
    upload();
    for (const id of ['normals', 'normalMatrix'])
      document.getElementById(id).onchange = upload;
    requestAnimationFrame(render);
  };
  request.send();
};
