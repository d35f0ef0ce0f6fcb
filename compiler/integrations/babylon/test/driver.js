// The Babylon.js test driver: draws a package's material on a camera-facing square and reads the canvas back, with
// Babylon's WebGL 2 engine or, given `webgpu`, its WebGPU engine.
// `render` draws the uv rectangle given in Babylon's uv (v up), top row first; `input` replaces the output by one input
// as PBRMaterial's shader holds it after the package filled it (linear values, after lighting and image processing;
// `nan`: times a NaN). `marker`: a red square of that many pixels that Babylon draws at the screen's top-left in the same
// frame; `png`: the canvas as a user's screenshot gets it (toDataURL, top row first) instead of readPixels' rows;
// `invertY`: the package's textures loaded with Babylon's default invertY = true, the plugin put on a PBRMaterial;
// `files`: the package's textures loaded from other files of it (withFiles); `colors`: the square's vertex colours
// (RGBA at its top-left, top-right, bottom-left and bottom-right corners).
import { Camera } from '@babylonjs/core/Cameras/camera.js';
import { FreeCamera } from '@babylonjs/core/Cameras/freeCamera.js';
import { Engine } from '@babylonjs/core/Engines/engine.js';
import { WebGPUEngine } from '@babylonjs/core/Engines/webgpuEngine.js';
import { DirectionalLight } from '@babylonjs/core/Lights/directionalLight.js';
import { HemisphericLight } from '@babylonjs/core/Lights/hemisphericLight.js';
import { MaterialPluginBase } from '@babylonjs/core/Materials/materialPluginBase.js';
import { StandardMaterial } from '@babylonjs/core/Materials/standardMaterial.js';
import { PBRMaterial } from '@babylonjs/core/Materials/PBR/pbrMaterial.js';
import { Texture } from '@babylonjs/core/Materials/Textures/texture.js';
import { Color3, Color4 } from '@babylonjs/core/Maths/math.color.js';
import { Vector3 } from '@babylonjs/core/Maths/math.vector.js';
import { CreateSphere } from '@babylonjs/core/Meshes/Builders/sphereBuilder.js';
import { Mesh } from '@babylonjs/core/Meshes/mesh.js';
import { VertexData } from '@babylonjs/core/Meshes/mesh.vertexData.js';
import { Scene } from '@babylonjs/core/scene.js';
import { withFiles } from '../../test_files.js';
import { keepWebGpuOffTheSwapChain } from '../../webgpu_canvas.js';

// Babylon's world is left-handed: the camera at z = -3 looks along +z, x right and y up on screen; the square faces -z.
const kProbes = {
  albedo: 'baseColor', // the base colour PBRMaterial reads the albedo from (surfaceAlbedo is then scaled by 1 - F0)
  roughness: 'vec3(roughness)',
  normal: 'vec3(normalW.x, normalW.y, -normalW.z) * 0.5 + 0.5', // world to the square's tangent space: T = +x, B = +y, N = -z
};

class Probe extends MaterialPluginBase {
  constructor(material, input, nan) {
    super(material, 'HexcProbe', 300, { HEXC_PROBE: false });
    this.value = nan ? `${kProbes[input]} * uintBitsToFloat(0x7fc00000u)` : kProbes[input];
    this._enable(true);
  }

  getClassName() { return 'HexcProbe'; }

  // Its code reads the same in WGSL (Babylon's WebGPU engine), but for `nan`'s uintBitsToFloat, which only WebGL 2 views use.
  isCompatible() { return true; }

  prepareDefines(defines) { defines.HEXC_PROBE = true; }

  getCustomCode(shaderType) {
    return shaderType === 'fragment' ? { CUSTOM_FRAGMENT_BEFORE_FRAGCOLOR: `finalColor = vec4(${this.value}, 1.0);` } : null;
  }
}

// A 2x2 square at z = 0; its corners' uv span `uv` = [u0, vTop, u1, vBottom], their vertex colours `colors` if given.
function square(scene, uv, colors) {
  const [u0, vTop, u1, vBottom] = uv;
  const data = new VertexData();
  data.positions = [-1, 1, 0, 1, 1, 0, -1, -1, 0, 1, -1, 0];
  data.normals = [0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1];
  data.uvs = [u0, vTop, u1, vTop, u0, vBottom, u1, vBottom];
  data.indices = [0, 1, 2, 1, 3, 2];
  if (colors) data.colors = colors.flat();
  const mesh = new Mesh('square', scene);
  data.applyToMesh(mesh);
  return mesh;
}

// A red square of `size` pixels at the top-left of a `width` x `height` canvas, in front of the material (z < 0).
function marker(scene, size, width, height) {
  const [w, h] = [2 * size / width, 2 * size / height];
  const data = new VertexData();
  data.positions = [-1, 1, -1, -1 + w, 1, -1, -1, 1 - h, -1, -1 + w, 1 - h, -1];
  data.indices = [0, 1, 2, 1, 3, 2];
  const mesh = new Mesh('marker', scene);
  data.applyToMesh(mesh);
  const red = new StandardMaterial('marker', scene);
  Object.assign(red, { emissiveColor: new Color3(1, 0, 0), disableLighting: true, backFaceCulling: false });
  mesh.material = red;
}

