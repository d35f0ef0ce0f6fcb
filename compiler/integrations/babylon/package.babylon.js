// hexc package for Babylon.js: a material plugin that gives a PBRMaterial this material's hex-tiled slots, keeping
// Babylon's lighting, shadows, environment and image processing.
//
//   import { createMaterial } from './MATERIAL.babylon.js';
//   mesh.material = await createMaterial('rock', scene);        // a PBRMaterial with the plugin
//   // or: new HexcPlugin(existingPbrMaterial, await loadTextures(scene));
//
// On Babylon's WebGPU engine (WGSL) too when hexc wrote the package with `--targets wgsl`.
//
// Conventions (docs/engines.md#babylonjs): the mesh's uv as Babylon has it, (0, 0) at the bottom-left of the image and
// v up; hexc's textures are loaded here, as hexc samples them (invertY off; sRGB ones with useSRGBBuffer, so that they
// are filtered in linear as hexc filters them); the tangent frame is built from the screen-space derivatives of the
// world position and uv (T along +u, B along +v); the values are linear, and Babylon's image processing encodes them.
// Layers weighed by the vertex colour read the mesh's `color` vertex buffer (linear, as Babylon keeps vertex colours;
// channel i weighs layer i) through a varying of the plugin's, and Babylon's own use of it (VERTEXCOLOR: tinting the
// albedo) is turned off, so that the colour weighs the layers only. A mesh without one is drawn with WebGL's default
// colour, (0, 0, 0, 1), and console.error says so, naming it.
import { MaterialPluginBase } from '@babylonjs/core/Materials/materialPluginBase.js';
import { PBRMaterial } from '@babylonjs/core/Materials/PBR/pbrMaterial.js';
import { ShaderLanguage } from '@babylonjs/core/Materials/shaderLanguage.js';
import { Constants } from '@babylonjs/core/Engines/constants.js';
import { RawTexture2DArray } from '@babylonjs/core/Materials/Textures/rawTexture2DArray.js';
import { Texture } from '@babylonjs/core/Materials/Textures/texture.js';

// The material's data, written by hexc: its slots, which Babylon input each fills, and their GLSL ES 3.00 code (and
// their WGSL with `--targets wgsl`, for Babylon's WebGPU engine).
const hexc = /* hexc:data */ null;
// The meshes without vertex colours this material has said it draws (HexcPlugin.prepareDefines).
const uncoloured = new WeakSet();

// The uv hexc's functions take, from Babylon's (v up the image, origin at the bottom-left).
const kUv = hexc.uv_origin === 'bottom-left' ? 'vHexcUv' : 'vec2(vHexcUv.x, 1.0 - vHexcUv.y)';
const kUvWgsl = hexc.uv_origin === 'bottom-left' ? 'fragmentInputs.vHexcUv'
  : 'vec2f(fragmentInputs.vHexcUv.x, 1.0 - fragmentInputs.vHexcUv.y)';

// The tangent frame from screen-space derivatives (Schüler's cotangent frame), its sign taken from the triangle's
// orientation on screen so that T runs along +u and B along +v in Babylon's left-handed world as in a right-handed one.
const kTangentFrame = `
vec3 hexcPerturb(vec3 N, vec3 p, vec2 uv, vec3 n) {
  vec3 dp1 = dFdx(p), dp2 = dFdy(p);
  vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
  vec3 dp2perp = cross(dp2, N), dp1perp = cross(N, dp1);
  vec3 T = dp2perp * duv1.x + dp1perp * duv2.x;
  vec3 B = dp2perp * duv1.y + dp1perp * duv2.y;
  float scale = sign(dot(cross(dp1, dp2), N)) * inversesqrt(max(max(dot(T, T), dot(B, B)), 1e-30));
  return normalize(T * scale * n.x + B * scale * n.y + N * n.z);
}`;

// The same frame in WGSL.
const kTangentFrameWgsl = `
fn hexcPerturb(N: vec3f, p: vec3f, uv: vec2f, n: vec3f) -> vec3f {
  let dp1 = dpdx(p); let dp2 = dpdy(p);
  let duv1 = dpdx(uv); let duv2 = dpdy(uv);
  let dp2perp = cross(dp2, N); let dp1perp = cross(N, dp1);
  let T = dp2perp * duv1.x + dp1perp * duv2.x;
  let B = dp2perp * duv1.y + dp1perp * duv2.y;
  let scale = sign(dot(cross(dp1, dp2), N)) * inverseSqrt(max(max(dot(T, T), dot(B, B)), 1e-30));
  return normalize(T * scale * n.x + B * scale * n.y + N * n.z);
}`;

// Where each role's value enters PBRMaterial's fragment shader: a regular expression over its code (a plugin's "!"
// injection point) and what replaces the match, given the slot's call.
const roles = {
  albedo: ['vec3 surfaceAlbedo=albedoOpacityOut\\.surfaceAlbedo;', (call) => `vec3 surfaceAlbedo=albedoOpacityOut.surfaceAlbedo*${call}.rgb;`],
  // Babylon's microSurface is 1 - roughness; both are read after this point.
  roughness: ['float roughness=reflectivityOut\\.roughness;',
    (call) => `float roughness=reflectivityOut.roughness*${call};microSurface=1.0-roughness;`],
  // After the geometric normal is final (pbrBlockNormalFinal) and before anything reads it.
  normal: ['albedoOpacityOutParams albedoOpacityOut;', (call) => `normalW=hexcPerturb(normalW,vPositionW,vHexcUv,${call});albedoOpacityOutParams albedoOpacityOut;`],
};

