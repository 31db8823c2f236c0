// rt export-web's camera (framework/render/gpu/web_export.h): camera/camera_moves.cpp's orbit,
// pan, zoom and set_projection, in doubles, as `rt view` moves its camera. The page script
// (page.js) draws with camera(); page_controls.js moves it.
function rtCamera(data) {
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
  const mul = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
    a[0] * b[1] - a[1] * b[0]];
  const normalize = (a) => mul(a, 1 / Math.sqrt(dot(a, a)));
  const kDegrees = Math.PI / 180;
  function rotate(x, axis, degrees) {  // Rodrigues' formula
    const k = normalize(axis), t = degrees * kDegrees, c = Math.cos(t), s = Math.sin(t);
    return add(add(mul(x, c), mul(cross(k, x), s)), mul(k, dot(k, x) * (1 - c)));
  }
  const clone = (x) => JSON.parse(JSON.stringify(x));
  const initial = clone(data.camera);
  const up = initial.v;  // orbits keep the scene camera's up, so the horizon never rolls
  let camera = clone(initial), pivotDistance = data.pivot_distance;
  const kOrthographic = 1;

  function lookAt(eye, target) {
    const w = normalize(sub(eye, target)), u = normalize(cross(up, w));
    Object.assign(camera, { eye: eye, u: u, v: cross(w, u), w: w });
  }
  // The height of the view at the pivot, in scene units (what a pan of 1 moves).
  function viewHeight() {
    return camera.projection === kOrthographic ? camera.view_height
      : 2 * pivotDistance * Math.tan(camera.vertical_fov_degrees * kDegrees / 2);
  }

  return {
    camera: () => camera,
    changed: () => JSON.stringify(camera) !== JSON.stringify(initial),
    reset() { camera = clone(initial); pivotDistance = data.pivot_distance; },
    orbit(yaw, pitch) {
      const pivot = sub(camera.eye, mul(camera.w, pivotDistance));
      let offset = rotate(sub(camera.eye, pivot), up, -yaw);
      const pitched = rotate(offset, normalize(cross(up, offset)), pitch);
      if (Math.abs(dot(normalize(pitched), up)) < 0.998) offset = pitched;
      lookAt(add(pivot, offset), pivot);
    },
    pan(right, upward) {  // fractions of the view's height, as rt view's right drag
      const h = viewHeight();
      camera.eye = add(camera.eye, add(mul(camera.u, right * h), mul(camera.v, upward * h)));
    },
    zoom(factor) {
      if (camera.projection === kOrthographic) { camera.view_height *= factor; return; }
      const pivot = sub(camera.eye, mul(camera.w, pivotDistance));
      pivotDistance = Math.max(pivotDistance * factor, 1e-3);
      camera.eye = add(pivot, mul(camera.w, pivotDistance));
    },
    toggleProjection() {  // rt view's P: the same view height at the pivot
      if (camera.projection === kOrthographic) {
        const fov = 2 * Math.atan(camera.view_height / (2 * pivotDistance)) / kDegrees;
        camera.vertical_fov_degrees = Math.min(170, Math.max(1, fov));
        camera.projection = 0;
      } else {
        camera.view_height = viewHeight();
        camera.projection = kOrthographic;
      }
    },
    // rt view's W writes this into the scene file; the page shows it to paste there.
    sceneJson() {
      const r = (v) => v.map((x) => Number(x.toPrecision(9)));
      const c = { eye: r(camera.eye), look_at: r(sub(camera.eye, mul(camera.w, pivotDistance))),
        up: r(camera.v) };
      if (camera.projection === kOrthographic) {
        c.projection = 'orthographic';
        c.view_height = Number(camera.view_height.toPrecision(9));
      } else {
        c.fov = Number(camera.vertical_fov_degrees.toPrecision(9));
      }
      return '"camera": ' + JSON.stringify(c);
    },
  };
}
