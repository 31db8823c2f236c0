// rt export-web's stage 10 (framework/render/gpu/web_export.h): a scene of several camera samples
// a pixel. As trace.comp's dispatches do, each draw of the stage 09 shader adds a few samples
// (sample_first, sample_count) of every pixel; here they add up by blending into a float
// framebuffer (rgb added, alpha, where the shader marks a stub, the least), and a second small
// shader shows the mean, sRGB-encoded as rt render writes it.
function rtSamples(gl, data, vertexShader, compile) {
  const sampled = data.sampled;
  if (!sampled) return null;
  if (!gl.getExtension('EXT_color_buffer_float'))
    throw new Error('this browser cannot draw into float images (EXT_color_buffer_float), which ' +
      'adding up stage 10\'s camera samples needs');
  // 32-bit sums where the browser can blend them, else 16-bit (enough for a mean of 8 bits).
  const format = gl.getExtension('EXT_float_blend') ? gl.RGBA32F : gl.RGBA16F;

  const sums = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, sums);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.texStorage2D(gl.TEXTURE_2D, 1, format, data.width, data.height);
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, sums, 0);
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE)
    throw new Error('this browser cannot draw into a float image of ' + data.width + 'x' +
      data.height);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);

  // The mean, encoded as image/image.cpp's linear_to_srgb (the wrapper's rt_encode_srgb).
  const kMeanShader = '#version 300 es\nprecision highp float;\n' +
    'uniform highp sampler2D sums;\nuniform float count;\nout vec4 color;\n' +
    'float encode(float x) {\n' +
    '    if (!(x > 0.0)) return 0.0;\n    if (x >= 1.0) return 1.0;\n' +
    '    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;\n}\n' +
    'void main() {\n' +
    '    vec4 sum = texelFetch(sums, ivec2(gl_FragCoord.xy), 0);\n' +
    '    vec3 mean = sum.rgb / count;\n' +
    '    color = vec4(encode(mean.r), encode(mean.g), encode(mean.b), sum.a);\n}\n';
  const mean = gl.createProgram();
  gl.attachShader(mean, compile(gl.VERTEX_SHADER, vertexShader, 'vertex shader'));
  gl.attachShader(mean, compile(gl.FRAGMENT_SHADER, kMeanShader, 'mean of the samples shader'));
  gl.linkProgram(mean);
  if (!gl.getProgramParameter(mean, gl.LINK_STATUS))
    throw new Error('the mean of the samples does not link: ' + gl.getProgramInfoLog(mean));

  // The scene's uniform block SampledScene, the bytes rt render --gpu uploads.
  const block = gl.createBuffer();
  gl.bindBuffer(gl.UNIFORM_BUFFER, block);
  gl.bufferData(gl.UNIFORM_BUFFER,
    Uint8Array.from(atob(sampled.block), (c) => c.charCodeAt(0)), gl.STATIC_DRAW);
  gl.bindBufferBase(gl.UNIFORM_BUFFER, 0, block);

  return {
    // Binds the block to the stage 09 program (once it is linked).
    attach(program) {
      gl.uniformBlockBinding(program, gl.getUniformBlockIndex(program, 'SampledScene'), 0);
    },
    // The progressive display: begin() empties the sums; each step(drawSamples) draws one batch
    // of camera samples (`drawSamples(first, count)` into the bound framebuffer), shows the mean
    // of all drawn so far on the canvas and says whether every sample is in.
    total: sampled.samples_per_pixel,
    drawn: 0,
    begin() {
      this.drawn = 0;
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.clearColor(0, 0, 0, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    },
    step(drawSamples) {
      const count = Math.min(sampled.samples_per_frame, this.total - this.drawn);
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.viewport(0, 0, data.width, data.height);
      gl.enable(gl.BLEND);
      gl.blendEquationSeparate(gl.FUNC_ADD, gl.MIN);
      gl.blendFunc(gl.ONE, gl.ONE);
      drawSamples(this.drawn, count);
      this.drawn += count;
      gl.disable(gl.BLEND);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.useProgram(mean);
      gl.activeTexture(gl.TEXTURE0 + 15);
      gl.bindTexture(gl.TEXTURE_2D, sums);
      gl.uniform1i(gl.getUniformLocation(mean, 'sums'), 15);
      gl.uniform1f(gl.getUniformLocation(mean, 'count'), this.drawn);
      gl.viewport(0, 0, data.width, data.height);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      return this.drawn >= this.total;
    },
  };
}