// The same points in PBRMaterial's WGSL.
const rolesWgsl = {
  albedo: ['var surfaceAlbedo: vec3f=albedoOpacityOut\\.surfaceAlbedo;', (call) => `var surfaceAlbedo: vec3f=albedoOpacityOut.surfaceAlbedo*${call}.rgb;`],
  roughness: ['var roughness: f32=reflectivityOut\\.roughness;',
    (call) => `var roughness: f32=reflectivityOut.roughness*${call};microSurface=1.0-roughness;`],
  normal: ['var albedoOpacityOut: albedoOpacityOutParams;',
    (call) => `normalW=hexcPerturb(normalW,fragmentInputs.vPositionW,fragmentInputs.vHexcUv,${call});var albedoOpacityOut: albedoOpacityOutParams;`],
};

// hexc's WGSL as Babylon's WGSL processor takes it: resources without @group and @binding (Babylon numbers them),
// each texture named as its uniform, which Babylon binds it by (naga appends `_` to a name that ends in a digit:
// `hexcTex_splat0_`), and a sampler per texture named <texture>Sampler, which Babylon binds with that texture, in place
// of hexc's one sampler.
function babylonWgsl(wgsl) {
  const sampler = /var (\w+): sampler;/.exec(wgsl)[1];
  const samplers = hexc.textures.map((t) => `var ${t.uniform}Sampler: sampler;`).join('\n');
  const named = hexc.textures.filter((t) => /\d$/.test(t.uniform))
    .reduce((text, t) => text.replace(new RegExp(`\\b${t.uniform}_\\b`, 'g'), t.uniform), wgsl);
  return named.replace(/@group\(\d+\) @binding\(\d+\) /g, '').replace(`var ${sampler}: sampler;`, samplers)
    .replace(new RegExp(`(\\w+), ${sampler}\\b`, 'g'), '$1, $1Sampler');
}

// A texture of `url`, once loaded: repeat, trilinear and isotropic (Babylon's default anisotropy of 4 moves
// hex-tiling's rotated gradients off hexc's reference by up to 8/255 on a non-square texture), the image's first row at
// t = 0 (invertY off), sRGB ones (`srgb`) decoded by the sampler before filtering.
function loadTexture(scene, url, srgb) {
  return new Promise((resolve, reject) => {
    const texture = new Texture(url, scene, {
      noMipmap: false, invertY: false, samplingMode: Texture.TRILINEAR_SAMPLINGMODE, useSRGBBuffer: srgb,
      onLoad: () => resolve(texture), onError: (message) => reject(new Error(`hexc: ${url}: ${message}`)),
    });
    texture.anisotropicFilteringLevel = 1;
  });
}

// A layered role's textures as one RawTexture2DArray, layer i the i-th file (the manifest's `layers.arrays`), sampled
// as loadTexture's. Babylon's 2D arrays have no sRGB format, so hexc gives this package arrays of linear roles only.
async function arrayTexture(scene, files, base) {
  const layers = await Promise.all(files.map((file) => loadTexture(scene, new URL(file, base).href, false)));
  const { width, height } = layers[0].getSize();
  const data = new Uint8Array(width * height * 4 * layers.length);
  for (const [i, layer] of layers.entries()) { // each read back as loaded, its first row first
    data.set(await layer.readPixels(), i * width * height * 4);
    layer.dispose();
  }
  const texture = new RawTexture2DArray(data, width, height, layers.length, Constants.TEXTUREFORMAT_RGBA, scene, true, false,
    Texture.TRILINEAR_SAMPLINGMODE);
  texture.anisotropicFilteringLevel = 1;
  return texture;
}

// Loads the slots' textures as hexc samples them (loadTexture; invertY off whatever the uv origin: hexc flips v itself
// for bottom-left). A layered role that hexc reads as an array (an entry with `layers`) is one RawTexture2DArray.
export async function loadTextures(scene, base = import.meta.url) {
  const textures = {};
  await Promise.all(hexc.textures.map(async (t) => {
    if (t.layers && t.colorspace === 'srgb') throw new Error(`hexc: ${t.uniform}: Babylon.js has no sRGB array texture`);
    textures[t.uniform] = t.layers ? await arrayTexture(scene, t.layers, base)
      : await loadTexture(scene, new URL(t.file, base).href, t.colorspace === 'srgb');
  }));
  return textures;
}

// The plugin: hexc's functions and textures in PBRMaterial's shaders, each slot's value at its role's input.
export class HexcPlugin extends MaterialPluginBase {
  constructor(material, textures) {
    super(material, 'Hexc', 200, { HEXC: false });
    this.textures = textures;
    this._enable(true);
    for (const name of hexc.unmapped) console.warn(`hexc: Babylon.js has no input for slot ${name} of ${hexc.material}`);
  }