// A PBRMaterial with the plugin and the package's textures loaded as loadTextures does, but with invertY on (Babylon's
// default, which a user who loads the textures themselves gets).
async function invertedMaterial(pkg, module, scene) {
  const textures = {};
  await Promise.all(pkg.data.textures.map((t) => new Promise((resolve, reject) => {
    textures[t.uniform] = new Texture(new URL(t.file, new URL(module, location.href)).href, scene, {
      invertY: true, samplingMode: Texture.TRILINEAR_SAMPLINGMODE, useSRGBBuffer: t.colorspace === 'srgb', onLoad: resolve, onError: reject,
    });
    textures[t.uniform].anisotropicFilteringLevel = 1;
  })));
  const material = new PBRMaterial('hexc', scene);
  Object.assign(material, { metallic: 0, roughness: 1 });
  new pkg.HexcPlugin(material, textures);
  return material;
}

// One WebGPU engine for the page: Chromium here gives no adapter again once an engine's device is destroyed.
let webGpu = null;
async function webGpuEngine(width, height) {
  if (!webGpu) {
    keepWebGpuOffTheSwapChain();
    const canvas = document.createElement('canvas');
    document.body.appendChild(canvas);
    webGpu = new WebGPUEngine(canvas, { antialias: false, adaptToDeviceRatio: false });
    await webGpu.initAsync();
  }
  webGpu.getRenderingCanvas().width = width;
  webGpu.getRenderingCanvas().height = height;
  webGpu.resize(true);
  return webGpu;
}

// The canvas's pixels, bottom row first as WebGL reads them (Babylon's WebGPU engine reads the top row first).
async function readPixels(engine, width, height) {
  if (engine.isWebGPU) {
    const top = new Uint8Array((await engine.readPixels(0, 0, width, height)).buffer);
    const pixels = new Uint8Array(width * height * 4);
    for (let y = 0; y < height; ++y) pixels.set(top.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
    return pixels;
  }
  const gl = engine._gl;
  const pixels = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return pixels;
}

window.hexcDriver = {
  // `sphere`: a lit sphere (the screenshot in docs/engines.md) instead of the square, with some ambient light;
  // `diffuse`: no specular highlight from the light (PBRMaterial's specularIntensity 0).
  async render({ module, width, height, uv, input, light, encoding, sphere, diffuse, webgpu, nan, invertY, files, png, colors, ...options }) {
    const errors = [];
    const consoleError = console.error;
    console.error = (...args) => { errors.push(args.join(' ')); consoleError(...args); };
    const canvas = webgpu ? null : document.body.appendChild(Object.assign(document.createElement('canvas'), { width, height }));
    const engine = webgpu ? await webGpuEngine(width, height) : new Engine(canvas, false, { preserveDrawingBuffer: true, adaptToDeviceRatio: false });
    const scene = new Scene(engine);
    try {
      const pkg = await import(module);
      scene.clearColor = new Color4(0, 0, 0, 1);
      scene.ambientColor = new Color3(0, 0, 0);
      scene.imageProcessingConfiguration.isEnabled = encoding === 'srgb';
      const camera = new FreeCamera('camera', new Vector3(0, 0, -3), scene); // orthographic: the distance only clears the sphere
      camera.setTarget(Vector3.Zero());
      camera.mode = Camera.ORTHOGRAPHIC_CAMERA;
      Object.assign(camera, { orthoLeft: -1, orthoRight: 1, orthoTop: 1, orthoBottom: -1, minZ: 0.1, maxZ: 10 });
      const material = invertY ? await invertedMaterial(pkg, module, scene) : await withFiles(pkg, files, () => pkg.createMaterial('hexc', scene));
      material.backFaceCulling = false;
      if (diffuse) material.specularIntensity = 0;
      if (input) new Probe(material, input, nan);
      if (options.marker) marker(scene, options.marker, width, height);
      if (light) new DirectionalLight('sun', new Vector3(-light[0], -light[1], light[2]), scene).intensity = 2.5; // towards the light: (x, y, -z)
      (sphere ? CreateSphere('sphere', { diameter: 1.9, segments: 48 }, scene) : square(scene, uv, colors)).material = material;
      if (sphere) new HemisphericLight('sky', new Vector3(0, 1, 0), scene).intensity = 0.4;
      await Promise.race([scene.whenReadyAsync(), new Promise((_, reject) => setTimeout(() => reject(new Error('not ready: ' + errors.join('\n'))), 60000))]);
      scene.render();
      if (png) {
        const url = canvas.toDataURL('image/png');
        return { png: url.slice(url.indexOf(',') + 1), errors: JSON.stringify(errors) };
      }
      const pixels = await readPixels(engine, width, height);
      let text = '';
      for (let i = 0; i < pixels.length; i += 0x8000) text += String.fromCharCode(...pixels.subarray(i, i + 0x8000));
      return { pixels: btoa(text), errors: JSON.stringify(errors) };
    } finally {
      console.error = consoleError;
      scene.dispose();
      if (canvas) {
        engine.dispose();
        canvas.remove();
      }
    }
  },
};
