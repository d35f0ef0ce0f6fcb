shader_type spatial;
// hexc material `${material}` for Godot 3 (docs/engines.md#godot): its hex-tiled slots feed Godot's own lighting.
// Godot's texture coordinates: ${uvorigin}. Bind each texture below to the slot's file (manifest: slots[].texture)
// with mipmaps, repeat and filtering on; an sRGB slot's with its sRGB flag (hint_albedo).
${uniforms}
// hexc's functions for this material (hexc --functions, Godot's shading language).
${functions}
void fragment() {
${inputs}
}
