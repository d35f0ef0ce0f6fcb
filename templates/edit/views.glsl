// `hexc edit`'s views of a material in one program (compiler/edit/views.cpp appends this to the material's template,
// whose `main` it renames hexcEditShaded): what the page draws is chosen by two specialisation constants, which
// SPIRV-Cross's GLSL ES leaves as macros (SPIRV_CROSS_CONSTANT_ID_<id>) that the page defines when it links each view
// (compiler/edit/page/view.js), so that showing another view or slot links again and compiles nothing on the server.
// hexcEditView: 0 the template's own shading, 1 a slot's values as the built-in `value` template shows them, 2 its
// weights as `weights` does, 3 a layered material's weight of one layer; hexcEditSlot: the slot, by its index in the
// material (view 3: the layer). Tokens: ${output}, the template's colour output; ${slots}, one `slot` section per slot
// of the material (${index}, ${name}); ${layer}, the `layer` section for a layered material (${role}: its first role).

//@ rename
// Inserted after the template's #version line.
#define main hexcEditShaded

//@ views
#undef main
layout(location = 15) in vec2 hexcEditUv;  // the texture coordinate, for the views (a location no template uses)
layout(constant_id = 1000) const int hexcEditView = 0;
layout(constant_id = 1001) const int hexcEditSlot = 0;

// A slot's result as the `value` template writes it: colour as is, a scalar as grey, a normal slot's derivative
// (dH/du, dH/dy, 0, 1), a triplanar normal slot's surface gradient (x, y, z, 1).
vec4 hexcEditValue(vec4 v) { return v; }
vec4 hexcEditValue(float v) { return vec4(vec3(v), 1.0); }
vec4 hexcEditValue(vec2 d) { return vec4(d, 0.0, 1.0); }
vec4 hexcEditValue(vec3 g) { return vec4(g, 1.0); }

void main() {
    if (hexcEditView == 0) {
        hexcEditShaded();
        return;
    }
${layer}
#if defined(HEXC_PROJECTION_triplanar)
    // A triplanar material on the unit sphere, as the `value` and `weights` templates show it.
    vec3 position, normal;
    hexcPreviewSphere(hexcEditUv, position, normal);
#define HEXC_EDIT_AT position, normal
#else
#define HEXC_EDIT_AT hexcEditUv
#endif
    // One call per slot gives both views: every call is a copy of the slot's code once inlined.
    vec4 value = vec4(0.0);
    vec3 weights = vec3(0.0);
${slots}
    ${output} = hexcEditView == 1 ? value : vec4(weights, 1.0);
}

//@ slot
    if (hexcEditSlot == ${index}) value = hexcEditValue(hexc_${name}(HEXC_EDIT_AT, weights));

//@ layer
    // The layers' weights at the pixel, as the roles blend by them (templates/library/layers.glsl): a role's read fills
    // them; what it fetches besides is not used and the optimiser drops it.
    if (hexcEditView == 3) {
        hexc_${role}(hexcEditUv);
        // The index is a constant in every view's program: in range in those that do not show a layer (0) too.
        ${output} = vec4(vec3(hexcLayersW[hexcEditView == 3 ? hexcEditSlot : 0]), 1.0);
        return;
    }
