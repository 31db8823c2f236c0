// rt export-web's panel, keys and mouse (framework/render/gpu/web_export.h), as `rt view`'s
// (framework/view/viewer_panel.cpp, viewer_window.cpp): the mode, shadows, the bounces, each
// Blinn-Phong term, reflection, refraction and Fresnel switch what the shader computes (uniforms,
// never a post-process); drag orbits, right or middle drag pans, the wheel zooms; the keys R, P,
// W and S reset the camera, switch the projection, show the camera to paste into the scene file
// and save a screenshot. The CPU render and its difference from the live frame show on request.
function rtControls(ctx) {
  const { data, settings, view, live, scale } = ctx;
  const panel = data.settings;
  const kOrbitDegreesPerPixel = 0.3, kZoomPerWheelStep = 0.9;  // rt view's (viewer_window.cpp)
  const root = document.getElementById('panel');
  let showingReference = false;

  function changed() {
    ctx.redraw();
  }
  function add(parent, tag, props) {
    const e = document.createElement(tag);
    Object.assign(e, props || {});
    parent.appendChild(e);
    return e;
  }
  function checkbox(parent, name, label, disabled, title) {
    const l = add(parent, 'label', { title: title || '' });
    // A disabled switch shows what the page draws: no environment is drawn unchecked.
    const box = add(l, 'input', { type: 'checkbox', id: 'toggle-' + name,
      checked: !!settings[name] && !(disabled && !panel.has_environment), disabled: !!disabled });
    l.appendChild(document.createTextNode(label));
    box.addEventListener('change', () => { settings[name] = box.checked; changed(); });
  }

  function buildPanel() {
    const row1 = add(root, 'div');
    add(row1, 'label', { textContent: 'mode ', htmlFor: 'mode' });
    const mode = add(row1, 'select', { id: 'mode', disabled: panel.modes.length < 2 });
    for (const m of panel.modes) add(mode, 'option', { value: m.name, textContent: m.name });
    mode.value = settings.mode;
    mode.addEventListener('change', () => { settings.mode = mode.value; changed(); });
    checkbox(row1, 'shadows', 'shadows');
    const depthLabel = add(row1, 'label', { htmlFor: 'max-depth',
      textContent: ' max depth ' + settings.max_depth + ' ' });
    const depth = add(row1, 'input', { type: 'range', id: 'max-depth', min: 0,
      max: panel.max_depth, value: settings.max_depth, disabled: panel.max_depth === 0,
      title: 'up to the scene\'s own (the shader is compiled for that many bounces)' });
    depth.addEventListener('input', () => {
      settings.max_depth = Number(depth.value);
      depthLabel.textContent = ' max depth ' + settings.max_depth + ' ';
      changed();
    });
    const row2 = add(root, 'div');
    for (const term of ['ambient', 'diffuse', 'specular', 'emissive']) checkbox(row2, term, term);
    const row3 = add(root, 'div');
    checkbox(row3, 'reflection', 'reflection');
    checkbox(row3, 'refraction', 'refraction');
    checkbox(row3, 'fresnel', 'Fresnel');
    checkbox(row3, 'environment', 'environment', !panel.has_environment,
      panel.has_environment ? '' : 'this scene has no environment');
  }

  // --- The keys and buttons of rt view ---
  let screenshots = 0;
  const actions = {
    R: () => { view.reset(); changed(); },
    P: () => { view.toggleProjection(); changed(); },
    W: () => {
      const text = view.sceneJson();
      document.getElementById('camera-json').textContent = text;
      ctx.status.textContent = 'The camera, for the scene file (rt view\'s W writes it there):';
      if (navigator.clipboard) navigator.clipboard.writeText(text).catch(() => {});
    },
    S: () => {
      const a = document.createElement('a');
      a.href = ctx.readFrame().url;
      a.download = 'screenshot-' + String(++screenshots).padStart(3, '0') + '.png';
      a.click();
      ctx.status.textContent = 'Saved ' + a.download + ' (the live frame).';
    },
  };
  document.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey || e.target.tagName === 'SELECT') return;
    const action = actions[e.key.toUpperCase()];
    if (action) { e.preventDefault(); action(); }
  });
  const buttons = [['reset', 'R'], ['projection', 'P'], ['write-camera', 'W'],
    ['screenshot', 'S']];
  for (const [id, key] of buttons)
    document.getElementById(id).addEventListener('click', actions[key]);

  // --- The mouse ---
  let dragging = null, pending = false;
  function later() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => { pending = false; ctx.redraw(); });
  }
  live.addEventListener('contextmenu', (e) => e.preventDefault());
  live.addEventListener('mousedown', (e) => {
    dragging = { x: e.clientX, y: e.clientY, pan: e.button !== 0 };
    e.preventDefault();
  });
  window.addEventListener('mouseup', () => { dragging = null; });
  window.addEventListener('mousemove', (e) => {
    if (!dragging) return;
    const dx = e.clientX - dragging.x, dy = e.clientY - dragging.y;
    if (dragging.pan) {
      const height = data.height * scale;  // the image's height on screen, as rt view's pan
      view.pan(-dx / height, dy / height);
    } else {
      view.orbit(dx * kOrbitDegreesPerPixel, dy * kOrbitDegreesPerPixel);
    }
    Object.assign(dragging, { x: e.clientX, y: e.clientY });
    later();
  });
  live.addEventListener('wheel', (e) => {
    e.preventDefault();
    view.zoom(Math.pow(kZoomPerWheelStep, e.deltaY < 0 ? 1 : -1));
    later();
  }, { passive: false });

  // --- The CPU render beside the live canvas, and the live frame's difference from it ---
  let reference = null;  // its pixels, once the image has loaded
  function showDifference() {
    if (!showingReference || !reference) return;
    const frame = ctx.readFrame().image.data;
    const out = new ImageData(data.width, data.height);
    for (let i = 0; i < reference.length; ++i)  // a picture for the eye, not the test's metric
      out.data[i] = i % 4 === 3 ? 255 : Math.min(255, 8 * Math.abs(frame[i] - reference[i]));
    document.getElementById('difference').getContext('2d').putImageData(out, 0, 0);
    document.getElementById('difference-caption').textContent =
      '|WebGL - CPU| x 8' + (ctx.changed()
        ? ': settings or camera changed, and the CPU render is of the scene file\'s' : '');
  }
  function toggleReference() {
    if (!data.reference) { ctx.status.textContent = 'This page holds no CPU render.'; return; }
    showingReference = !showingReference;
    document.getElementById('reference-figure').hidden = !showingReference;
    document.getElementById('difference-figure').hidden = !showingReference;
    document.getElementById('compare').textContent = showingReference
      ? 'Hide the CPU render' : 'Show the CPU render and the difference';
    if (reference || !showingReference) { showDifference(); return; }
    const img = document.getElementById('reference');
    img.style.width = data.width * scale + 'px';
    img.onload = () => {
      const c = document.createElement('canvas');
      c.width = data.width;
      c.height = data.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      reference = g.getImageData(0, 0, data.width, data.height).data;
      showDifference();
    };
    img.src = data.reference;
  }
  document.getElementById('compare').addEventListener('click', toggleReference);

  buildPanel();
  return { drawn: showDifference };
}
