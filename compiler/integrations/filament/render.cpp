// Renders a compiled hexc Filament package (.filamat) on a quad filling a W x H headless swap chain with Filament's
// OpenGL backend, and writes the frame as PNG (compiler/integrations/filament/check.py runs it under xvfb-run):
//   hexc-filament-render MATERIAL.filamat OUT.png SIZE [--light X,Y,Z] [--no-post] [--int NAME=VALUE] [UNIFORM=FILE[:srgb] ...]
// The quad's uv has (0, 0) at its top-left corner, v down; its tangent frame is the identity: tangent +x (+u),
// bitangent +y (up the image), normal +z towards the camera.
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

#include <cstdint>
#include <cstdio>
#include <cstring>
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
};

const Vertex kQuad[4] = {{{-1, 1, 0}, {0, 0}, {0, 0, 0, 32767}},
                         {{1, 1, 0}, {1, 0}, {0, 0, 0, 32767}},
                         {{-1, -1, 0}, {0, 1}, {0, 0, 0, 32767}},
                         {{1, -1, 0}, {1, 1}, {0, 0, 0, 32767}}};
const uint16_t kIndices[6] = {0, 2, 1, 1, 2, 3};

Texture* loadTexture(Engine& engine, const std::string& file, bool srgb) {
    int w = 0, h = 0, n = 0;
    stbi_uc* pixels = stbi_load(file.c_str(), &w, &h, &n, 4);
    if (!pixels) {
        std::fprintf(stderr, "cannot read %s\n", file.c_str());
        std::exit(1);
    }
    Texture* t = Texture::Builder()
                     .width(uint32_t(w))
                     .height(uint32_t(h))
                     .levels(0xff)
                     .format(srgb ? Texture::InternalFormat::SRGB8_A8 : Texture::InternalFormat::RGBA8)
                     .sampler(Texture::Sampler::SAMPLER_2D)
                     .build(engine);
    t->setImage(engine, 0,
                backend::PixelBufferDescriptor(pixels, size_t(w) * h * 4, backend::PixelDataFormat::RGBA, backend::PixelDataType::UBYTE,
                                               [](void* buffer, size_t, void*) { stbi_image_free(buffer); }));
    t->generateMipmaps(engine);
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr,
                     "usage: %s MATERIAL.filamat OUT.png SIZE [--light X,Y,Z] [--no-post] [--int NAME=VALUE] [UNIFORM=FILE[:srgb] ...]\n",
                     argv[0]);
        return 2;
    }
    std::ifstream in(argv[1], std::ios::binary);
    const std::vector<char> package((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string out = argv[2];
    const uint32_t size = uint32_t(std::stoi(argv[3]));

    Engine* engine = Engine::create(Engine::Backend::OPENGL);
    SwapChain* swapChain = engine->createSwapChain(size, size, SwapChain::CONFIG_READABLE);
    Renderer* renderer = engine->createRenderer();
    Scene* scene = engine->createScene();
    View* view = engine->createView();
    Entity cameraEntity = utils::EntityManager::get().create();
    Camera* camera = engine->createCamera(cameraEntity);
    camera->setProjection(Camera::Projection::ORTHO, -1, 1, -1, 1, 0.1, 10);
    camera->lookAt({0, 0, 1}, {0, 0, 0}, {0, 1, 0});
    view->setCamera(camera);
    view->setScene(scene);
    view->setViewport({0, 0, size, size});

    Material* material = Material::Builder().package(package.data(), package.size()).build(*engine);
    MaterialInstance* instance = material->createInstance();
    TextureSampler sampler(TextureSampler::MinFilter::LINEAR_MIPMAP_LINEAR, TextureSampler::MagFilter::LINEAR,
                           TextureSampler::WrapMode::REPEAT);
    std::vector<Texture*> textures;
    for (int i = 4; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--int" && i + 1 < argc) {  // an int parameter: NAME=VALUE
            const std::string v = argv[++i];
            instance->setParameter(v.substr(0, v.find('=')).c_str(), std::stoi(v.substr(v.find('=') + 1)));
        } else if (arg == "--no-post") {
            view->setPostProcessingEnabled(false);
        } else if (arg == "--light" && i + 1 < argc) {
            float d[3];
            std::sscanf(argv[++i], "%f,%f,%f", &d[0], &d[1], &d[2]);
            Entity light = utils::EntityManager::get().create();
            LightManager::Builder(LightManager::Type::DIRECTIONAL).direction({-d[0], -d[1], -d[2]}).intensity(110000).build(*engine, light);
            scene->addEntity(light);
        } else {
            const size_t eq = arg.find('=');
            std::string file = arg.substr(eq + 1);
            const bool srgb = file.ends_with(":srgb");
            if (srgb) file.resize(file.size() - 5);
            textures.push_back(loadTexture(*engine, file, srgb));
            instance->setParameter(arg.substr(0, eq).c_str(), textures.back(), sampler);
        }
    }

    VertexBuffer* vertices = VertexBuffer::Builder()
                                 .vertexCount(4)
                                 .bufferCount(1)
                                 .attribute(VertexAttribute::POSITION, 0, VertexBuffer::AttributeType::FLOAT3, 0, sizeof(Vertex))
                                 .attribute(VertexAttribute::UV0, 0, VertexBuffer::AttributeType::FLOAT2, 12, sizeof(Vertex))
                                 .attribute(VertexAttribute::TANGENTS, 0, VertexBuffer::AttributeType::SHORT4, 20, sizeof(Vertex))
                                 .normalized(VertexAttribute::TANGENTS)
                                 .build(*engine);
    vertices->setBufferAt(*engine, 0, VertexBuffer::BufferDescriptor(kQuad, sizeof(kQuad), nullptr));
    IndexBuffer* indices = IndexBuffer::Builder().indexCount(6).bufferType(IndexBuffer::IndexType::USHORT).build(*engine);
    indices->setBuffer(*engine, IndexBuffer::BufferDescriptor(kIndices, sizeof(kIndices), nullptr));
    Entity quad = utils::EntityManager::get().create();
    RenderableManager::Builder(1)
        .boundingBox({{-1, -1, -1}, {1, 1, 1}})
        .material(0, instance)
        .geometry(0, RenderableManager::PrimitiveType::TRIANGLES, vertices, indices, 0, 6)
        .culling(false)
        .build(*engine, quad);
    scene->addEntity(quad);

    std::vector<uint8_t> pixels(size_t(size) * size * 4);
    bool read = false;
    for (int frame = 0; frame < 3 && !read; ++frame) {
        if (!renderer->beginFrame(swapChain)) continue;
        renderer->render(view);
        if (frame == 2)
            renderer->readPixels(0, 0, size, size,
                                 backend::PixelBufferDescriptor(
                                     pixels.data(), pixels.size(), backend::PixelDataFormat::RGBA, backend::PixelDataType::UBYTE,
                                     [](void*, size_t, void* user) { *static_cast<bool*>(user) = true; }, &read));
        renderer->endFrame();
        engine->flushAndWait();
    }
    engine->flushAndWait();
    // OpenGL reads the bottom row first.
    std::vector<uint8_t> flipped(pixels.size());
    for (uint32_t y = 0; y < size; ++y)
        std::memcpy(&flipped[size_t(y) * size * 4], &pixels[size_t(size - 1 - y) * size * 4], size_t(size) * 4);
    const bool ok = read && stbi_write_png(out.c_str(), int(size), int(size), 4, flipped.data(), int(size) * 4);
    engine->destroy(quad);
    Engine::destroy(&engine);
    if (!ok) std::fprintf(stderr, "no frame read back\n");
    return ok ? 0 : 1;
}
