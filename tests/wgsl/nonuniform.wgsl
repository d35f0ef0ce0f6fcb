// Tint must refuse this: a textureSample under a branch on a stage input (non-uniform control flow).
@group(0) @binding(0) var t: texture_2d<f32>;
@group(0) @binding(1) var s: sampler;
@fragment fn main(@location(0) uv: vec2<f32>) -> @location(0) vec4<f32> {
    var c = vec4<f32>(0.0);
    if (uv.x > 0.5) { c = textureSample(t, s, uv); }
    return c;
}
