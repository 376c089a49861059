// Injected by PhongLab (core/page/PageRun) before a student's page runs, in
// every document of the page. It makes the page deterministic and records
// what the page hands to WebGL, so that PhongLab can check the page as the
// student's browser ran it:
//  - the clock is virtual (Date, performance.now, requestAnimationFrame and
//    the timers advance only when PhongLab runs a frame) and Math.random is
//    seeded, so two runs draw the same frame;
//  - the canvas gets preserveDrawingBuffer (to be read after the frame) and
//    no antialiasing; the browser's clear after each shown frame is kept;
//  - each draw is recorded with the state it ran with: the program, every
//    active uniform's value (as getUniform reads it back), the attribute
//    layouts and the buffers' bytes, and the JavaScript stack that made it.
// window.__phonglabConfig ({seed, steps}) is set by PhongLab in front of
// this text. Nothing here talks to the network; the network attempts a page
// makes outside HTTP (WebSocket, EventSource, beacons, WebRTC) are refused here
// and listed, HTTP ones are answered by PhongLab itself.
(() => {
  'use strict';
  if (window.__phonglab) return;
  const config = window.__phonglabConfig || {};
  const realSetTimeout = window.setTimeout.bind(window);
  const origin = location.origin;

  // --- what the page did wrong or tried, for the report ----------------
  const problems = { errors: [], refused: [], console: [] };
  const note = (list, entry) => { if (list.length < 50) list.push(entry); };
  window.addEventListener('error', (e) => note(problems.errors, {
    message: String(e.message), where: where(e.filename, e.lineno, e.colno) }));
  window.addEventListener('unhandledrejection', (e) => note(problems.errors, {
    message: 'unhandled promise rejection: ' + String(e.reason), where: null }));
  const realConsoleError = console.error;
  const text = (value) => { try { return String(value); } catch (e) { return '[object]'; } };
  console.error = function (...args) {
    note(problems.console, args.map(text).join(' '));
    return realConsoleError.apply(this, args);
  };
  function refuse(kind, url) {
    note(problems.refused, { kind, url: String(url) });
  }
  for (const name of ['WebSocket', 'EventSource', 'RTCPeerConnection', 'webkitRTCPeerConnection']) {
    if (!window[name]) continue;
    window[name] = function (url) {
      refuse(name, url);
      throw new DOMException(name + ' is not available while PhongLab checks the page',
                             'SecurityError');
    };
  }
  // A dialog would hold the page until someone answers it.
  window.alert = (message) => note(problems.console, 'alert: ' + String(message));
  window.confirm = (message) => { note(problems.console, 'confirm: ' + String(message)); return false; };
  window.prompt = (message) => { note(problems.console, 'prompt: ' + String(message)); return null; };
  if (navigator.sendBeacon)
    navigator.sendBeacon = (url) => { refuse('sendBeacon', url); return false; };

  // --- the stack of the page's call, outside this script ----------------
  function where(file, line, column) {
    if (!file) return null;
    const path = (file.startsWith(origin) ? file.slice(origin.length + 1) : file).split('?')[0];
    let name = path;
    try { name = decodeURIComponent(path); } catch (e) { /* a name like 50%.js stays as it is */ }
    return { file: name, line: line | 0, column: column | 0 };
  }
  function callStack() {
    const frames = [];
    const text = new Error().stack || '';
    for (const line of text.split('\n').slice(1)) {
      const m = /\(?((?:https?|file):[^\s()]+):(\d+):(\d+)\)?\s*$/.exec(line);
      if (!m) continue;
      const at = where(m[1], +m[2], +m[3]);
      const fn = /^\s*at\s+(?:async\s+)?([^\s(]+)\s+\(/.exec(line);
      at.function = fn ? fn[1] : '';
      frames.push(at);
      if (frames.length === 8) break;
    }
    return frames;
  }

  // --- the virtual clock ------------------------------------------------
  const kFrameMs = 1000 / 60;
  const kEpoch = Date.UTC(2026, 0, 1, 12, 0, 0);
  let now = 0; // virtual milliseconds since the page started
  const RealDate = Date;
  function FixedDate(...args) {
    if (!new.target) return new RealDate(kEpoch + now).toString();
    return args.length ? new RealDate(...args) : new RealDate(kEpoch + read());
  }
  FixedDate.prototype = RealDate.prototype;
  // Each reading moves the clock on by a microsecond, the same on every run:
  // a page that waits in a loop for the time to pass gets there.
  const read = () => (now += 0.001);
  FixedDate.now = () => kEpoch + read();
  FixedDate.parse = RealDate.parse;
  FixedDate.UTC = RealDate.UTC;
  window.Date = FixedDate;
  Object.defineProperty(performance, 'now', { value: () => read(), configurable: true });
  let seed = (config.seed >>> 0) || 1;
  Math.random = () => { // mulberry32
    seed = (seed + 0x6d2b79f5) >>> 0;
    let t = seed;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };

  const timers = new Map(); // id -> {fn, args, due, every}
  let nextTimer = 1;
  const callable = (fn) => (typeof fn === 'function' ? fn : () => (0, eval)(String(fn)));
  function addTimer(fn, ms, args, every) {
    const id = nextTimer++;
    const wait = Math.max(0, Number(ms) || 0);
    timers.set(id, { fn: callable(fn), args, due: now + wait, every: every ? Math.max(wait, 1) : 0 });
    return id;
  }
  window.setTimeout = (fn, ms, ...args) => addTimer(fn, ms, args, false);
  window.setInterval = (fn, ms, ...args) => addTimer(fn, ms, args, true);
  window.clearTimeout = window.clearInterval = (id) => { timers.delete(id); };
  let frameCallbacks = new Map();
  let nextFrameCallback = 1;
  window.requestAnimationFrame = (fn) => {
    const id = nextFrameCallback++;
    frameCallbacks.set(id, fn);
    return id;
  };
  window.cancelAnimationFrame = (id) => { frameCallbacks.delete(id); };

  // Requests the page has in flight (XMLHttpRequest, fetch): a frame waits
  // for them, as a page that loads its mesh first would be seen drawing it.
  let inFlight = 0;
  const counted = (promise) => { ++inFlight; return promise.finally(() => { --inFlight; }); };
  const realFetch = window.fetch;
  window.fetch = function (...args) { return counted(realFetch.apply(this, args)); };
  // Reading a response's body is the rest of the request.
  for (const name of ['text', 'json', 'arrayBuffer', 'blob']) {
    const real = Response.prototype[name];
    Response.prototype[name] = function (...args) { return counted(real.apply(this, args)); };
  }
  const pending = new Set(); // XMLHttpRequests sent and not yet ended
  const realSend = XMLHttpRequest.prototype.send;
  XMLHttpRequest.prototype.send = function (...args) {
    if (!pending.has(this)) {
      pending.add(this);
      ++inFlight;
      const done = () => { if (pending.delete(this)) --inFlight; };
      this.addEventListener('loadend', done, { once: true });
      try { return realSend.apply(this, args); } catch (e) { done(); throw e; }
    }
    return realSend.apply(this, args);
  };

  // --- WebGL --------------------------------------------------------------
  const ids = new WeakMap();
  let nextId = 1;
  const idOf = (object) => {
    if (!object) return 0;
    if (!ids.has(object)) ids.set(object, nextId++);
    return ids.get(object);
  };
  const state = {
    gl: null, version: 0, canvas: null, extraContexts: 0,
    shaders: new Map(),   // id -> {type, source, log}
    programs: new Map(),  // id -> {vertex, fragment, linked, log}
    buffers: new Map(),   // id -> {bytes: Uint8Array, version, stack}
    savedBuffers: new Map(), // "id:version" -> Uint8Array, the bytes a draw used
    uniformStacks: new Map(), // "program:name" -> stack of the call that set it
    draws: [], drewThisFrame: false, frame: 0, shown: null,
  };

  const instrumented = new WeakSet();
  const contexts = new WeakMap(); // context -> {canvas, version}
  function adopt(gl, canvas, version) {
    state.gl = gl; state.canvas = canvas; state.version = version;
  }
  const realGetContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (type, attributes) {
    const webgl = /^(webgl2?|experimental-webgl)$/.test(String(type));
    const wanted = webgl ? Object.assign({}, attributes || {},
      { preserveDrawingBuffer: true, antialias: false }) : attributes;
    const context = realGetContext.call(this, type, wanted);
    if (webgl && context && !instrumented.has(context)) {
      // three.js and others probe WebGL on a canvas of their own first:
      // every context is recorded, and the capture follows the one that draws.
      instrumented.add(context);
      if (state.gl) ++state.extraContexts;
      else adopt(context, this, type === 'webgl2' ? 2 : 1);
      contexts.set(context, { canvas: this, version: type === 'webgl2' ? 2 : 1 });
      instrument(context);
    }
    return context;
  };

  function bytesOf(data, srcOffset, length) {
    if (data === null || data === undefined) return new Uint8Array(0);
    if (typeof data === 'number') return new Uint8Array(data);
    if (data instanceof ArrayBuffer) return new Uint8Array(data.slice(0));
    const element = data.BYTES_PER_ELEMENT || 1;
    const start = data.byteOffset + (srcOffset || 0) * element;
    const count = length ? length * element : data.byteLength - (srcOffset || 0) * element;
    return new Uint8Array(data.buffer.slice(start, start + count));
  }

  function instrument(gl) {
    const proto = Object.getPrototypeOf(gl);
    const call = (name, ...args) => proto[name].apply(gl, args);
    const wrap = (name, after) => {
      if (typeof proto[name] !== 'function') return;
      gl[name] = function (...args) {
        const result = proto[name].apply(gl, args);
        after(args, result);
        return result;
      };
    };
    wrap('createShader', ([type], shader) => {
      if (shader) state.shaders.set(idOf(shader), { type, source: '', log: '' });
    });
    wrap('shaderSource', ([shader, source]) => {
      const s = state.shaders.get(idOf(shader));
      if (s) s.source = String(source);
    });
    wrap('compileShader', ([shader]) => {
      const s = state.shaders.get(idOf(shader));
      if (s && !call('getShaderParameter', shader, gl.COMPILE_STATUS))
        s.log = call('getShaderInfoLog', shader) || '';
    });
    wrap('linkProgram', ([program]) => {
      const entry = { vertex: '', fragment: '', linked: false, log: '' };
      for (const shader of call('getAttachedShaders', program) || []) {
        const s = state.shaders.get(idOf(shader));
        if (!s) continue;
        if (s.type === gl.VERTEX_SHADER) entry.vertex = s.source;
        else entry.fragment = s.source;
        if (s.log) entry.log += s.log;
      }
      entry.linked = !!call('getProgramParameter', program, gl.LINK_STATUS);
      if (!entry.linked) entry.log += call('getProgramInfoLog', program) || '';
      state.programs.set(idOf(program), entry);
    });
    const bufferTarget = (target) => call('getParameter',
      target === gl.ELEMENT_ARRAY_BUFFER ? gl.ELEMENT_ARRAY_BUFFER_BINDING : gl.ARRAY_BUFFER_BINDING);
    wrap('bufferData', ([target, data, usage, srcOffset, length]) => {
      if (target !== gl.ARRAY_BUFFER && target !== gl.ELEMENT_ARRAY_BUFFER) return;
      const id = idOf(bufferTarget(target));
      const old = state.buffers.get(id);
      state.buffers.set(id, { bytes: bytesOf(data, srcOffset, length),
                              version: old ? old.version + 1 : 1, stack: callStack() });
    });
    wrap('bufferSubData', ([target, offset, data, srcOffset, length]) => {
      if (target !== gl.ARRAY_BUFFER && target !== gl.ELEMENT_ARRAY_BUFFER) return;
      const entry = state.buffers.get(idOf(bufferTarget(target)));
      if (!entry) return;
      const bytes = bytesOf(data, srcOffset, length);
      const grown = new Uint8Array(Math.max(entry.bytes.length, offset + bytes.length));
      grown.set(entry.bytes);
      grown.set(bytes, offset);
      entry.bytes = grown; entry.version += 1; entry.stack = callStack();
    });
    const locations = new WeakMap(); // WebGLUniformLocation -> "program:name"
    wrap('getUniformLocation', ([program, name], location) => {
      if (location) locations.set(location, idOf(program) + ':' + String(name).replace(/\[0\]$/, ''));
    });
    for (const name of Object.getOwnPropertyNames(proto)) {
      if (!/^uniform(Matrix)?[1-4]/.test(name)) continue;
      wrap(name, ([location]) => {
        const key = location && locations.get(location);
        if (key) state.uniformStacks.set(key, callStack());
      });
    }
    wrap('clear', ([mask]) => {
      if (drawsToCanvas() && owns()) startDrawing().push({ op: 'clear', mask,
        color: Array.from(call('getParameter', gl.COLOR_CLEAR_VALUE)),
        depth: call('getParameter', gl.DEPTH_CLEAR_VALUE),
        state: drawState() });
    });
    const draw = (kind) => (args) => { if (drawsToCanvas() && owns()) recordDraw(kind, args); };
    // The frame is one context's: the first that draws (a probe that only
    // asks for a context never does).
    function owns() { return state.gl === gl || (!state.shown && !state.drewThisFrame); }
    wrap('drawArrays', draw('arrays'));
    wrap('drawElements', draw('elements'));
    wrap('drawArraysInstanced', draw('arrays-instanced'));
    wrap('drawElementsInstanced', draw('elements-instanced'));
    wrap('drawRangeElements', draw('range-elements'));

    function drawsToCanvas() {
      return !call('getParameter', gl.FRAMEBUFFER_BINDING);
    }
    function startDrawing() {
      if (state.gl !== gl && !state.shown && !state.drewThisFrame) {
        const c = contexts.get(gl);
        adopt(gl, c.canvas, c.version);
      }
      if (!state.drewThisFrame) { state.draws = []; state.drewThisFrame = true; }
      return state.draws;
    }
    function enabled(cap) { return call('isEnabled', cap); }
    function drawState() {
      return {
        viewport: Array.from(call('getParameter', gl.VIEWPORT)),
        depthTest: enabled(gl.DEPTH_TEST), depthFunc: call('getParameter', gl.DEPTH_FUNC),
        depthMask: call('getParameter', gl.DEPTH_WRITEMASK),
        cullFace: enabled(gl.CULL_FACE), cullMode: call('getParameter', gl.CULL_FACE_MODE),
        frontFace: call('getParameter', gl.FRONT_FACE),
        blend: enabled(gl.BLEND),
        blendFunc: [gl.BLEND_SRC_RGB, gl.BLEND_DST_RGB, gl.BLEND_SRC_ALPHA, gl.BLEND_DST_ALPHA]
          .map((p) => call('getParameter', p)),
        colorMask: Array.from(call('getParameter', gl.COLOR_WRITEMASK)),
        scissorTest: enabled(gl.SCISSOR_TEST),
        scissor: Array.from(call('getParameter', gl.SCISSOR_BOX)),
      };
    }
    function saveBuffer(buffer) {
      const id = idOf(buffer);
      const entry = state.buffers.get(id);
      if (!entry) return null;
      const key = id + ':' + entry.version;
      if (!state.savedBuffers.has(key))
        state.savedBuffers.set(key, { bytes: entry.bytes, stack: entry.stack });
      return key;
    }
    function uniformValue(value) {
      if (value === null || value === undefined) return null;
      if (typeof value === 'number' || typeof value === 'boolean') return [Number(value)];
      if (value.length !== undefined) return Array.from(value, Number);
      return null; // a sampler's texture unit is a number; anything else is left out
    }
    function uniforms(program) {
      const pid = idOf(program);
      const list = [];
      const count = call('getProgramParameter', program, gl.ACTIVE_UNIFORMS);
      for (let i = 0; i < count; ++i) {
        const info = call('getActiveUniform', program, i);
        if (!info) continue;
        const base = info.name.replace(/\[0\]$/, '');
        const isArray = info.name.endsWith('[0]');
        const values = [];
        for (let k = 0; k < info.size; ++k) {
          const location = call('getUniformLocation', program, isArray ? base + '[' + k + ']' : base);
          values.push(location ? uniformValue(call('getUniform', program, location)) : null);
        }
        list.push({ name: base, type: info.type, size: info.size, array: isArray, values,
                    set_at: state.uniformStacks.get(pid + ':' + base) || [] });
      }
      return list;
    }
    function attributes(program) {
      const list = [];
      const count = call('getProgramParameter', program, gl.ACTIVE_ATTRIBUTES);
      for (let i = 0; i < count; ++i) {
        const info = call('getActiveAttrib', program, i);
        if (!info || info.name.startsWith('gl_')) continue;
        const location = call('getAttribLocation', program, info.name);
        const entry = { name: info.name, type: info.type, location };
        const get = (p) => call('getVertexAttrib', location, p);
        entry.enabled = !!get(gl.VERTEX_ATTRIB_ARRAY_ENABLED);
        if (entry.enabled) {
          entry.buffer = saveBuffer(get(gl.VERTEX_ATTRIB_ARRAY_BUFFER_BINDING));
          entry.size = get(gl.VERTEX_ATTRIB_ARRAY_SIZE);
          entry.component = get(gl.VERTEX_ATTRIB_ARRAY_TYPE);
          entry.normalized = !!get(gl.VERTEX_ATTRIB_ARRAY_NORMALIZED);
          entry.stride = get(gl.VERTEX_ATTRIB_ARRAY_STRIDE);
          entry.offset = call('getVertexAttribOffset', location, gl.VERTEX_ATTRIB_ARRAY_POINTER);
          entry.integer = state.version === 2 && !!get(gl.VERTEX_ATTRIB_ARRAY_INTEGER);
          entry.divisor = state.version === 2 ? get(gl.VERTEX_ATTRIB_ARRAY_DIVISOR) : 0;
        } else {
          entry.value = Array.from(get(gl.CURRENT_VERTEX_ATTRIB), Number);
        }
        list.push(entry);
      }
      return list;
    }
    function recordDraw(kind, args) {
      const program = call('getParameter', gl.CURRENT_PROGRAM);
      if (!program) return;
      const entry = { op: 'draw', kind, program: idOf(program), mode: args[0],
                      state: drawState(), stack: callStack() };
      if (kind.startsWith('arrays')) {
        entry.first = args[1]; entry.count = args[2]; entry.instances = args[3] || 1;
      } else {
        const at = kind === 'range-elements' ? 3 : 1;
        entry.count = args[at]; entry.indexType = args[at + 1]; entry.offset = args[at + 2];
        entry.instances = kind === 'elements-instanced' ? args[4] : 1;
        entry.indices = saveBuffer(call('getParameter', gl.ELEMENT_ARRAY_BUFFER_BINDING));
      }
      entry.uniforms = uniforms(program);
      entry.attributes = attributes(program);
      startDrawing().push(entry);
    }
  }

  // --- frames ---------------------------------------------------------------
  function withCanvasBound(work) {
    const gl = state.gl;
    const target = state.version === 2 ? gl.READ_FRAMEBUFFER : gl.FRAMEBUFFER;
    const binding = state.version === 2 ? gl.READ_FRAMEBUFFER_BINDING : gl.FRAMEBUFFER_BINDING;
    const proto = Object.getPrototypeOf(gl);
    const bound = proto.getParameter.call(gl, binding);
    if (bound) proto.bindFramebuffer.call(gl, target, null);
    const result = work(gl, proto);
    if (bound) proto.bindFramebuffer.call(gl, target, bound);
    return result;
  }
  function readCanvas() {
    return withCanvasBound((gl, proto) => {
      const width = gl.drawingBufferWidth, height = gl.drawingBufferHeight;
      const pixels = new Uint8Array(width * height * 4);
      const pack = proto.getParameter.call(gl, gl.PACK_ALIGNMENT);
      proto.pixelStorei.call(gl, gl.PACK_ALIGNMENT, 1);
      proto.readPixels.call(gl, 0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      proto.pixelStorei.call(gl, gl.PACK_ALIGNMENT, pack);
      return { width, height, pixels };
    });
  }
  // What the browser does once a frame is shown when the drawing buffer is
  // not preserved: clears it to transparent black (and depth to 1), so a
  // page that clears only the colour still finds depth cleared next frame.
  function clearAsTheBrowserDoes() {
    const gl = state.gl;
    const proto = Object.getPrototypeOf(gl);
    const get = (p) => proto.getParameter.call(gl, p);
    const drawBinding = get(gl.FRAMEBUFFER_BINDING);
    const color = get(gl.COLOR_CLEAR_VALUE), depth = get(gl.DEPTH_CLEAR_VALUE);
    const stencil = get(gl.STENCIL_CLEAR_VALUE);
    const colorMask = get(gl.COLOR_WRITEMASK), depthMask = get(gl.DEPTH_WRITEMASK);
    const stencilMask = get(gl.STENCIL_WRITEMASK);
    const scissor = proto.isEnabled.call(gl, gl.SCISSOR_TEST);
    const target = gl.FRAMEBUFFER;
    if (drawBinding) proto.bindFramebuffer.call(gl, target, null);
    proto.disable.call(gl, gl.SCISSOR_TEST);
    proto.colorMask.call(gl, true, true, true, true);
    proto.depthMask.call(gl, true);
    proto.stencilMask.call(gl, 0xffffffff);
    proto.clearColor.call(gl, 0, 0, 0, 0);
    proto.clearDepth.call(gl, 1);
    proto.clearStencil.call(gl, 0);
    proto.clear.call(gl, gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT | gl.STENCIL_BUFFER_BIT);
    proto.clearColor.apply(gl, color);
    proto.clearDepth.call(gl, depth);
    proto.clearStencil.call(gl, stencil);
    proto.colorMask.apply(gl, colorMask);
    proto.depthMask.call(gl, depthMask);
    proto.stencilMask.call(gl, stencilMask);
    if (scissor) proto.enable.call(gl, gl.SCISSOR_TEST);
    if (drawBinding) proto.bindFramebuffer.call(gl, target, drawBinding);
  }
  function showFrame() {
    if (!state.gl || !state.drewThisFrame) return;
    state.shown = Object.assign(readCanvas(), { frame: state.frame, draws: state.draws });
    state.drewThisFrame = false;
    clearAsTheBrowserDoes();
  }
  // The timers due when the frame starts, in order; one a timer sets for
  // now waits for the next frame (a chain of setTimeout(f, 0) moves one step
  // a frame instead of never letting the frame end).
  function runTimersDue() {
    const due = [...timers].filter(([, t]) => t.due <= now).sort((a, b) => a[1].due - b[1].due || a[0] - b[0]);
    for (const [id, t] of due) {
      if (!timers.has(id)) continue; // cleared by an earlier one
      if (t.every) t.due = Math.max(t.due + t.every, now + 0.001); else timers.delete(id);
      try { t.fn(...t.args); } catch (e) { reportException(e); }
    }
  }
  function reportException(e) {
    const stack = String((e && e.stack) || e);
    const m = /((?:https?|file):[^\s()]+):(\d+):(\d+)/.exec(stack);
    note(problems.errors, { message: String((e && e.message) || e),
                            where: m ? where(m[1], +m[2], +m[3]) : null });
  }
  function frame() {
    showFrame();
    state.frame += 1;
    now = Math.max(now, state.frame * kFrameMs);
    runTimersDue();
    const callbacks = frameCallbacks;
    frameCallbacks = new Map();
    for (const fn of callbacks.values()) {
      try { fn(now); } catch (e) { reportException(e); }
    }
  }
  const idle = () => frameCallbacks.size === 0 && timers.size === 0;
  const realPause = (ms) => new Promise((resolve) => realSetTimeout(resolve, ms));
  async function settle() {
    await realPause(0);
    for (let waited = 0; inFlight > 0 && waited < 3000; waited += 10) await realPause(10);
  }

  // --- the steps a student would take before looking --------------------
  function runStep(step) {
    // The selector ends at the first '=' (select #shading=phong).
    const m = /^\s*(click|select|check|uncheck|set)\s+(\S+?)(?:\s*=\s*(.*))?$/.exec(step);
    if (!m) return 'not a step (click SELECTOR, select SELECTOR=VALUE, check SELECTOR, '
                   + 'uncheck SELECTOR, set SELECTOR=VALUE)';
    const [, verb, selector, value] = m;
    let element;
    try { element = document.querySelector(selector); } catch (e) { return 'not a selector'; }
    if (!element) return 'nothing on the page matches ' + selector;
    const fire = (type) => element.dispatchEvent(new Event(type, { bubbles: true }));
    if (verb === 'click') { element.click(); return ''; }
    if (verb === 'check' || verb === 'uncheck') {
      if (element.checked !== (verb === 'check')) element.click();
      return '';
    }
    if (value === undefined) return verb + ' needs SELECTOR=VALUE';
    if (verb === 'select') {
      const options = Array.from(element.options || []);
      const option = options.find((o) => o.value === value)
        || options.find((o) => o.text.trim() === value);
      if (!option) return 'no option ' + value + ' (there are: '
                          + options.map((o) => o.value).join(', ') + ')';
      element.value = option.value;
    } else {
      element.value = value;
    }
    fire('input');
    fire('change');
    return '';
  }

  // --- the capture ------------------------------------------------------------
  function base64(bytes) {
    let text = '';
    for (let i = 0; i < bytes.length; i += 0x8000)
      text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(text);
  }
  function capture(stepsDone) {
    const shown = state.shown;
    const usedPrograms = new Set(shown ? shown.draws.filter((d) => d.op === 'draw')
                                           .map((d) => d.program) : []);
    const programs = [];
    for (const [id, p] of state.programs)
      programs.push(Object.assign({ id, drawn: usedPrograms.has(id) }, p));
    const buffers = {};
    for (const [key, saved] of state.savedBuffers)
      buffers[key] = { bytes: base64(saved.bytes), set_at: saved.stack };
    return {
      format: 1,
      webgl: state.version,
      steps: stepsDone,
      frame: shown ? shown.frame : 0,
      animated: !idle(),
      canvas: shown ? { width: shown.width, height: shown.height }
                    : (state.canvas ? { width: state.canvas.width, height: state.canvas.height }
                                    : null),
      pixels: shown ? base64(shown.pixels) : '',
      draws: shown ? shown.draws : [],
      programs,
      buffers,
      extra_contexts: state.extraContexts,
      errors: problems.errors,
      console_errors: problems.console,
      refused: problems.refused,
    };
  }

  window.__phonglab = {
    // Runs the steps, then `frames` frames, and hands back the last frame
    // shown, as JSON text.
    async run(frames, steps) {
      await settle();
      const done = [];
      for (const step of steps || []) {
        let problem;
        try { problem = runStep(step); } catch (e) { problem = String(e); }
        done.push({ step, problem });
        await settle();
      }
      // Every frame runs, drawing or not: a page that draws once its mesh
      // has come is seen drawing it.
      // A page that has not drawn after them (setTimeout(init, 500)) gets up
      // to ten seconds of frames more, until it draws or has nothing left.
      const kMoreFrames = 600;
      for (let k = 0; k < frames || (k < frames + kMoreFrames && !state.shown
                                       && !state.drewThisFrame && !idle()); ++k) {
        frame();
        await settle();
      }
      showFrame();
      return JSON.stringify(capture(done));
    },
  };
})();
