// hexc's WGSL in Chromium's WebGPU (Dawn, with Tint as its WGSL compiler; SwiftShader on a machine without a GPU).
// window.hexcWgsl.validate(codes): Tint's verdict on each module: {errors, warnings}, errors including any validation
// error Dawn raised while creating it (Tint's uniformity analysis among them).
// window.hexcWgsl.render(config): draws a fragment module over a uv rectangle with the textures given (each at its
// binding, every mip level from hexc-expect's files) and returns its RGBA32F pixels, top row first, base64-encoded.
// The vertex module is hexc's own pass-through stage (--vertex), fed the inputs its manifest lists (triangle).

let device;

async function gpu() {
    if (device) return device;
    if (!navigator.gpu) throw new Error("no navigator.gpu: Chromium needs --enable-unsafe-webgpu (and --headless=new)");
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) throw new Error("WebGPU gave no adapter");
    // The histogram blend's Gaussian texture and table are float32, which WebGPU filters only with this feature.
    device = await adapter.requestDevice({ requiredFeatures: adapter.features.has("float32-filterable") ? ["float32-filterable"] : [] });
    return device;
}

const text = (m) => `${m.lineNum}:${m.linePos}: ${m.message}`;

async function compile(code) {
    const d = await gpu();
    d.pushErrorScope("validation");
    const module = d.createShaderModule({ code });
    const messages = (await module.getCompilationInfo()).messages;
    const scope = await d.popErrorScope();
    const errors = messages.filter((m) => m.type === "error").map(text);
    if (scope && !errors.length) errors.push(scope.message);
    return { module, errors, warnings: messages.filter((m) => m.type !== "error").map(text) };
}

async function validate(codes) {
    const verdicts = [];
    for (const code of codes) {
        const { errors, warnings } = await compile(code);
        verdicts.push({ errors, warnings });
    }
    return verdicts;
}

