// Renders a compiled hexc Filament package (.filamat) on a quad filling a W x H headless swap chain with Filament's
// OpenGL backend, and writes the frame as PNG (compiler/integrations/filament/check.py runs it under Xvfb):
//   hexc-filament-render MATERIAL.filamat OUT.png SIZE [--uv U0,V0,U1,V1] [--colors R,G,B,A,...] [--marker MARKER.filamat]
//                        [--light X,Y,Z] [--no-post] [--int NAME=VALUE] [UNIFORM=FILE[:srgb] ...]
// The quad's uv is (U0, V0) at its top-left corner and (U1, V1) at its bottom-right (default 0,0,1,1: uv (0, 0) at the
// top-left, v down; 0,1,1,0 is a GL-convention mesh, (0, 0) at the bottom-left, v up); --colors gives its vertex
// colours (COLOR: 16 numbers, RGBA at the top-left, top-right, bottom-left and bottom-right; default white); its tangent frame is the
// identity: tangent +x (+u), bitangent +y (up the screen), normal +z towards the camera. --marker draws a second
// renderable with that material over the screen's top-left corner (a sixteenth of the side), so that the image's
// orientation can be checked. The frame is written as Filament's readPixels returns it: top row first (Renderer.h).
// A texture FILE is 8-bit (PNG, by stb) or, named .exr, float RGBA (OpenEXR, by tinyexr: a histogram slot's Gaussian
// texture and table), uploaded as RGBA32F; every texture gets its full mip chain.
#include <backend/PixelBufferDescriptor.h>
#include <filament/Camera.h>
#include <filament/Engine.h>
#include <filament/IndexBuffer.h>
#include <filament/LightManager.h>
#include <filament/Material.h>
#include <filament/MaterialInstance.h>
#include <filament/RenderableManager.h>
#include <filament/Renderer.h>
#include <filament/Scene.h>
#include <filament/SwapChain.h>
#include <filament/Texture.h>
#include <filament/TextureSampler.h>
#include <filament/VertexBuffer.h>
#include <filament/View.h>
#include <filament/Viewport.h>
#include <utils/EntityManager.h>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace filament;
using utils::Entity;

