"use strict";
// WebGL 2 in webgl2fundamentals' style: a vertex array, an index buffer
// (the tree welded by position and normal), world-space lighting, one draw
// once the mesh has loaded (no animation).
function compile(gl, id, type) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, document.getElementById(id).text);
  gl.compileShader(shader);
  return shader;
}

function indexedObj(text) {
  const v = [], vn = [], positions = [], normals = [], indices = [], seen = new Map();
  for (const line of text.split('\n')) {
    const p = line.trim().split(/\s+/);
    if (p[0] === 'v') v.push(p.slice(1, 4).map(Number));
    else if (p[0] === 'vn') vn.push(p.slice(1, 4).map(Number));
    else if (p[0] === 'f') {
      const corners = p.slice(1).map((c) => {
        const [vi, , ni] = c.split('/');
        const key = vi + '/' + ni;
        if (!seen.has(key)) {
          seen.set(key, positions.length / 3);
          positions.push(...v[vi - 1]);
          normals.push(...vn[ni - 1]);
        }
        return seen.get(key);
      });
      for (let k = 1; k + 1 < corners.length; ++k) indices.push(corners[0], corners[k], corners[k + 1]);
    }
  }
  return { positions, normals, indices };
}

async function main() {
  const canvas = document.querySelector('#canvas');
  const gl = canvas.getContext('webgl2');
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, 'vertex-shader-3d', gl.VERTEX_SHADER));
  gl.attachShader(program, compile(gl, 'fragment-shader-3d', gl.FRAGMENT_SHADER));
  gl.linkProgram(program);
  const mesh = indexedObj(await (await fetch('tree.obj')).text());

  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  for (const [name, data] of [['a_position', mesh.positions], ['a_normal', mesh.normals]]) {
    const buffer = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(data), gl.STATIC_DRAW);
    const location = gl.getAttribLocation(program, name);
    gl.enableVertexAttribArray(location);
    gl.vertexAttribPointer(location, 3, gl.FLOAT, false, 0, 0);
  }
  const indexBuffer = gl.createBuffer();
  gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indexBuffer);
  gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint16Array(mesh.indices), gl.STATIC_DRAW);

  gl.viewport(0, 0, gl.canvas.width, gl.canvas.height);
  gl.clearColor(0.9, 0.9, 0.95, 1);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.enable(gl.DEPTH_TEST);
  gl.enable(gl.CULL_FACE);
  gl.useProgram(program);

  const projection = m4.perspective(Math.PI / 4, canvas.width / canvas.height, 0.1, 20);
  const eye = [0.4, 0.6, 2.6];
  const view = m4.inverse(m4.lookAt(eye, [0, 0.1, 0], [0, 1, 0]));
  const world = m4.yRotation(0.6);
  const set = (name, fn, ...args) => gl[fn](gl.getUniformLocation(program, name), ...args);
  set('u_worldViewProjection', 'uniformMatrix4fv', false, m4.multiply(m4.multiply(projection, view), world));
  set('u_worldInverseTranspose', 'uniformMatrix4fv', false, m4.transpose(m4.inverse(world)));
  set('u_world', 'uniformMatrix4fv', false, world);
  set('u_color', 'uniform4fv', [0.2, 0.7, 0.3, 1]);
  set('u_lightColor', 'uniform3fv', [1, 1, 1]);
  set('u_specularColor', 'uniform3fv', [0.6, 0.6, 0.6]);
  set('u_shininess', 'uniform1f', 30);
  set('u_lightWorldPosition', 'uniform3fv', [1.5, 2.0, 2.5]);
  set('u_viewWorldPosition', 'uniform3fv', eye);
  gl.drawElements(gl.TRIANGLES, mesh.indices.length, gl.UNSIGNED_SHORT, 0);
}

main();
