// What the WebGPU test drivers share (Babylon.js's, three.js WebGPU's), a workaround for the test environment only, not
// for a package's users: headless Chromium on SwiftShader has no shared image for a WebGPU canvas's swap chain (its GPU
// process logs "Could not find SharedImageBackingFactory with params: usage: ...|WebgpuSwapChainTexture|..." and
// "SharedImageStub: Unable to create shared image") and loses the device after a few presented frames
// (docs/engines.md). The canvas context hands the engine an ordinary texture of the configured format and usage
// instead, which it draws into and the driver reads back (getCurrentTexture() after the frame); nothing is presented.
let kept = false;

export function keepWebGpuOffTheSwapChain() {
  if (kept) return;
  kept = true;
  const configured = new WeakMap();
  GPUCanvasContext.prototype.configure = function (configuration) { configured.set(this, { configuration, texture: null }); };
  GPUCanvasContext.prototype.getCurrentTexture = function () {
    const entry = configured.get(this);
    const { device, format, usage } = entry.configuration;
    const { width, height } = this.canvas;
    if (!entry.texture || entry.texture.width !== width || entry.texture.height !== height) {
      entry.texture?.destroy();
      entry.texture = device.createTexture({ size: [width, height], format, usage: usage | GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
    }
    return entry.texture;
  };
}