// A texture from hexc-expect's files (tests/execution/expect.cpp): every mip level of every layer (one, or a layers
// role's texture array's), raw, in its WebGPU format.
async function texture(d, { format, layers }) {
    const bytesPerTexel = format === "rgba32float" ? 16 : 4;
    const t = d.createTexture({ size: [layers[0][0].width, layers[0][0].height, layers.length], format, mipLevelCount: layers[0].length,
                                usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    for (const [layer, levels] of layers.entries()) {
        for (const [mipLevel, { width, height, url }] of levels.entries()) {
            const data = await (await fetch(url)).arrayBuffer();
            if (data.byteLength !== width * height * bytesPerTexel) throw new Error(`${url}: ${data.byteLength} bytes for ${width}x${height}`);
            d.queue.writeTexture({ texture: t, mipLevel, origin: [0, 0, layer] }, data, { bytesPerRow: width * bytesPerTexel },
                                 [width, height]);
        }
    }
    return t;
}

// What the harness's full-screen draw (templates/harness/fullscreen.vert.glsl) gives each stage input at its vertex t:
// the position, the uv, the plane's normal and the vertex colour (1 - t.x, t.x, t.y, 1 - t.y).
const feeds = {
    gl_Position: ([tx, ty]) => [tx * 2 - 1, ty * 2 - 1, 0, 1],
    v_uv: ([tx, ty], [u0, v0, u1, v1]) => [u0 + tx * (u1 - u0), v0 + ty * (v1 - v0)],
    v_normal: () => [0, 0, 1],
    hexcVertexColor: ([tx, ty]) => [1 - tx, tx, ty, 1 - ty],
};

// The full-screen triangle of templates/harness/fullscreen.vert.glsl, in Vulkan's clip space (y = -1 the top row, which
// hexc's vertex stage flips for WebGPU): t = (0,0), (2,0), (0,2), each of the manifest's vertex `attributes` fed as there,
// one interleaved float32 buffer. Returns it and its layout.
function triangle(d, rect, attributes) {
    const values = [[0, 0], [2, 0], [0, 2]].map((t) => attributes.map(({ feeds: name }) => {
        if (!feeds[name]) throw new Error(`the page cannot feed the vertex input ${name}`);
        return feeds[name](t, rect);
    }));
    const data = new Float32Array(values.flat(2));
    const buffer = d.createBuffer({ size: data.byteLength, usage: GPUBufferUsage.VERTEX, mappedAtCreation: true });
    new Float32Array(buffer.getMappedRange()).set(data);
    buffer.unmap();
    let offset = 0;
    const layout = values[0].map((v, i) => {
        const attribute = { shaderLocation: attributes[i].location, offset, format: `float32x${v.length}` };
        offset += v.length * 4;
        return attribute;
    });
    return { buffer, layout: { arrayStride: offset, attributes: layout } };
}

async function render({ vertex, fragment, vertexEntry, fragmentEntry, attributes, textures, sampler, width, height, rect }) {
    const d = await gpu();
    const vertices = triangle(d, rect, attributes);
    const stages = [await compile(vertex), await compile(fragment)];
    const failed = stages.flatMap((s) => s.errors);
    if (failed.length) throw new Error("Tint rejected the shader: " + failed.join("; "));
    // The layout from the manifest, as an engine builds it: every texture it lists, even one the shader does not read
    // (the lattice weights at falloffcontrast 0 read none); empty groups below hexc's.
    const visibility = GPUShaderStage.FRAGMENT;
    const group = d.createBindGroupLayout({ entries: [{ binding: sampler.binding, visibility, sampler: { type: "filtering" } },
        ...textures.map((t) => ({ binding: t.binding, visibility, texture: { sampleType: "float", viewDimension: t.array ? "2d-array" : "2d" } }))] });
    const groups = Array.from({ length: sampler.group + 1 }, (_, g) => (g === sampler.group ? group : d.createBindGroupLayout({ entries: [] })));
    d.pushErrorScope("validation");
    const pipeline = d.createRenderPipeline({
        layout: d.createPipelineLayout({ bindGroupLayouts: groups }),
        vertex: { module: stages[0].module, entryPoint: vertexEntry, buffers: [vertices.layout] },
        fragment: { module: stages[1].module, entryPoint: fragmentEntry, targets: [{ format: "rgba32float" }] },
        primitive: { topology: "triangle-list" },
    });
    const entries = [{ binding: sampler.binding, resource: d.createSampler({
        addressModeU: "repeat", addressModeV: "repeat", magFilter: "linear", minFilter: "linear", mipmapFilter: "linear" }) }];
    for (const t of textures) entries.push({ binding: t.binding, resource: (await texture(d, t)).createView({ dimension: t.array ? "2d-array" : "2d" }) });
    const bindGroup = d.createBindGroup({ layout: group, entries });
    const target = d.createTexture({ size: [width, height], format: "rgba32float",
                                     usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
    const readback = d.createBuffer({ size: width * height * 16, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
    const encoder = d.createCommandEncoder();
    const pass = encoder.beginRenderPass({ colorAttachments: [{ view: target.createView(), loadOp: "clear", storeOp: "store",
                                                                 clearValue: [0, 0, 0, 0] }] });
    pass.setPipeline(pipeline);
    pass.setBindGroup(sampler.group, bindGroup);
    pass.setVertexBuffer(0, vertices.buffer);
    pass.draw(3);
    pass.end();
    encoder.copyTextureToBuffer({ texture: target }, { buffer: readback, bytesPerRow: width * 16 }, [width, height]);
    d.queue.submit([encoder.finish()]);
    const error = await d.popErrorScope();
    if (error) throw new Error(error.message);
    const started = performance.now();
    await readback.mapAsync(GPUMapMode.READ);
    const bytes = new Uint8Array(readback.getMappedRange().slice(0));
    readback.unmap();
    let binary = "";
    for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    return { pixels: btoa(binary), ms: performance.now() - started };
}

window.hexcWgsl = { validate, render };
window.hexcReady = true;
