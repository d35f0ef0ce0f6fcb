// The page's WebGL 2 renderer: hexc's GLSL ES 3.00 fragment shaders with the vertex stage of templates/edit, their
// parameter blocks laid out as their manifests say, and the textures the manifests name. The server sends two: the
// material's views (templates/edit/views.glsl), linked three times as the hex-tiled view and the shown slot's weights
// and values, and plain tiling.
import * as geometry from './geometry.js';

// The views' specialisation constants (templates/edit/views.glsl), as SPIRV-Cross's GLSL ES leaves them: macros.
const kViewMacro = 'SPIRV_CROSS_CONSTANT_ID_1000', kSlotMacro = 'SPIRV_CROSS_CONSTANT_ID_1001';
const kViews = { hex: 0, values: 1, weights: 2, layer: 3 };

// Linked programs kept by their sources: a structure seen before in the session (an undo, a setting switched back, a
// slot selected again) links nothing, and the driver keeps the shaders it compiled for them. A structure is four
// programs (plain tiling and three views).
const kLinkedPrograms = 32;

// The templates' own light direction (templates/builtin/lit.glsl): the page turns the frame to move the light.
const kTemplateLight = (() => { const l = Math.hypot(1, 1, 2); return [1 / l, 1 / l, 2 / l]; })();

export class View {
  // `shaders`: templates/edit's sources by file name (view.vert.glsl, display.vert.glsl, display.frag.glsl).
  constructor(canvas, shaders) {
    this.canvas = canvas;
    this.gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
    if (!this.gl) throw new Error('this browser has no WebGL 2');
    this.vertexSource = shaders['view.vert.glsl'];
    this.floatRender = !!this.gl.getExtension('EXT_color_buffer_float');
    this.floatLinear = !!this.gl.getExtension('OES_texture_float_linear');
    this.programs = {};
    this.linked = new Map();  // linked programs by their sources (linkedProgram)
    this.generation = 0;      // setPrograms' calls: a later one supersedes an earlier one still linking
    this.parallel = this.gl.getExtension('KHR_parallel_shader_compile');
    this.live = new Map();  // parameters set since the programs' compile (setParam), which a program linked again keeps
    this.textures = {};  // by URL name: "albedo", "albedo.gaussian", "albedo.lut"
    this.meshes = {};
    this.display = this.compileProgram('display', shaders['display.vert.glsl'], shaders['display.frag.glsl']);
  }

  // Compiles and links a program, waiting for it (the display pass's, at start).
  compileProgram(name, vertex, fragment) {
    const program = this.startLink(vertex, fragment);
    this.linkResult(name, program);
    return program;
  }

  // Starts compiling and linking a program; with KHR_parallel_shader_compile the driver does it beside the page's
  // frames, which keep drawing the programs they have until linkResult() is asked (see ready()).
  startLink(vertex, fragment) {
    const gl = this.gl, program = gl.createProgram();
    for (const [type, source] of [[gl.VERTEX_SHADER, vertex], [gl.FRAGMENT_SHADER, fragment]]) {
      const s = gl.createShader(type);
      gl.shaderSource(s, source);
      gl.compileShader(s);
      gl.attachShader(program, s);
      gl.deleteShader(s);  // freed with the program
    }
    gl.linkProgram(program);
    return program;
  }

  // Whether a program started by startLink() is linked, asked without waiting for it (always true without the
  // extension: asking for the link status then waits).
  ready(program) {
    return !this.parallel || this.gl.getProgramParameter(program, this.parallel.COMPLETION_STATUS_KHR);
  }

  // Throws an Error with WebGL's log if the program did not link (its shaders' logs first: they say why).
  linkResult(name, program) {
    const gl = this.gl;
    if (gl.getProgramParameter(program, gl.LINK_STATUS)) return;
    const logs = gl.getAttachedShaders(program).filter(s => !gl.getShaderParameter(s, gl.COMPILE_STATUS)).map(s => gl.getShaderInfoLog(s));
    gl.deleteProgram(program);
    throw new Error(logs.length ? `WebGL could not compile the ${name} program: ${logs.join('\n')}`
                                : `WebGL could not link the ${name} program: ${gl.getProgramInfoLog(program)}`);
  }

