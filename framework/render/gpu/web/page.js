// rt export-web's page script (framework/render/gpu/web_export.h). It draws the scene's first
// frame with the inlined fragment shader in WebGL2, reads it back with readPixels and hands it to
// the test as a PNG data URL (window.__rtPixels, window.__rtDone); then page_controls.js's panel,
// keys and mouse change the settings and the camera (page_camera.js) as `rt view`'s do, and each
// change draws again (window.__rtFrame() reads the latest frame back for the test).
(function () {
  const data = JSON.parse(document.getElementById('rt-data').textContent);
  const status = document.getElementById('status');
  const live = document.getElementById('live');
  const frameTime = document.getElementById('frame-time');

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

  // A compiler log's line numbers ("ERROR: 0:379:") of the stage 09 shader as the GLSL file and
  // line they came from (web_export.cpp's source_lines), or as "the export's line N".
  function withSourceLines(log) {
    const { head, runs } = data.source_lines;
    return log.replace(/\b0:(\d+):/g, (match, number) => {
      const line = Number(number) - head;  // 1-based, in the export
      const run = runs.find((r) => r[0] <= line && line < r[0] + r[3]);
      return run ? run[1] + ':' + (run[2] + line - run[0]) + ':' : 'the export\'s line ' + line + ':';
    });
  }

  // `explain` rewrites the compiler's log (withSourceLines, for the stage 09 shader).
  function compile(type, source, name, explain = (log) => log) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS))
      throw new Error('the ' + name + ' does not compile: ' + explain(gl.getShaderInfoLog(shader)));
    return shader;
  }

  function link() {
    const program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER, kVertexShader, 'vertex shader'));
    const fragment = document.getElementById('rt-shader').textContent;
    gl.attachShader(program,
      compile(gl.FRAGMENT_SHADER, fragment, 'fragment shader (stage 09)', withSourceLines));
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS))
      throw new Error('the shaders do not link: ' + gl.getProgramInfoLog(program));
    return program;
  }

  // The scene's large arrays (meshes, the BVH, images: web_arrays.h) as RGBA32UI data textures
  // on texture units 0.., each bound to its sampler rt_data_<name>.
  function uploadDataTextures(program) {
    gl.useProgram(program);
    data.data_textures.forEach((array, unit) => {
      const bytes = Uint8Array.from(atob(array.base64), (c) => c.charCodeAt(0));
      const words = new Uint32Array(array.width * array.height * 4);
      words.set(new Uint32Array(bytes.buffer));
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, gl.createTexture());
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32UI, array.width, array.height, 0,
        gl.RGBA_INTEGER, gl.UNSIGNED_INT, words);
      gl.uniform1i(gl.getUniformLocation(program, 'rt_data_' + array.name), unit);
    });
  }

  const view = rtCamera(data);
  // rt view's settings (view/view_settings.h), as the panel sets them: the scene file's at first.
  const panel = data.settings;
  const settings = Object.assign({}, panel.initial);
  for (const term of panel.terms) settings[term] = true;
  const initialSettings = JSON.stringify(settings);
  const settingsChanged = () => JSON.stringify(settings) !== initialSettings;

  // --- Drawing ---
  let program = null;
  let samples = null;  // stage 10's accumulation (page_samples.js), for a sampled scene
  const ranges = rtRanges(gl, data, kVertexShader, compile);  // depth, bvh_visits (page_ranges.js)
  // What the settings make of the shader's uniforms: web_export.cpp's feature bits per mode,
  // shadows and refraction (as gpu_feature_bits gives them), the switched-off terms as bits.
  function setSettingUniforms(at) {
    const mode = panel.modes.find((m) => m.name === settings.mode);
    gl.uniform1i(at('render_mode'), mode.value);
    const shaded = mode.value === panel.shaded;
    gl.uniform1i(at('max_depth'), shaded ? settings.max_depth : 0);
    gl.uniform1i(at('fresnel'), settings.fresnel ? 1 : 0);
    const index = (settings.shadows ? 2 : 0) + (settings.refraction ? 1 : 0);
    gl.uniform1i(at('scene_features'), panel.feature_bits[settings.mode][index]);
    let off = 0;
    panel.terms.forEach((term, i) => { if (!settings[term]) off |= 1 << i; });
    gl.uniform1i(at('rt_terms_off'), off);
  }

  // Draws the frame and calls done(ms) when it is complete: at once for one sample a pixel; for
  // stage 10's, batch by batch, one an animation frame, showing the mean so far (a newer draw
  // drops an older one's remaining batches), as rt view refines a sampled scene.
  let generation = 0;
  function draw(done) {
    const t0 = performance.now();
    const mine = ++generation;
    gl.useProgram(program);
    const at = (name) => gl.getUniformLocation(program, name);
    const camera = view.camera();
    gl.uniform3f(at('iResolution'), data.width, data.height, 1);
    gl.uniform1i(at('camera.projection'), camera.projection);
    for (const axis of ['eye', 'u', 'v', 'w']) gl.uniform3fv(at('camera.' + axis), camera[axis]);
    gl.uniform1f(at('camera.vertical_fov_degrees'), camera.vertical_fov_degrees);
    gl.uniform1f(at('camera.view_height'), camera.view_height);
    setSettingUniforms(at);
    gl.viewport(0, 0, data.width, data.height);
    const mode = panel.modes.find((m) => m.name === settings.mode);
    const finish = () => {
      // Wait for the GPU (one pixel read back), so that the time is the frame's.
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
      done(performance.now() - t0);
    };
    if (mode.name === 'depth' || mode.name === 'bvh_visits') {
      ranges.draw(() => gl.drawArrays(gl.TRIANGLES, 0, 3), mode.name === 'bvh_visits');
      return finish();
    }
    if (!samples || mode.value !== panel.shaded) {
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      return finish();
    }
    samples.begin();
    const batch = () => {
      if (mine !== generation) return;
      try {
        const complete = samples.step((first, count) => {
          gl.useProgram(program);
          gl.uniform1i(at('sample_first'), first);
          gl.uniform1i(at('sample_count'), count);
          gl.drawArrays(gl.TRIANGLES, 0, 3);
        });
        if (complete) return finish();
        frameTime.textContent = samples.drawn + ' of ' + samples.total + ' samples a pixel...';
        requestAnimationFrame(batch);
      } catch (e) {
        fail('rt export-web: ' + e.message);
      }
    };
    batch();
  }

  // The frame time, as rt view's HUD shows it; a WebGL error goes to the console.
  let frames = 0;
  function showFrameTime(ms) {
    const error = gl.getError();
    if (error !== gl.NO_ERROR) console.error('rt export-web: WebGL error 0x' + error.toString(16));
    ++frames;
    frameTime.textContent = 'frame ' + frames + ': ' + ms.toFixed(1) + ' ms (' +
      (1000 / Math.max(ms, 0.1)).toFixed(1) + ' fps)' +
      (samples ? ', ' + samples.total + ' samples a pixel' : '') + ', ' + data.width + 'x' +
      data.height + ' on ' + renderer;
  }
  function redraw() {
    if (!program) return;
    draw((ms) => {
      showFrameTime(ms);
      if (controls) controls.drawn();
    });
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

  // The frame on the canvas, top row first, opaque (alpha held the stubs), as ImageData and as a
  // PNG data URL the test can write and compare; a WebGL error throws.
  function readFrame(report) {
    const rgba = new Uint8Array(data.width * data.height * 4);
    gl.readPixels(0, 0, data.width, data.height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    const error = gl.getError();
    if (error !== gl.NO_ERROR) throw new Error('WebGL error 0x' + error.toString(16));
    const stubs = report ? reportStubs(rgba) : 0;
    const image = new ImageData(data.width, data.height);
    const row = data.width * 4;
    for (let y = 0; y < data.height; ++y)  // readPixels' rows are bottom first
      image.data.set(rgba.subarray((data.height - 1 - y) * row, (data.height - y) * row), y * row);
    for (let i = 3; i < image.data.length; i += 4) image.data[i] = 255;
    const canvas = document.createElement('canvas');
    canvas.width = data.width;
    canvas.height = data.height;
    canvas.getContext('2d').putImageData(image, 0, 0);
    return { image: image, stubs: stubs, url: canvas.toDataURL('image/png') };
  }
  // For the test: the latest frame, after a click on the panel has drawn it (synchronously).
  window.__rtFrame = () => readFrame(false).url;

  let controls = null;
  function start() {
    const t0 = performance.now();
    try {
      samples = rtSamples(gl, data, kVertexShader, compile);
      program = link();
      uploadDataTextures(program);
      if (samples) samples.attach(program);
      draw((drawMs) => {  // the first frame, every sample in, for the test
        const first = readFrame(true);
        window.__rtPixels = first.url;
        const ms = Math.round(performance.now() - t0);
        status.textContent = 'First frame ' + data.width + 'x' + data.height + ' in ' + ms +
          ' ms (compile and draw) on ' + renderer +
          (first.stubs ? '; magenta pixels reached stubs (see the console)' : '') + '.';
        controls = rtControls({ data: data, settings: settings, view: view, redraw: redraw,
          readFrame: readFrame, live: live, scale: scale, status: status,
          changed: () => settingsChanged() || view.changed() });
        showFrameTime(drawMs);
        window.__rtDone = { ok: true, renderer: renderer, ms: ms };
      });
    } catch (e) {
      fail('rt export-web: ' + e.message);
    }
  }

  // Let the page paint "Compiling..." before the (blocking) compile.
  requestAnimationFrame(() => setTimeout(start, 0));
})();
