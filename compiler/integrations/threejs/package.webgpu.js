// hexc package for three.js's WebGPURenderer: a MeshStandardNodeMaterial (or any node material with the same inputs)
// whose inputs are this material's hex-tiled functions in WGSL, keeping three.js's lighting, shadows and environment.
//
//   import { createMaterial } from './MATERIAL.three-webgpu.js';
//   mesh.material = await createMaterial({ metalness: 0 });   // MeshStandardNodeMaterial parameters
//
// Conventions (docs/engines.md#threejs-webgpu), those of the WebGL 2 package: the mesh's uv as three.js has it, (0, 0)
// at the bottom-left of the image and v up; hexc's textures are loaded here, as hexc samples them (the image's first row
// at t = 0, sRGB decoded by the sampler); the tangent frame is three.js's own (the geometry's tangents, or its frame from
// the uv's derivatives), its bitangent along +v; the values are linear and three.js encodes the canvas output. Layers
// weighed by the vertex colour read the geometry's `color` attribute (vertexColor(): linear, channel i weighs layer i;
// RGB alone: alpha 1; none: white), which does not tint the albedo.
import * as THREE from 'three/webgpu';
import { code, materialColor, materialEmissive, materialMetalness, materialReference, materialRoughness, normalMap, texture, uv, vec2, vec4,
  vertexColor, wgslFn } from 'three/tsl';

// The material's data, written by hexc: its slots, which input each fills, and their WGSL code.
const hexc = /* hexc:data */ null;

// Each role: the node material's input and what it takes from the slot's value, the material's own factor kept as
// three.js's maps keep it (color, roughness, metalness, emissive; normalScale for the tangent-space normal).
const roles = {
  albedo: ['colorNode', (value) => vec4(materialColor.mul(value.rgb), value.a)],
  roughness: ['roughnessNode', (value) => materialRoughness.mul(value)],
  metallic: ['metalnessNode', (value) => materialMetalness.mul(value)],
  ao: ['aoNode', (value) => value],
  emission: ['emissiveNode', (value) => materialEmissive.mul(value.rgb)],
  normal: ['normalNode', (value) => normalMap(value.mul(0.5).add(0.5), materialReference('normalScale', 'vec2'))],
};

// hexc's functions as three.js's node builder takes module-scope WGSL (a wgslFn's include): without their resource
// declarations, which three.js makes itself, at its own bindings, for the texture nodes named as hexc names its textures
// (below); and with each texture's own sampler, `<texture>_sampler` as three.js names it, in place of hexc's one shared
// sampler (the state is the same: repeat, trilinear).
function threeWgsl(wgsl) {
  const sampler = /var (\w+): sampler;/.exec(wgsl)[1];
  return wgsl.replace(/@group\(\d+\) @binding\(\d+\) var \w+: [^;]+;\n/g, '')
    .replace(new RegExp(`(\\w+), ${sampler}\\b`, 'g'), '$1, $1_sampler');
}

// The name hexc's WGSL gives a texture's uniform: naga's, which appends `_` to a name that ends in a digit
// (`hexcTex_splat0_`).
function wgslName(uniform) {
  return /\d$/.test(uniform) ? `${uniform}_` : uniform;
}

// The uv hexc's functions take, from three.js's (v up the image, origin at the bottom-left).
function hexcUv() {
  return hexc.uv_origin === 'bottom-left' ? uv() : vec2(uv().x, uv().y.oneMinus());
}

/* hexc:textures */

// The slots' textures, loaded as hexc samples them (loadSampled): a texture per slot, no arrays.
export async function loadTextures(base = import.meta.url, loader = new THREE.TextureLoader()) {
  return loadSampled(base, loader, null);
}

// Each slot's value as a node: a wgslFn that calls the slot's function (naga's functions take the uv, and the vertex
// colour, by pointer) and takes every texture hexc's functions read as a parameter, so that three.js binds them, under
// hexc's names, for the whole module (the include); the parameters themselves are not read.
export function slotNodes(textures) {
  const module = code(threeWgsl(hexc.wgsl));
  const nodes = Object.fromEntries(hexc.textures.map((t) => [t.uniform, texture(textures[t.uniform]).setName(wgslName(t.uniform))]));
  const parameters = (hexc.vertex_color ? ', color: vec4<f32>' : '') + hexc.textures.map((t) => `, bound_${t.uniform}: texture_2d<f32>`).join('');
  const color = hexc.vertex_color ? { color: vertexColor() } : {};
  const values = {};
  for (const slot of hexc.slots) {
    const name = slot.call.slice(0, slot.call.indexOf('('));
    const returns = new RegExp(`fn ${name}\\([^)]*\\) -> ([\\w<>]+)`).exec(hexc.wgsl)[1];
    const call = wgslFn(`fn ${name}_node(uv: vec2<f32>${parameters}) -> ${returns} {
  var at = uv;${hexc.vertex_color ? '\n  var weights = color;' : ''}
  return ${slot.call.replace('UV', '&at').replace('COLOR', '&weights')};
}`, [module]);
    values[slot.name] = call({ uv: hexcUv(), ...color, ...Object.fromEntries(hexc.textures.map((t) => [`bound_${t.uniform}`, nodes[t.uniform]])) });
  }
  return values;
}

// Gives `material` (a node material) the hex-tiled slots: each slot's value at its role's input. A material type
// without that input (MeshBasicNodeMaterial has no roughnessNode: it is not lit) leaves the slot out, with a warning,
// as a slot with no three.js input is.
export function applyHexc(material, textures) {
  const values = slotNodes(textures);
  for (const slot of hexc.slots) {
    const [input, value] = roles[slot.role];
    if (input in material) material[input] = value(values[slot.name]);
    else console.warn(`hexc: ${material.type} has no ${input}, so slot ${slot.name} of ${hexc.material} is ignored`);
  }
  for (const name of hexc.unmapped) console.warn(`hexc: three.js has no input for slot ${name} of ${hexc.material}`);
  return material;
}

// A MeshStandardNodeMaterial with `parameters`, its slots hex-tiled.
export async function createMaterial(parameters = {}, base = import.meta.url) {
  return applyHexc(new THREE.MeshStandardNodeMaterial(parameters), await loadTextures(base));
}

export const data = hexc;