  // Links each program, the views for `shown.slot` (a name in the server's `slots`) and, when `shown.layer` is a
  // layer's index, its weight and the splat map that holds it, and makes them the ones drawn; a program linked before
  // in this session (the same sources) is taken from this.linked, linking nothing. Resolves false if a later call
  // superseded this one, and throws an Error with WebGL's log if a program does not link (the programs drawn stay as
  // they were).
  async setPrograms(programs, slots, shown) {
    const generation = ++this.generation;
    const wanted = [];
    if (programs.plain.fragment) wanted.push(['plain', programs.plain, '']);
    if (programs.views.fragment) {
      const view = (name, kind, index) => wanted.push([name, programs.views, `#define ${kViewMacro} ${kind}\n#define ${kSlotMacro} ${index}\n`]);
      const index = Math.max(0, slots.indexOf(shown.slot));
      view('hex', kViews.hex, 0);  // the template's own shading shows no slot: one program whichever is selected
      view('values', kViews.values, index);
      view('weights', kViews.weights, index);
      if (shown.layer !== undefined) {
        view('layer', kViews.layer, shown.layer);
        // The splat map as the layers read it: its slot's values (hexc names the maps' slots splat0, splat1).
        const splat = slots.indexOf(`splat${Math.floor(shown.layer / 4)}`);
        if (splat >= 0) view('splat', kViews.values, splat);
      }
    }
    const linked = wanted.map(([name, p, defines]) => this.linkedProgram(p, defines));
    while (!linked.every(l => l.ready || (l.ready = this.ready(l.program)))) await new Promise(requestAnimationFrame);
    if (generation !== this.generation) return false;
    const built = {};
    wanted.forEach(([name, p], i) => {
      const l = linked[i];
      if (!l.uniforms) {
        try { this.linkResult(name, l.program); } catch (e) { this.linked.delete(l.key); throw e; }
        this.describe(l, p.manifest);
      }
      built[name] = { ...l, block: this.block(p.manifest), manifest: p.manifest };
    });
    for (const p of Object.values(this.programs)) this.gl.deleteBuffer(p.block.buffer);
    this.programs = built;
    this.evict();
    return true;
  }

  // The program of `p.fragment` with `defines` after its #version line, from this.linked or started now (the most
  // recently used is last in the map).
  linkedProgram(p, defines) {
    const after = (source, text) => { const lines = source.split('\n'); return [lines[0], text + lines.slice(1).join('\n')].join('\n'); };
    const painted = p.manifest.layers?.vertex_color?.input;  // the vertex colour, which the page paints
    const inputs = p.manifest.targets.glsl.inputs
      .map(i => `#define ${i.name === painted ? 'HEXC_VERTEX_COLOR' : `HEXC_INPUT_${i.location}`} ${i.name}\n`).join('');
    const vertex = after(this.vertexSource, inputs), fragment = after(p.fragment, defines), key = `${vertex}\0${fragment}`;
    const known = this.linked.get(key);
    this.linked.delete(key);
    this.linked.set(key, known || { key, program: this.startLink(vertex, fragment) });
    return this.linked.get(key);
  }

  // Frees the least recently used programs past kLinkedPrograms that are not drawn.
  evict() {
    const drawn = new Set(Object.values(this.programs).map(p => p.program));
    for (const [key, l] of this.linked) {
      if (this.linked.size <= kLinkedPrograms) break;
      if (drawn.has(l.program)) continue;
      this.gl.deleteProgram(l.program);
      this.linked.delete(key);
    }
  }

