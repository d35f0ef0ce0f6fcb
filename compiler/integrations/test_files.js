// What the web engines' test drivers share: a package made with some of its textures loaded from other files.

// `make()` (which loads the package's textures) with each texture file of the package named in `files` (a file name ->
// another file beside the module) loaded from the other file, as a package whose data named them so would: a layer's
// textures exchanged with another layer's, a splat map with its channels swapped (the negative controls of
// tests/engines/web_test.py). The package's data is as it was after.
export async function withFiles(pkg, files, make) {
  if (!files) return make();
  const saved = pkg.data.textures.map((t) => ({ ...t }));
  const renamed = (file) => files[file] ?? file;
  for (const t of pkg.data.textures) Object.assign(t, t.layers ? { layers: t.layers.map(renamed) } : { file: renamed(t.file) });
  try {
    return await make();
  } finally {
    saved.forEach((t, i) => Object.assign(pkg.data.textures[i], t));
  }
}