  getClassName() { return 'HexcPlugin'; }

  // WGSL (Babylon's WebGPU engine) when hexc wrote it: `hexc --engine babylon --targets wgsl`.
  isCompatible(shaderLanguage) { return shaderLanguage === ShaderLanguage.GLSL || (shaderLanguage === ShaderLanguage.WGSL && !!hexc.wgsl); }

  // Without the mesh's `color` vertex buffer WebGL reads its default colour, (0, 0, 0, 1): one layer over the whole mesh
  // (the first; the fourth where there are four). Said once per mesh; not thrown: Babylon checks readiness in timers
  // (whenReadyAsync), where an Error would leave the scene waiting instead of reaching the application.
  prepareDefines(defines, scene, mesh) {
    defines.HEXC = true;
    if (!hexc.vertex_color) return;
    defines.VERTEXCOLOR = defines.VERTEXALPHA = false;  // after Babylon's own attribute defines
    if (!mesh.isVerticesDataPresent('color') && !uncoloured.has(mesh)) {
      uncoloured.add(mesh);
      console.error(`hexc: ${hexc.material} weighs its layers by the vertex colour, and mesh "${mesh.name}" has no \`color\` `
        + 'vertex buffer: it is drawn with the colour (0, 0, 0, 1); give it one (channel i weighs layer i)');
    }
  }

  getAttributes(attributes) {
    for (const name of hexc.vertex_color ? ['uv', 'color'] : ['uv']) if (!attributes.includes(name)) attributes.push(name);
  }

  getSamplers(samplers) { samplers.push(...Object.keys(this.textures)); }

  getUniforms() { return { ubo: [] }; }

  isReadyForSubMesh() { return Object.values(this.textures).every((t) => t.isReady()); }

  bindForSubMesh(uniformBuffer) {
    for (const [uniform, texture] of Object.entries(this.textures)) uniformBuffer.setTexture(uniform, texture);
  }

  getCustomCode(shaderType, shaderLanguage) {
    if (shaderLanguage === ShaderLanguage.WGSL) return this.customCodeWgsl(shaderType);
    const color = hexc.vertex_color ? 'varying vec4 vHexcColor;' : '';
    if (shaderType === 'vertex') {
      return { CUSTOM_VERTEX_DEFINITIONS: `#ifndef UV1\nattribute vec2 uv;\n#endif\nvarying vec2 vHexcUv;\n${color && `attribute vec4 color;\n${color}`}`,
        CUSTOM_VERTEX_MAIN_END: `vHexcUv = uv;${color && 'vHexcColor = color;'}` };
    }
    const code = { CUSTOM_FRAGMENT_DEFINITIONS: `varying vec2 vHexcUv;\n${color}\n${hexc.glsl}\n${kTangentFrame}` };
    for (const slot of hexc.slots) {
      const [point, replace] = roles[slot.role];
      code[`!${point}`] = replace(slot.call.replace('UV', kUv).replace('COLOR', 'vHexcColor'));
    }
    return code;
  }

  // naga's functions take their uv (and vertex colour) by pointer: each call gets a function-scope copy.
  customCodeWgsl(shaderType) {
    const color = hexc.vertex_color ? 'varying vHexcColor: vec4f;' : '';
    if (shaderType === 'vertex') {
      return { CUSTOM_VERTEX_DEFINITIONS: `#ifndef UV1\nattribute uv: vec2f;\n#endif\nvarying vHexcUv: vec2f;\n${color && `attribute color: vec4f;\n${color}`}`,
        CUSTOM_VERTEX_MAIN_END: `vertexOutputs.vHexcUv = vertexInputs.uv;${color && 'vertexOutputs.vHexcColor = vertexInputs.color;'}` };
    }
    const code = { CUSTOM_FRAGMENT_DEFINITIONS: `varying vHexcUv: vec2f;\n${color}\n${babylonWgsl(hexc.wgsl)}\n${kTangentFrameWgsl}` };
    for (const slot of hexc.slots) {
      const [point, replace] = rolesWgsl[slot.role];
      const uv = `hexcUv_${slot.name}`, weights = `hexcColor_${slot.name}`;
      const colorCopy = color && `var ${weights}: vec4f = fragmentInputs.vHexcColor;`;
      code[`!${point}`] = `var ${uv}: vec2f = ${kUvWgsl};${colorCopy}` + replace(slot.call.replace('UV', `&${uv}`).replace('COLOR', `&${weights}`));
    }
    return code;
  }
}

// A PBRMaterial named `name` with the plugin; metallic 0 and roughness 1 unless `parameters` say otherwise (the
// roughness slot multiplies Babylon's roughness).
export async function createMaterial(name, scene, parameters = {}, base = import.meta.url) {
  const material = new PBRMaterial(name, scene);
  Object.assign(material, { metallic: 0, roughness: 1 }, parameters);
  new HexcPlugin(material, await loadTextures(scene, base));
  return material;
}

export const data = hexc;