  // What a linked program's draws look up once: its uniforms, its block's binding and its textures' units.
  describe(l, manifest) {
    const gl = this.gl, glsl = manifest.targets.glsl;
    const index = gl.getUniformBlockIndex(l.program, manifest.parameters.block);
    if (index !== gl.INVALID_INDEX) gl.uniformBlockBinding(l.program, index, 0);
    l.uniforms = {};
    for (const u of ['u_viewProjection', 'u_light', 'u_uvScale', 'u_flat']) l.uniforms[u] = gl.getUniformLocation(l.program, u);
    l.textures = Object.entries(glsl.textures).map(([key, t]) => ({ source: this.textureSource(manifest, key), unit: t.texture_unit,
                                                                    location: gl.getUniformLocation(l.program, t.uniform) }));
  }

  // The parameter block of a manifest, its members set to the manifest's values.
  block(manifest) {
    const params = manifest.parameters;
    const block = { data: new DataView(new ArrayBuffer(Math.max(16, params.size))), buffer: this.gl.createBuffer(), members: params.members };
    for (const m of params.members) this.write(block, m, m.value);
    for (const [name, value] of this.live) {
      const m = params.members.find(m => m.name === name || (m.aliases || []).includes(name));
      if (m) this.write(block, m, value);
    }
    return block;
  }

  // Where a program's texture comes from: a histogram slot reads hexc's Gaussian texture in place of its own.
  textureSource(manifest, key) {
    if (key.endsWith('.lut')) return key;
    const slot = manifest.slots.find(s => s.name === key);
    return slot && slot.histogram ? `${key}.gaussian` : key;
  }

  // Every texture the programs read, by the name the server gives it.
  textureSources() {
    const all = new Set();
    for (const p of Object.values(this.programs)) for (const t of p.textures) all.add(t.source);
    return [...all];
  }

  write(block, member, value) {
    const v = Array.isArray(value) ? value : Array(member.type.endsWith('vec2') ? 2 : 1).fill(value);  // `tiling: 4` is [4, 4]
    const int = member.type.startsWith('i');
    v.forEach((x, i) => int ? block.data.setInt32(member.offset + 4 * i, x, true) : block.data.setFloat32(member.offset + 4 * i, x, true));
    block.dirty = true;
  }

  // The member of the hex-tiled program a setting is (by the name `<slot>_<setting>` or an alias), or undefined: a
  // setting that is not a member changes the shader's structure.
  member(name) {
    const hex = this.programs.hex;
    return hex && hex.block.members.find(m => m.name === name || (m.aliases || []).includes(name));
  }

  // Sets a parameter in every program that has it, and in those linked before the next compile.
  setParam(name, value) {
    this.live.set(name, value);
    for (const p of Object.values(this.programs)) {
      const m = p.block.members.find(m => m.name === name || (m.aliases || []).includes(name));
      if (m) this.write(p.block, m, value);
    }
  }

