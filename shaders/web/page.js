// rt export-web's page script (framework/render/gpu/web_export.h). It draws the scene's first
// frame with the inlined fragment shader in WebGL2, reads it back with readPixels and hands it to
// the test as a PNG data URL (window.__rtPixels, window.__rtDone), then follows the mouse as
// `rt view` does: drag orbits about the surface under the image centre, the wheel zooms.
'use strict';
(function () {
  const data = JSON.parse(document.getElementById('rt-data').textContent);
  const status = document.getElementById('status');
  const live = document.getElementById('live');
  const kOrbitDegreesPerPixel = 0.3, kZoomPerWheelStep = 0.9;  // rt view's (viewer_window.cpp)

  document.getElementById('title').textContent = data.scene + ' (' + data.mode + ')';
  // Small course images blown up by a whole factor, each pixel a crisp square, as in rt view.
  const scale = Math.max(1, Math.floor(480 / Math.max(data.width, data.height)));
  function sized(canvas) {
    canvas.width = data.width;
    canvas.height = data.height;
    canvas.style.width = data.width * scale + 'px';
    canvas.style.height = data.height * scale + 'px';
  }
  sized(live);
  sized(document.getElementById('difference'));

  let renderer = 'no renderer yet';
  function fail(message) {
    status.textContent = message;
    console.error(message);
    window.__rtDone = { error: message, renderer: renderer };
  }

  // The renderer string for a browser without WebGL2: WebGL 1's, if it has that.
  function rendererWithoutWebgl2() {
    const gl1 = document.createElement('canvas').getContext('webgl');
    if (!gl1) return 'no WebGL at all';
    const info = gl1.getExtension('WEBGL_debug_renderer_info');
    return 'WebGL 1 only: ' + gl1.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl1.RENDERER);
  }

  // preserveDrawingBuffer: the first frame is read back after the draw; alpha unpremultiplied,
  // since it carries the stub a pixel reached (shadertoy_export.h's wrapper).
  const gl = live.getContext('webgl2', {
    alpha: true, premultipliedAlpha: false, antialias: false, depth: false,
    preserveDrawingBuffer: true,
  });
  if (!gl) {
    const renderer = rendererWithoutWebgl2();
    status.textContent = 'This browser offers no WebGL2 (' + renderer + ').';
    window.__rtDone = { noWebgl2: true, renderer: renderer };
    return;
  }
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  renderer = gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);

  // A full-screen triangle from gl_VertexID: no vertex buffers.
  const kVertexShader = '#version 300 es\nvoid main() {\n' +
    '    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n' +
    '    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n}\n';

  function compile(type, source, name) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS))
      throw new Error('the ' + name + ' does not compile: ' + gl.getShaderInfoLog(shader));
    return shader;
  }

  function link() {
    const program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER, kVertexShader, 'vertex shader'));
    const fragment = document.getElementById('rt-shader').textContent;
    gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragment, 'fragment shader (stage 09)'));
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS))
      throw new Error('the shaders do not link: ' + gl.getProgramInfoLog(program));
    return program;
  }

  // --- The camera (camera/camera_moves.cpp's orbit and zoom, in doubles) ---
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
  const mul = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
    a[0] * b[1] - a[1] * b[0]];
  const normalize = (a) => mul(a, 1 / Math.sqrt(dot(a, a)));
  function rotate(x, axis, degrees) {  // Rodrigues' formula
    const k = normalize(axis), t = degrees * Math.PI / 180, c = Math.cos(t), s = Math.sin(t);
    return add(add(mul(x, c), mul(cross(k, x), s)), mul(k, dot(k, x) * (1 - c)));
  }
  const initial = JSON.parse(JSON.stringify(data.camera));
  const up = initial.v;  // orbits keep the scene camera's up, so the horizon never rolls
  let camera = JSON.parse(JSON.stringify(initial)), pivotDistance = data.pivot_distance;

  function lookAt(eye, target) {
    const w = normalize(sub(eye, target)), u = normalize(cross(up, w));
    Object.assign(camera, { eye: eye, u: u, v: cross(w, u), w: w });
  }
  function orbit(yaw, pitch) {
    const pivot = sub(camera.eye, mul(camera.w, pivotDistance));
    let offset = rotate(sub(camera.eye, pivot), up, -yaw);
    const pitched = rotate(offset, normalize(cross(up, offset)), pitch);
    if (Math.abs(dot(normalize(pitched), up)) < 0.998) offset = pitched;
    lookAt(add(pivot, offset), pivot);
  }
  function zoom(factor) {
    if (camera.projection === 1) { camera.view_height *= factor; return; }
    const pivot = sub(camera.eye, mul(camera.w, pivotDistance));
    pivotDistance = Math.max(pivotDistance * factor, 1e-3);
    camera.eye = add(pivot, mul(camera.w, pivotDistance));
  }

  // --- Drawing ---
  let program = null;
  function draw() {
    gl.useProgram(program);
    const at = (name) => gl.getUniformLocation(program, name);
    gl.uniform3f(at('iResolution'), data.width, data.height, 1);
    gl.uniform1i(at('camera.projection'), camera.projection);
    for (const axis of ['eye', 'u', 'v', 'w']) gl.uniform3fv(at('camera.' + axis), camera[axis]);
    gl.uniform1f(at('camera.vertical_fov_degrees'), camera.vertical_fov_degrees);
    gl.uniform1f(at('camera.view_height'), camera.view_height);
    gl.viewport(0, 0, data.width, data.height);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  // Each stub a pixel reached (alpha < 255 holds its number), once, as rt render reports them.
  function reportStubs(rgba) {
    const seen = new Set();
    for (let i = 3; i < rgba.length; i += 4)
      if (rgba[i] < 255 && rgba[i] < data.stubs.length) seen.add(rgba[i]);
    for (const k of seen) {
      const s = data.stubs[k];
      console.error(s.loop
        ? s.file + ':' + s.line + ': a while loop ran too many times (stopped)'
        : s.file + ':' + s.line + ': not implemented: ' + s.function + ' (' + s.handout + ')');
    }
    return seen.size;
  }

  // The first frame, top row first, opaque, as an image the test can write and compare.
  let firstFrame = null;
  function readFirstFrame() {
    const rgba = new Uint8Array(data.width * data.height * 4);
    gl.readPixels(0, 0, data.width, data.height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    const error = gl.getError();
    if (error !== gl.NO_ERROR) throw new Error('WebGL error 0x' + error.toString(16));
    const stubs = reportStubs(rgba);
    firstFrame = new ImageData(data.width, data.height);
    const row = data.width * 4;
    for (let y = 0; y < data.height; ++y)  // readPixels' rows are bottom first
      firstFrame.data.set(rgba.subarray((data.height - 1 - y) * row, (data.height - y) * row), y * row);
    for (let i = 3; i < firstFrame.data.length; i += 4) firstFrame.data[i] = 255;
    const image = document.createElement('canvas');
    image.width = data.width;
    image.height = data.height;
    image.getContext('2d').putImageData(firstFrame, 0, 0);
    window.__rtPixels = image.toDataURL('image/png');
    return stubs;
  }

  function start() {
    const t0 = performance.now();
    try {
      program = link();
      draw();
      const stubs = readFirstFrame();
      const ms = Math.round(performance.now() - t0);
      status.textContent = 'First frame ' + data.width + 'x' + data.height + ' in ' + ms +
        ' ms (compile and draw) on ' + renderer +
        (stubs ? '; magenta pixels reached stubs (see the console)' : '') + '.';
      window.__rtDone = { ok: true, renderer: renderer, ms: ms };
    } catch (e) {
      fail('rt export-web: ' + e.message);
    }
  }

  // --- The CPU render beside the live canvas, and the first frame's difference from it ---
  function showReference() {
    if (!data.reference) { status.textContent = 'This page holds no CPU render.'; return; }
    const img = document.getElementById('reference');
    img.src = data.reference;
    img.style.width = data.width * scale + 'px';
    img.onload = () => {
      const c = document.createElement('canvas');
      c.width = data.width;
      c.height = data.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      const ref = g.getImageData(0, 0, data.width, data.height).data;
      const out = new ImageData(data.width, data.height);
      for (let i = 0; i < ref.length; ++i)  // a picture for the eye, not the test's metric
        out.data[i] = i % 4 === 3 ? 255 : Math.min(255, 8 * Math.abs(firstFrame.data[i] - ref[i]));
      document.getElementById('difference').getContext('2d').putImageData(out, 0, 0);
    };
    document.getElementById('reference-figure').hidden = false;
    document.getElementById('difference-figure').hidden = !firstFrame;
  }

  // --- The mouse ---
  let dragging = null;
  live.addEventListener('mousedown', (e) => { dragging = [e.clientX, e.clientY]; });
  window.addEventListener('mouseup', () => { dragging = null; });
  window.addEventListener('mousemove', (e) => {
    if (!dragging || !program) return;
    orbit((e.clientX - dragging[0]) * kOrbitDegreesPerPixel,
      (e.clientY - dragging[1]) * kOrbitDegreesPerPixel);
    dragging = [e.clientX, e.clientY];
    requestAnimationFrame(draw);
  });
  live.addEventListener('wheel', (e) => {
    e.preventDefault();
    if (!program) return;
    zoom(Math.pow(kZoomPerWheelStep, e.deltaY < 0 ? 1 : -1));
    requestAnimationFrame(draw);
  }, { passive: false });
  document.getElementById('reset').addEventListener('click', () => {
    camera = JSON.parse(JSON.stringify(initial));
    pivotDistance = data.pivot_distance;
    if (program) draw();
  });
  document.getElementById('compare').addEventListener('click', showReference);

  // Let the page paint "Compiling..." before the (blocking) compile.
  requestAnimationFrame(() => setTimeout(start, 0));
})();
