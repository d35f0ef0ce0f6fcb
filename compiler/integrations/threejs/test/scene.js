// What the three.js test drivers share (WebGL 2's driver.js, WebGPU's webgpu.js): the scene they draw, from three.js's
// core classes, which both renderers draw.
import { AmbientLight, DirectionalLight, Float32BufferAttribute, Mesh, MeshBasicMaterial, OrthographicCamera, PlaneGeometry, Scene,
  SphereGeometry } from 'three';

// A red square of `size` pixels at the top-left of a `width` x `height` canvas, in front of the material.
function marker(size, width, height) {
  const geometry = new PlaneGeometry(2 * size / width, 2 * size / height);
  geometry.translate(-1 + size / width, 1 - size / height, 1);
  return new Mesh(geometry, new MeshBasicMaterial({ color: 0xff0000 }));
}

// A 2x2 square in front of an orthographic camera; its corners' uv span `uv` = [u0, vTop, u1, vBottom], their vertex
// colours `colors` (RGBA) if given.
function square(uv, colors) {
  const geometry = new PlaneGeometry(2, 2);
  const [u0, vTop, u1, vBottom] = uv;
  const corners = [[u0, vTop], [u1, vTop], [u0, vBottom], [u1, vBottom]]; // PlaneGeometry's vertex order
  geometry.setAttribute('uv', new Float32BufferAttribute(corners.flat(), 2));
  if (colors) geometry.setAttribute('color', new Float32BufferAttribute(colors.flat(), 4));
  return geometry;
}

// `material` on the square whose uv span `uv` (or on a sphere, with some ambient light: the screenshots in
// docs/engines.md), in front of an orthographic camera; `light`: a directional light from that direction; `size`: the
// marker's, on a `width` x `height` canvas (none if 0); `colors`: the square's vertex colours.
export function stage(material, { uv, colors, sphere, light, size, width, height }) {
  const scene = new Scene();
  scene.add(new Mesh(sphere ? new SphereGeometry(0.95, 96, 48) : square(uv, colors), material));
  if (size) scene.add(marker(size, width, height));
  if (sphere) scene.add(new AmbientLight(0xffffff, 0.4));
  if (light) {
    const sun = new DirectionalLight(0xffffff, 2.5);
    sun.position.set(...light);
    scene.add(sun);
  }
  const camera = new OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
  camera.position.z = 3; // orthographic: only keeps the sphere (radius 0.95) beyond the near plane
  return { scene, camera };
}
