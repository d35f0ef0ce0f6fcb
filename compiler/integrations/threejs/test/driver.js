// The three.js test driver: draws a package's material on a camera-facing square and reads the canvas back.
// `render` draws the uv rectangle given in three.js's uv (v up), top row first; `probe` replaces the lit output by one
// input as three.js's shader holds it after the package filled it (linear values, no lighting).
import * as THREE from 'three';

const kProbes = {
  albedo: 'diffuseColor.rgb',
  roughness: 'vec3(roughnessFactor)',
  metalness: 'vec3(metalnessFactor)',
  normal: 'normal * 0.5 + 0.5', // view space: on this square, T = +x, B = +y, N = +z
};

function probe(material, input) {
  const previous = material.onBeforeCompile;
  material.onBeforeCompile = (shader, renderer) => {
    previous.call(material, shader, renderer);
    shader.fragmentShader = shader.fragmentShader.replace('#include <opaque_fragment>', `gl_FragColor = vec4(${kProbes[input]}, 1.0);`);
  };
  const key = material.customProgramCacheKey.bind(material);
  material.customProgramCacheKey = () => `${key()}|probe:${input}`;
}

// A 2x2 square in front of an orthographic camera; its corners' uv span `uv` = [u0, vTop, u1, vBottom].
function square(uv) {
  const geometry = new THREE.PlaneGeometry(2, 2);
  const [u0, vTop, u1, vBottom] = uv;
  const corners = [[u0, vTop], [u1, vTop], [u0, vBottom], [u1, vBottom]]; // PlaneGeometry's vertex order
  geometry.setAttribute('uv', new THREE.Float32BufferAttribute(corners.flat(), 2));
  return geometry;
}

window.hexcDriver = {
  // `sphere`: a lit sphere (the screenshot in docs/engines.md) instead of the square, with some ambient light.
  async render({ module, width, height, uv, input, light, encoding, sphere }) {
    const pkg = await import(module);
    const canvas = document.createElement('canvas');
    canvas.width = width;
    canvas.height = height;
    document.body.appendChild(canvas);
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    renderer.outputColorSpace = encoding === 'srgb' ? THREE.SRGBColorSpace : THREE.LinearSRGBColorSpace;
    const material = await pkg.createMaterial({ metalness: 0, roughness: 1 });
    if (input) probe(material, input);
    const scene = new THREE.Scene();
    scene.add(new THREE.Mesh(sphere ? new THREE.SphereGeometry(0.95, 96, 48) : square(uv), material));
    if (sphere) scene.add(new THREE.AmbientLight(0xffffff, 0.4));
    if (light) {
      const sun = new THREE.DirectionalLight(0xffffff, 2.5);
      sun.position.set(...light);
      scene.add(sun);
    }
    const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
    camera.position.z = 3; // orthographic: only keeps the sphere (radius 0.95) beyond the near plane
    renderer.render(scene, camera);
    const gl = renderer.getContext();
    const pixels = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const errors = renderer.info.programs.map((p) => p.diagnostics).filter((d) => d);
    renderer.dispose();
    canvas.remove();
    let text = '';
    for (let i = 0; i < pixels.length; i += 0x8000) text += String.fromCharCode(...pixels.subarray(i, i + 0x8000));
    return { pixels: btoa(text), errors: JSON.stringify(errors) };
  },
};