namespace {

struct Vertex {
    float position[3];
    float uv[2];
    int16_t tangents[4];  // the tangent frame as a quaternion, snorm16: identity
    float color[4];
};

const uint16_t kIndices[6] = {0, 2, 1, 1, 2, 3};

// A quad from (x0, y0) at its top-left to (x1, y1) at its bottom-right in clip space, at depth z, with uv (u0, v0) at
// the top-left and (u1, v1) at the bottom-right, and the colours `c` at its corners (RGBA: top-left, top-right,
// bottom-left, bottom-right).
struct Quad {
    Vertex vertices[4];
    Quad(float x0, float y0, float x1, float y1, float z, const float uv[4], const float c[16])
        : vertices{{{x0, y0, z}, {uv[0], uv[1]}, {0, 0, 0, 32767}, {c[0], c[1], c[2], c[3]}},
                   {{x1, y0, z}, {uv[2], uv[1]}, {0, 0, 0, 32767}, {c[4], c[5], c[6], c[7]}},
                   {{x0, y1, z}, {uv[0], uv[3]}, {0, 0, 0, 32767}, {c[8], c[9], c[10], c[11]}},
                   {{x1, y1, z}, {uv[2], uv[3]}, {0, 0, 0, 32767}, {c[12], c[13], c[14], c[15]}}} {}
};

// Adds `quad` to `scene` with `instance`; the quad must outlive the engine's use of it (the upload does not copy).
Entity addQuad(Engine& engine, Scene& scene, const Quad& quad, MaterialInstance* instance) {
    VertexBuffer* vertices = VertexBuffer::Builder()
                                 .vertexCount(4)
                                 .bufferCount(1)
                                 .attribute(VertexAttribute::POSITION, 0, VertexBuffer::AttributeType::FLOAT3, 0, sizeof(Vertex))
                                 .attribute(VertexAttribute::UV0, 0, VertexBuffer::AttributeType::FLOAT2, 12, sizeof(Vertex))
                                 .attribute(VertexAttribute::TANGENTS, 0, VertexBuffer::AttributeType::SHORT4, 20, sizeof(Vertex))
                                 .normalized(VertexAttribute::TANGENTS)
                                 .attribute(VertexAttribute::COLOR, 0, VertexBuffer::AttributeType::FLOAT4, 28, sizeof(Vertex))
                                 .build(engine);
    vertices->setBufferAt(engine, 0, VertexBuffer::BufferDescriptor(quad.vertices, sizeof(quad.vertices), nullptr));
    IndexBuffer* indices = IndexBuffer::Builder().indexCount(6).bufferType(IndexBuffer::IndexType::USHORT).build(engine);
    indices->setBuffer(engine, IndexBuffer::BufferDescriptor(kIndices, sizeof(kIndices), nullptr));
    Entity entity = utils::EntityManager::get().create();
    RenderableManager::Builder(1)
        .boundingBox({{-1, -1, -1}, {1, 1, 1}})
        .material(0, instance)
        .geometry(0, RenderableManager::PrimitiveType::TRIANGLES, vertices, indices, 0, 6)
        .culling(false)
        .build(engine, entity);
    scene.addEntity(entity);
    return entity;
}

std::vector<char> readFile(const char* path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The texels of `file`, 8-bit (stb) or float (an .exr, tinyexr), as Filament uploads them; exits on a file it cannot read.
backend::PixelBufferDescriptor texels(const std::string& file, int& w, int& h) {
    if (file.ends_with(".exr")) {
        float* rgba = nullptr;
        const char* error = nullptr;
        if (LoadEXR(&rgba, &w, &h, file.c_str(), &error) != TINYEXR_SUCCESS) {
            std::fprintf(stderr, "cannot read %s: %s\n", file.c_str(), error ? error : "");
            std::exit(1);
        }
        return {rgba, size_t(w) * h * 16, backend::PixelDataFormat::RGBA, backend::PixelDataType::FLOAT,
                [](void* buffer, size_t, void*) { std::free(buffer); }};
    }
    int n = 0;
    stbi_uc* pixels = stbi_load(file.c_str(), &w, &h, &n, 4);
    if (!pixels) {
        std::fprintf(stderr, "cannot read %s\n", file.c_str());
        std::exit(1);
    }
    return {pixels, size_t(w) * h * 4, backend::PixelDataFormat::RGBA, backend::PixelDataType::UBYTE,
            [](void* buffer, size_t, void*) { stbi_image_free(buffer); }};
}

Texture* loadTexture(Engine& engine, const std::string& file, bool srgb) {
    int w = 0, h = 0;
    backend::PixelBufferDescriptor data = texels(file, w, h);
    const bool exr = file.ends_with(".exr");
    Texture* t = Texture::Builder()
                     .width(uint32_t(w))
                     .height(uint32_t(h))
                     .levels(0xff)
                     .format(exr    ? Texture::InternalFormat::RGBA32F
                             : srgb ? Texture::InternalFormat::SRGB8_A8
                                    : Texture::InternalFormat::RGBA8)
                     .sampler(Texture::Sampler::SAMPLER_2D)
                     .build(engine);
    t->setImage(engine, 0, std::move(data));
    t->generateMipmaps(engine);
    return t;
}

// Renders three frames (the shaders compile and the textures upload in the first) and reads the last back.
bool renderAndRead(Engine& engine, Renderer& renderer, SwapChain& swapChain, View& view, uint32_t size, std::vector<uint8_t>& pixels) {
    bool read = false;
    for (int frame = 0; frame < 3 && !read; ++frame) {
        if (!renderer.beginFrame(&swapChain)) continue;
        renderer.render(&view);
        if (frame == 2)
            renderer.readPixels(0, 0, size, size,
                                backend::PixelBufferDescriptor(
                                    pixels.data(), pixels.size(), backend::PixelDataFormat::RGBA, backend::PixelDataType::UBYTE,
                                    [](void*, size_t, void* user) { *static_cast<bool*>(user) = true; }, &read));
        renderer.endFrame();
        engine.flushAndWait();
    }
    engine.flushAndWait();
    return read;
}

// The options after SIZE: the mesh's uv, the marker, the light, post-processing, int parameters and textures.
struct Options {
    float uv[4] = {0, 0, 1, 1};
    std::vector<float> colors = std::vector<float>(16, 1.0f);  // white
    std::vector<char> marker;
};

Options applyOptions(int argc, char** argv, Engine& engine, Scene& scene, View& view, MaterialInstance& instance,
                     std::vector<Texture*>& textures) {
    Options o;
    const TextureSampler sampler(TextureSampler::MinFilter::LINEAR_MIPMAP_LINEAR, TextureSampler::MagFilter::LINEAR,
                                 TextureSampler::WrapMode::REPEAT);
    for (int i = 4; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--int" && i + 1 < argc) {  // an int parameter: NAME=VALUE
            const std::string v = argv[++i];
            instance.setParameter(v.substr(0, v.find('=')).c_str(), std::stoi(v.substr(v.find('=') + 1)));
        } else if (arg == "--uv" && i + 1 < argc) {
            std::sscanf(argv[++i], "%f,%f,%f,%f", &o.uv[0], &o.uv[1], &o.uv[2], &o.uv[3]);
        } else if (arg == "--colors" && i + 1 < argc) {
            const std::string v = argv[++i];
            size_t at = 0;
            for (float& c : o.colors) {
                c = std::stof(v.substr(at));
                at = v.find(',', at) + 1;
            }
        } else if (arg == "--marker" && i + 1 < argc) {
            o.marker = readFile(argv[++i]);
        } else if (arg == "--no-post") {
            view.setPostProcessingEnabled(false);
        } else if (arg == "--light" && i + 1 < argc) {
            float d[3];
            std::sscanf(argv[++i], "%f,%f,%f", &d[0], &d[1], &d[2]);
            Entity light = utils::EntityManager::get().create();
            LightManager::Builder(LightManager::Type::DIRECTIONAL).direction({-d[0], -d[1], -d[2]}).intensity(110000).build(engine, light);
            scene.addEntity(light);
        } else {
            const size_t eq = arg.find('=');
            std::string file = arg.substr(eq + 1);
            const bool srgb = file.ends_with(":srgb");
            if (srgb) file.resize(file.size() - 5);
            textures.push_back(loadTexture(engine, file, srgb));
            instance.setParameter(arg.substr(0, eq).c_str(), textures.back(), sampler);
        }
    }
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr,
                     "usage: %s MATERIAL.filamat OUT.png SIZE [--uv U0,V0,U1,V1] [--colors R,G,B,A,...] [--marker MARKER.filamat] "
                     "[--light X,Y,Z] [--no-post] [--int NAME=VALUE] [UNIFORM=FILE[:srgb] ...]\n",
                     argv[0]);
        return 2;
    }
    const std::vector<char> package = readFile(argv[1]);
    const std::string out = argv[2];
    const uint32_t size = uint32_t(std::stoi(argv[3]));

    Engine* engine = Engine::create(Engine::Backend::OPENGL);
    SwapChain* swapChain = engine->createSwapChain(size, size, SwapChain::CONFIG_READABLE);
    Renderer* renderer = engine->createRenderer();
    Scene* scene = engine->createScene();
    View* view = engine->createView();
    Camera* camera = engine->createCamera(utils::EntityManager::get().create());
    camera->setProjection(Camera::Projection::ORTHO, -1, 1, -1, 1, 0.1, 10);
    camera->lookAt({0, 0, 1}, {0, 0, 0}, {0, 1, 0});
    view->setCamera(camera);
    view->setScene(scene);
    view->setViewport({0, 0, size, size});

    Material* material = Material::Builder().package(package.data(), package.size()).build(*engine);
    MaterialInstance* instance = material->createInstance();
    std::vector<Texture*> textures;
    const Options o = applyOptions(argc, argv, *engine, *scene, *view, *instance, textures);
    const Quad quad(-1, 1, 1, -1, 0, o.uv, o.colors.data());
    addQuad(*engine, *scene, quad, instance);
    const Quad marker(-1, 1, -1 + 2.0f / 16, 1 - 2.0f / 16, 0.5f, o.uv, Options().colors.data());  // nearer the camera than the quad
    if (!o.marker.empty()) {
        Material* m = Material::Builder().package(o.marker.data(), o.marker.size()).build(*engine);
        addQuad(*engine, *scene, marker, m->createInstance());
    }

    std::vector<uint8_t> pixels(size_t(size) * size * 4);
    const bool ok = renderAndRead(*engine, *renderer, *swapChain, *view, size, pixels) &&
                    stbi_write_png(out.c_str(), int(size), int(size), 4, pixels.data(), int(size) * 4);
    Engine::destroy(&engine);
    if (!ok) std::fprintf(stderr, "no frame read back\n");
    return ok ? 0 : 1;
}
