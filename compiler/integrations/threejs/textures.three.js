// How hexc's three.js packages load their textures, on WebGL 2 and on WebGPU alike (one copy in hexc's source,
// compiler/integrations/threejs/textures.three.js, written into each package's module).

// Loads the slots' textures, as hexc samples them: repeat, trilinear, sRGB decoded by the sampler where the slot is
// sRGB (three.js's WebGPU backend gives those an -srgb format), and the image's first row at t = 0 (flipY off, whatever
// the uv origin: hexc flips v itself for bottom-left). A layered role that hexc reads as an array (an entry with
// `layers`, in the WebGL 2 package only) is `loadArray(files, base)`'s texture of its layers' files.
async function loadSampled(base, loader, loadArray) {
  const textures = {};
  await Promise.all(hexc.textures.map(async (t) => {
    const texture = t.layers ? await loadArray(t.layers, base) : await loader.loadAsync(new URL(t.file, base).href);
    texture.flipY = false;
    texture.wrapS = texture.wrapT = THREE.RepeatWrapping;
    texture.magFilter = THREE.LinearFilter;
    texture.minFilter = THREE.LinearMipmapLinearFilter;
    texture.colorSpace = t.colorspace === 'srgb' ? THREE.SRGBColorSpace : THREE.NoColorSpace;
    textures[t.uniform] = texture;
  }));
  return textures;
}