  // Uploads texels the server sent: 8-bit or float RGBA, with a full mip chain unless it is a look-up table.
  setTexture(name, info) {
    const gl = this.gl;
    const old = this.textures[name];
    const t = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    const lut = name.endsWith('.lut');
    if (info.format === 'rgba32f') {
      const format = this.floatLinear && this.floatRender ? gl.RGBA32F : gl.RGBA16F;
      gl.texImage2D(gl.TEXTURE_2D, 0, format, info.width, info.height, 0, gl.RGBA, gl.FLOAT, new Float32Array(info.texels));
    } else {
      gl.texImage2D(gl.TEXTURE_2D, 0, info.srgb ? gl.SRGB8_ALPHA8 : gl.RGBA8, info.width, info.height, 0, gl.RGBA, gl.UNSIGNED_BYTE,
                    new Uint8Array(info.texels));
    }
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, lut ? gl.LINEAR : gl.LINEAR_MIPMAP_LINEAR);
    if (!lut) gl.generateMipmap(gl.TEXTURE_2D);
    this.textures[name] = t;
    if (old) gl.deleteTexture(old);
  }

  // The mesh `name` as `make` builds it, built again only when make.key changes; the one it replaces is freed.
  mesh(name, make) {
    const old = this.meshes[name];
    if (old && old.key === make.key) return old;
    const gl = this.gl, m = make();
    const vao = gl.createVertexArray(), buffers = [];
    gl.bindVertexArray(vao);
    [[m.positions, 3], [m.normals, 3], [m.tangents, 4], [m.uvs, 2]].forEach(([data, size], location) => {
      gl.bindBuffer(gl.ARRAY_BUFFER, buffers[buffers.push(gl.createBuffer()) - 1]);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(data), gl.STATIC_DRAW);
      gl.enableVertexAttribArray(location);
      gl.vertexAttribPointer(location, size, gl.FLOAT, false, 0, 0);
    });
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, buffers[buffers.push(gl.createBuffer()) - 1]);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint32Array(m.indices), gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    if (old) {
      gl.deleteVertexArray(old.vao);
      old.buffers.forEach(b => gl.deleteBuffer(b));
    }
    this.meshes[name] = { vao, buffers, count: m.indices.length, key: make.key };
    return this.meshes[name];
  }

  // The camera and mesh of a view state: {shape, camera: {azimuth, elevation, distance}, rect} (angles in degrees).
  scene(s, aspect) {
    const rad = Math.PI / 180;
    if (s.shape === 'flat') {
      const make = () => geometry.flat(s.rect);
      make.key = s.rect.join(',');
      return { mesh: this.mesh('flat', make), matrix: geometry.flatProjection(s.rect), uvScale: 1, depth: false, flat: true };
    }
    const { azimuth, elevation, distance } = s.camera;
    const e = elevation * rad, a = azimuth * rad;
    const target = s.shape === 'plane' ? [s.camera.x || 0, s.camera.y || 0, 0] : [0, 0, 0];
    const eye = [target[0] + distance * Math.cos(e) * Math.cos(a), target[1] + distance * Math.cos(e) * Math.sin(a), target[2] + distance * Math.sin(e)];
    const far = s.shape === 'plane' ? distance * 400 : distance + 4;
    const matrix = geometry.multiply(geometry.perspective(45 * rad, aspect, distance * 0.01, far), geometry.lookAt(eye, target, [0, 0, 1]));
    // The plane reaches 200 camera distances away, in powers of two: zooming builds a new one only past a doubling.
    const extent = Math.pow(2, Math.ceil(Math.log2(Math.max(64, distance * 200))));
    const make = { plane: () => geometry.plane(extent), sphere: geometry.sphere, cube: geometry.cube }[s.shape];
    make.key = s.shape === 'plane' ? String(extent) : s.shape;
    return { mesh: this.mesh(s.shape, make), matrix, uvScale: s.shape === 'plane' ? 1 : s.uvScale || 1, depth: s.shape !== 'plane' };
  }

  lightRotation(s, flat) {
    if (flat) return new Float32Array([1, 0, 0, 0, 1, 0, 0, 0, 1]);  // the templates' own light, as hexc render shows it
    const rad = Math.PI / 180, e = s.light.elevation * rad, a = s.light.azimuth * rad;
    return geometry.rotationBetween([Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)], kTemplateLight);
  }

  // Draws the view state: `regions`, [program name, left, right] in fractions of the width, side by side, into the
  // linear frame, then shows it on the canvas sRGB-encoded (templates/edit/display.frag.glsl).
  draw(s, regions) {
    const gl = this.gl, width = this.canvas.width, height = this.canvas.height;
    if (!this.frame || this.frame.width !== width || this.frame.height !== height) {
      if (this.frame) this.frame.release();
      this.frame = this.target(this.floatRender ? gl.RGBA16F : gl.RGBA8, width, height);
    }
    this.render(s, regions, this.frame);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, width, height);
    gl.disable(gl.DEPTH_TEST);
    gl.useProgram(this.display);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.frame.color);
    gl.uniform1i(gl.getUniformLocation(this.display, 'u_frame'), 0);
    gl.bindVertexArray(null);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  // A framebuffer of `format` colour (nearest filtering: the display pass reads it texel for texel) and depth.
  target(format, width, height) {
    const gl = this.gl;
    const color = gl.createTexture(), depth = gl.createRenderbuffer(), framebuffer = gl.createFramebuffer();
    gl.bindTexture(gl.TEXTURE_2D, color);
    gl.texStorage2D(gl.TEXTURE_2D, 1, format, width, height);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
    gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, color, 0);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
    const release = () => { gl.deleteFramebuffer(framebuffer); gl.deleteTexture(color); gl.deleteRenderbuffer(depth); };
    return { framebuffer, color, width, height, release };
  }

  render(s, regions, target) {
    const gl = this.gl, width = target.width, height = target.height;
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
    gl.viewport(0, 0, width, height);
    gl.disable(gl.SCISSOR_TEST);
    gl.clearColor(0.18, 0.18, 0.2, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    const sc = this.scene(s, width / height), light = this.lightRotation(s, sc.flat);
    gl.enable(gl.SCISSOR_TEST);
    for (const [name, left, right] of regions) {
      const p = this.programs[name];
      if (!p) continue;
      const x0 = Math.round(left * width), x1 = Math.round(right * width);
      gl.scissor(x0, 0, x1 - x0, height);
      gl.useProgram(p.program);
      gl.uniformMatrix4fv(p.uniforms.u_viewProjection, false, sc.matrix);
      gl.uniformMatrix3fv(p.uniforms.u_light, false, light);
      gl.uniform1f(p.uniforms.u_uvScale, sc.uvScale);
      gl.uniform1i(p.uniforms.u_flat, sc.flat ? 1 : 0);
      gl.bindBuffer(gl.UNIFORM_BUFFER, p.block.buffer);
      if (p.block.dirty) gl.bufferData(gl.UNIFORM_BUFFER, p.block.data, gl.DYNAMIC_DRAW);
      p.block.dirty = false;
      gl.bindBufferBase(gl.UNIFORM_BUFFER, 0, p.block.buffer);
      for (const t of p.textures) {
        gl.activeTexture(gl.TEXTURE0 + t.unit);
        gl.bindTexture(gl.TEXTURE_2D, this.textures[t.source] || null);
        gl.uniform1i(t.location, t.unit);
      }
      if (sc.depth) gl.enable(gl.DEPTH_TEST); else gl.disable(gl.DEPTH_TEST);
      gl.bindVertexArray(sc.mesh.vao);
      gl.drawElements(gl.TRIANGLES, sc.mesh.count, gl.UNSIGNED_INT, 0);
    }
    gl.disable(gl.SCISSOR_TEST);
  }

  // The view drawn into a float framebuffer and read back, RGBA rows bottom first as WebGL reads them: the values the
  // shaders wrote, not rounded to the canvas's 8 bits (a normal slot's derivatives exceed [0, 1]).
  readFloat(s, regions, width, height) {
    const gl = this.gl;
    if (!this.floatRender) throw new Error('no EXT_color_buffer_float: cannot read float pixels');
    const target = this.target(gl.RGBA32F, width, height);
    this.render(s, regions, target);
    const out = new Float32Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, out);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    target.release();
    return out;
  }

  // The canvas's RGBA8 texels, rows top first (for a capture).
  readCanvas() {
    const gl = this.gl, w = this.canvas.width, h = this.canvas.height;
    const pixels = new Uint8Array(w * h * 4), rows = new Uint8Array(w * h * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    for (let y = 0; y < h; ++y) rows.set(pixels.subarray((h - 1 - y) * w * 4, (h - y) * w * 4), y * w * 4);
    return rows;
  }
}
