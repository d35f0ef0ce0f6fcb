// hexc package for three.js: a MeshStandardMaterial (or any built-in material with the same shader chunks) whose
// slots are this material's hex-tiled functions, keeping three.js's lighting, shadows and environment.
//
//   import { createMaterial } from './MATERIAL.three.js';
//   mesh.material = await createMaterial({ metalness: 0 });   // MeshStandardMaterial parameters
//
// Conventions (docs/engines.md#threejs): the mesh's uv as three.js has it, (0, 0) at the bottom-left of the image and
// v up; hexc's textures are loaded here, as hexc samples them; the tangent frame is three.js's own (its getTangentFrame
// or the geometry's tangents), its bitangent along +v; the values are linear and three.js encodes the canvas output.
// Layers weighed by the vertex colour read the geometry's `color` attribute (linear, as three.js keeps vertex colours;
// channel i weighs layer i; RGB alone: alpha 1): the material's vertexColors is turned on, and the colour weighs the
// layers instead of tinting the albedo. A geometry without one is refused when it is drawn (an Error naming it).
import * as THREE from 'three';

// The material's data, written by hexc: its slots, which three.js input each fills, and their GLSL ES 3.00 code.
const hexc = /* hexc:data */ null;

// What replaces the chunk of each role's input, given the slot's call. The normal map keeps three.js's chunk (normalScale,
// its tbn with T along +u and B along +v) and reads hexc's tangent-space normal instead of the texture.
const kNormalRead = 'vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;';
function replaced(text, what, by) {
  if (!text.includes(what)) throw new Error(`hexc: this three.js has no \`${what}\` (the package is written for r187)`);
  return text.replace(what, by);
}
// Each role: the material property three.js gives the material types that take that input, the chunk it reads it in,
// and what replaces the chunk given the slot's call.
const roles = {
  albedo: ['map', 'map_fragment', (call) => `diffuseColor *= ${call};`],
  roughness: ['roughnessMap', 'roughnessmap_fragment', (call) => `float roughnessFactor = roughness * ${call};`],
  metallic: ['metalnessMap', 'metalnessmap_fragment', (call) => `float metalnessFactor = metalness * ${call};`],
  ao: ['aoMap', 'aomap_fragment', (call) => `reflectedLight.indirectDiffuse *= ${call};`],
  emission: ['emissiveMap', 'emissivemap_fragment', (call) => `totalEmissiveRadiance *= ${call}.rgb;`],
  normal: ['normalMap', 'normal_fragment_maps', (call) => replaced(THREE.ShaderChunk.normal_fragment_maps, kNormalRead, `vec3 mapN = ${call};`)],
};

// The slots `material`'s type has an input for. A type without one (MeshBasicMaterial has no normalMap: it is not lit)
// has no chunk to replace, so such a slot is left out with a warning, as a slot with no three.js input is.
function slotsTaken(material) {
  return hexc.slots.filter((slot) => {
    const [property] = roles[slot.role];
    if (property in material) return true;
    console.warn(`hexc: ${material.type} has no ${property}, so slot ${slot.name} of ${hexc.material} is ignored: `
      + `give it a material type with a ${property} (MeshStandardMaterial takes every slot)`);
    return false;
  });
}

// The uv hexc's functions take, from three.js's (v up the image, origin at the bottom-left).
function hexcUv() {
  return hexc.uv_origin === 'bottom-left' ? 'vUv' : 'vec2(vUv.x, 1.0 - vUv.y)';
}

// The RGBA bytes of `images` (one size), stacked first to last, each with its first row first, as the files store
// them: read back from a WebGL 2 texture (no premultiplied alpha, no colour conversion), as a 2D canvas, which keeps
// premultiplied pixels, would not give them where alpha is below 1.
function stacked(images) {
  const { width, height } = images[0];
  const gl = new OffscreenCanvas(width, height).getContext('webgl2');
  const data = new Uint8Array(width * height * 4 * images.length);
  gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
  gl.pixelStorei(gl.UNPACK_COLORSPACE_CONVERSION_WEBGL, gl.NONE);
  images.forEach((image, layer) => {
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, image);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data, layer * width * height * 4);
  });
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return data;
}

// A layered role's textures as one DataArrayTexture, layer i the i-th file (the manifest's `layers.arrays`).
async function arrayTexture(files, base) {
  const loader = new THREE.ImageLoader();
  const images = await Promise.all(files.map((file) => loader.loadAsync(new URL(file, base).href)));
  const texture = new THREE.DataArrayTexture(stacked(images), images[0].width, images[0].height, images.length);
  texture.generateMipmaps = true;
  texture.needsUpdate = true;
  return texture;
}

/* hexc:textures */

// The slots' textures, loaded as hexc samples them (loadSampled); a layered role's array is a DataArrayTexture.
export async function loadTextures(base = import.meta.url, loader = new THREE.TextureLoader()) {
  return loadSampled(base, loader, arrayTexture);
}

// Layers weighed by the vertex colour: three.js's vColor (a vec4 in r187's chunks) from the geometry's `color`. Without
// that attribute WebGL reads its default, (0, 0, 0, 1): one layer over the whole mesh (the first; the fourth where there
// are four) and no sign why. So a draw of such a geometry throws instead, before three.js draws it.
function requireColor(material) {
  material.vertexColors = true;
  const previous = material.onBeforeRender;
  material.onBeforeRender = (renderer, scene, camera, geometry, object, group) => {
    if (!geometry.attributes.color) {
      throw new Error(`hexc: ${hexc.material} weighs its layers by the vertex colour, and the geometry of mesh `
        + `"${object.name || object.uuid}" has no \`color\` attribute: give it one (channel i weighs layer i)`);
    }
    previous.call(material, renderer, scene, camera, geometry, object, group);
  };
}

// Gives `material` the hex-tiled slots: its shader chunks for each slot's role read hexc's functions instead.
export function applyHexc(material, textures) {
  material.defines = { ...material.defines, USE_UV: '' };
  if (hexc.vertex_color) requireColor(material);
  const slots = slotsTaken(material);
  // three.js builds the tangent frame and the normal uniforms only for a material with a normal map: the hexc
  // texture stands in for it (its texels are never read through it).
  const normal = slots.find((s) => s.role === 'normal');
  if (normal && !material.normalMap) material.normalMap = textures[normal.uniform];
  const previous = material.onBeforeCompile;
  material.onBeforeCompile = (shader, renderer) => {
    previous.call(material, shader, renderer);
    for (const [uniform, texture] of Object.entries(textures)) shader.uniforms[uniform] = { value: texture };
    let fragment = replaced(shader.fragmentShader, 'void main() {', `${hexc.glsl}\nvoid main() {`);
    if (hexc.vertex_color) fragment = replaced(fragment, '#include <color_fragment>', '');
    for (const slot of slots) {
      const [, chunk, code] = roles[slot.role];
      fragment = replaced(fragment, `#include <${chunk}>`, code(slot.call.replace('UV', hexcUv()).replace('COLOR', 'vColor')));
    }
    shader.fragmentShader = fragment;
  };
  const key = material.customProgramCacheKey.bind(material);
  material.customProgramCacheKey = () => `${key()}|hexc:${hexc.material}:${hexc.uv_origin}`;
  for (const name of hexc.unmapped) console.warn(`hexc: three.js has no input for slot ${name} of ${hexc.material}`);
  return material;
}

// A MeshStandardMaterial with `parameters`, its slots hex-tiled.
export async function createMaterial(parameters = {}, base = import.meta.url) {
  return applyHexc(new THREE.MeshStandardMaterial(parameters), await loadTextures(base));
}

export const data = hexc;
