// rt export-web's depth and BVH-visit views (framework/render/gpu/web_export.h). As rt render
// maps them (render/render.cpp's map_depth and map_visits), a pixel's grey or heat colour depends
// on the whole image's range: the stage 09 shader writes each pixel's hit distance or node count
// (trace_pixel's a; -1 nothing, -2 a stub) into a float image, the page reads it back, finds the
// nearest and farthest hit (or the most visits), and a small second shader maps every pixel.
function rtRanges(gl, data, vertexShader, compile) {
  // The heat ramp's five stops are render.cpp's heat_color.
  const kMapShader = '#version 300 es\nprecision highp float;\n' +
    'uniform highp sampler2D values;\nuniform int visits;\n' +
    'uniform float near;\nuniform float span;\nuniform float most;\nout vec4 color;\n' +
    'const vec3 kStops[5] = vec3[5](vec3(0.0, 0.0, 0.02), vec3(0.34, 0.06, 0.43),\n' +
    '    vec3(0.73, 0.21, 0.33), vec3(0.97, 0.56, 0.04), vec3(0.99, 1.0, 0.64));\n' +
    'vec3 heat(float v) {\n    v = clamp(v, 0.0, 1.0) * 4.0;\n    int i = min(3, int(v));\n' +
    '    return mix(kStops[i], kStops[i + 1], v - float(i));\n}\n' +
    'void main() {\n' +
    '    vec4 p = texelFetch(values, ivec2(gl_FragCoord.xy), 0);\n' +
    '    vec3 c = vec3(0.0);\n' +
    '    if (p.r == -2.0) c = vec3(1.0, 0.0, 1.0);\n' +
    '    else if (p.r >= 0.0 && visits == 0) c = vec3(1.0 - 0.8 * (p.r - near) / span);\n' +
    '    else if (p.r >= 0.0) c = heat(p.r / most);\n' +
    '    color = vec4(c, p.a);  // a: the stub the pixel reached (the wrapper\'s)\n}\n';
  let map = null, values = null, framebuffer = null;

  function setUp() {
    if (!gl.getExtension('EXT_color_buffer_float'))
      throw new Error('this browser cannot draw into float images (EXT_color_buffer_float), ' +
        'which the depth and BVH-visit views need');
    values = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, values);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, data.width, data.height);
    framebuffer = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, values, 0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    map = gl.createProgram();
    gl.attachShader(map, compile(gl.VERTEX_SHADER, vertexShader, 'vertex shader'));
    gl.attachShader(map, compile(gl.FRAGMENT_SHADER, kMapShader, 'depth and visits shader'));
    gl.linkProgram(map);
    if (!gl.getProgramParameter(map, gl.LINK_STATUS))
      throw new Error('the depth and visits shader does not link: ' + gl.getProgramInfoLog(map));
  }

  // map_depth's [nearest, farthest] hit, map_visits' largest count (at least 1).
  function range(pixels, visits) {
    let near = Infinity, far = 0, most = 1;
    for (let i = 0; i < pixels.length; i += 4) {
      const v = pixels[i];
      if (v < 0) continue;
      near = Math.min(near, v);
      far = Math.max(far, v);
      most = Math.max(most, v);
    }
    return { near: near, span: far > near ? far - near : 1, most: most, visits: visits };
  }

  return {
    // `drawValues()` draws the stage 09 shader in that mode into the bound framebuffer; the
    // mapped image goes on the canvas.
    draw(drawValues, visits) {
      if (!map) setUp();
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.viewport(0, 0, data.width, data.height);
      drawValues();
      const pixels = new Float32Array(data.width * data.height * 4);
      gl.readPixels(0, 0, data.width, data.height, gl.RGBA, gl.FLOAT, pixels);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      const r = range(pixels, visits);
      gl.useProgram(map);
      gl.activeTexture(gl.TEXTURE0 + 14);
      gl.bindTexture(gl.TEXTURE_2D, values);
      const at = (name) => gl.getUniformLocation(map, name);
      gl.uniform1i(at('values'), 14);
      gl.uniform1i(at('visits'), r.visits ? 1 : 0);
      gl.uniform1f(at('near'), r.near);
      gl.uniform1f(at('span'), r.span);
      gl.uniform1f(at('most'), r.most);
      gl.viewport(0, 0, data.width, data.height);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    },
  };
}
