// The three.js WebGPU test driver (tests/engines/webgpu_test.py): draws a `threejs-webgpu` package's material with
// three.js's WebGPURenderer on a camera-facing square (or a sphere) and reads the canvas back as the canvas holds it.
// `uv`: the square's uv [u0, v at the top, u1, v at the bottom] in three.js's uv (v up); `view`: instead of the lit
// material, one of the package's slots unlit (MeshBasicNodeMaterial: an RGBA value's colour, a scalar as grey, a
// normal as n * 0.5 + 0.5); `light`: a directional light from that direction; `marker`: a red square of that many
// pixels three.js draws at the screen's top-left in the same frame; `flipY`: the textures uploaded with three.js's
// default flipY = true; `swap`: {uniform: other uniform}, a texture bound in another's place. The canvas is sRGB
// (three.js's default output), its pixels returned top row first, as WebGPU's texture rows are.
import * as THREE from 'three/webgpu';
import { vec3, vec4 } from 'three/tsl';
import { keepWebGpuOffTheSwapChain } from '../../webgpu_canvas.js';
import { stage } from './scene.js';

// One renderer for the page: Chromium here gives no adapter again once a device is destroyed (webgpu_canvas.js).
let renderer = null;
async function webGpuRenderer(width, height) {
  if (!renderer) {
    keepWebGpuOffTheSwapChain();
    renderer = new THREE.WebGPURenderer({ canvas: document.body.appendChild(document.createElement('canvas')), antialias: false });
    await renderer.init();
    if (!renderer.backend.isWebGPUBackend) throw new Error('three.js fell back to WebGL 2: no WebGPU here');
  }
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  return renderer;
}

// The value a slot's node shows unlit, as a colour.
function shown(value, returns) {
  if (returns === 'f32') return vec4(vec3(value), 1);
  if (returns === 'vec3<f32>') return vec4(value.mul(0.5).add(0.5), 1);
  return vec4(value.rgb, 1);
}

async function material(pkg, { view, flipY, swap }) {
  const textures = await pkg.loadTextures();
  for (const texture of flipY ? Object.values(textures) : []) texture.flipY = true;
  // A copy: three.js binds one texture object once, under one name.
  for (const [uniform, other] of Object.entries(swap ?? {})) textures[uniform] = textures[other].clone();
  if (!view) return pkg.applyHexc(new THREE.MeshStandardNodeMaterial({ metalness: 0, roughness: 1 }), textures);
  const slot = pkg.data.slots.find((s) => s.call.startsWith(`${view}(`));
  const returns = new RegExp(`fn ${view}\\([^)]*\\) -> ([\\w<>]+)`).exec(pkg.data.wgsl)[1];
  return new THREE.MeshBasicNodeMaterial({ colorNode: shown(pkg.slotNodes(textures)[slot.name], returns) });
}

// The canvas's texture, RGBA8 rows top first (its format's channel order undone: three.js picks the preferred
// canvas format, bgra8unorm here).
async function readCanvas(canvas, device) {
  const texture = canvas.getContext('webgpu').getCurrentTexture();
  const { width, height } = texture;
  const stride = Math.ceil(width * 4 / 256) * 256;
  const buffer = device.createBuffer({ size: stride * height, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
  const encoder = device.createCommandEncoder();
  encoder.copyTextureToBuffer({ texture }, { buffer, bytesPerRow: stride }, [width, height]);
  device.queue.submit([encoder.finish()]);
  await buffer.mapAsync(GPUMapMode.READ);
  const rows = new Uint8Array(buffer.getMappedRange());
  const pixels = new Uint8Array(width * height * 4);
  const bgra = texture.format.startsWith('bgra');
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width; ++x) {
      const at = y * stride + x * 4, to = (y * width + x) * 4;
      pixels.set([rows[at + (bgra ? 2 : 0)], rows[at + 1], rows[at + (bgra ? 0 : 2)], rows[at + 3]], to);
    }
  }
  buffer.unmap();
  buffer.destroy();
  return pixels;
}

window.hexcDriver = {
  async render({ module, width, height, uv, light, sphere, colors, ...options }) {
    const errors = [], warnings = [];
    const [consoleError, consoleWarn] = [console.error, console.warn];
    console.error = (...args) => { errors.push(args.join(' ')); consoleError(...args); };
    console.warn = (...args) => { warnings.push(args.join(' ')); consoleWarn(...args); };
    try {
      const r = await webGpuRenderer(width, height);
      const device = r.backend.device;
      const made = await material(await import(module), options);
      const { scene, camera } = stage(made, { uv, colors, sphere, light, size: options.marker, width, height });
      device.pushErrorScope('validation');
      await r.renderAsync(scene, camera);
      const error = await device.popErrorScope();
      if (error) errors.push(error.message);
      const pixels = await readCanvas(r.domElement, device);
      let text = '';
      for (let i = 0; i < pixels.length; i += 0x8000) text += String.fromCharCode(...pixels.subarray(i, i + 0x8000));
      return { pixels: btoa(text), errors: JSON.stringify(errors), warnings };
    } finally {
      [console.error, console.warn] = [consoleError, consoleWarn];
    }
  },
};
