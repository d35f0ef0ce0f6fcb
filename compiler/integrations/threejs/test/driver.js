// The three.js test driver: draws a package's material on a camera-facing square and reads the canvas back.
// `render` draws the uv rectangle given in three.js's uv (v up), top row first; `probe` replaces the lit output by one
// input as three.js's shader holds it after the package filled it (linear values, no lighting; `nan`: times a NaN).
// `marker`: a red square of that many pixels that three.js draws at the screen's top-left in the same frame; `png`:
// the canvas as a user's screenshot gets it (toDataURL, top row first) instead of readPixels' rows; `flipY`: the
// package's textures uploaded with three.js's default flipY = true; `materialType`: applyHexc on a new material of
// that type instead of createMaterial (the console's warnings are returned); `files`: the package's textures loaded
// from other files of it (withFiles); `colors`: the square's vertex colours (scene.js).
import * as THREE from 'three';
import { stage } from './scene.js';
import { withFiles } from '../../test_files.js';

const kProbes = {
  albedo: 'diffuseColor.rgb',
  roughness: 'vec3(roughnessFactor)',
  metalness: 'vec3(metalnessFactor)',
  normal: 'normal * 0.5 + 0.5', // view space: on this square, T = +x, B = +y, N = +z
};

function probe(material, input, nan) {
  const previous = material.onBeforeCompile;
  const value = nan ? `${kProbes[input]} * uintBitsToFloat(0x7fc00000u)` : kProbes[input];
  material.onBeforeCompile = (shader, renderer) => {
    previous.call(material, shader, renderer);
    shader.fragmentShader = shader.fragmentShader.replace('#include <opaque_fragment>', `gl_FragColor = vec4(${value}, 1.0);`);
  };
  const key = material.customProgramCacheKey.bind(material);
  material.customProgramCacheKey = () => `${key()}|probe:${input}:${!!nan}`;
}

// The package's material as the test asks for it, and the console's warnings while it is made.
async function material(pkg, { input, nan, flipY, materialType, files }) {
  const warnings = [];
  const consoleWarn = console.warn;
  console.warn = (...args) => { warnings.push(args.join(' ')); consoleWarn(...args); };
  try {
    const parameters = { metalness: 0, roughness: 1 };
    let made;
    if (materialType || flipY) { // as docs/engines.md's "a material of your own"
      const textures = await pkg.loadTextures();
      for (const texture of flipY ? Object.values(textures) : []) texture.flipY = true;
      made = pkg.applyHexc(new THREE[materialType ?? 'MeshStandardMaterial'](materialType ? {} : parameters), textures);
    } else {
      made = await withFiles(pkg, files, () => pkg.createMaterial(parameters));
    }
    if (input) probe(made, input, nan);
    return [made, warnings];
  } finally {
    console.warn = consoleWarn;
  }
}

window.hexcDriver = {
  // `sphere`: a lit sphere (the screenshot in docs/engines.md) instead of the square, with some ambient light.
  async render({ module, width, height, uv, input, light, encoding, sphere, nan, flipY, materialType, files, png, colors, ...options }) {
    const pkg = await import(module);
    const canvas = document.createElement('canvas');
    canvas.width = width;
    canvas.height = height;
    document.body.appendChild(canvas);
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    try { // a draw the package refuses throws: the page's next draws still get a WebGL context
      renderer.outputColorSpace = encoding === 'srgb' ? THREE.SRGBColorSpace : THREE.LinearSRGBColorSpace;
      const [made, warnings] = await material(pkg, { input, nan, flipY, materialType, files });
      const { scene, camera } = stage(made, { uv, colors, sphere, light, size: options.marker, width, height });
      renderer.render(scene, camera);
      const errors = renderer.info.programs.map((p) => p.diagnostics).filter((d) => d);
      if (png) {
        const url = canvas.toDataURL('image/png');
        return { png: url.slice(url.indexOf(',') + 1), errors: JSON.stringify(errors), warnings };
      }
      const gl = renderer.getContext();
      const pixels = new Uint8Array(width * height * 4);
      gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      let text = '';
      for (let i = 0; i < pixels.length; i += 0x8000) text += String.fromCharCode(...pixels.subarray(i, i + 0x8000));
      return { pixels: btoa(text), errors: JSON.stringify(errors), warnings };
    } finally {
      renderer.dispose();
      canvas.remove();
    }
  },
};
