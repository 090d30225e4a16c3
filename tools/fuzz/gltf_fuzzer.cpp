// libFuzzer target for engine::loadGltf. Each input is written into a private
// scene folder as scene.gltf and as scene.glb and loaded from both (the loader picks the
// container by GLB magic or by the .glb extension, so both names matter).
//
// Expected outcome for bad input: engine::InputError. Findings: any other exception, a
// crash, an ASan/UBSan report, a leak, a timeout, a huge allocation (run.sh sets the
// libFuzzer limits), or a loaded Scene that breaks the contract in Scene.h (an index out
// of range, a primitive that is not a triangle list...).
#include "engine/gltf/GltfLoader.h"
#include "engine/scene/Deform.h"
#include "engine/util/Error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <system_error>
#include <typeinfo>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path gFolder;      // the private scene folder, made once per process
bool gVerbose = false;  // GLTF_FUZZ_VERBOSE=1: print each load's outcome (for triage)

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "\n==gltf_fuzzer== FINDING: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();  // libFuzzer saves the input as crash-<sha1>
}

void writeFile(const fs::path& path, const void* data, std::size_t size) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) finding("harness: cannot write " + path.string());
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    while (size > 0) {
        const ssize_t written = ::write(fd, bytes, size);
        if (written <= 0) finding("harness: short write to " + path.string());
        bytes += written;
        size -= static_cast<std::size_t>(written);
    }
    ::close(fd);
}

// A 2x2 RGBA PNG, so an image URI 'tex.png' has something real to decode.
constexpr std::uint8_t kTinyPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x06, 0x00, 0x00, 0x00, 0x72, 0xb6, 0x0d,
    0x24, 0x00, 0x00, 0x00, 0x10, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0xf0,
    0x1f, 0x0a, 0x21, 0x14, 0x00, 0x45, 0xcc, 0x07, 0xf9, 0x66, 0xcb, 0xff, 0x39, 0x00, 0x00, 0x00,
    0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

// Neighbours a hostile URI may name: real files, and the hazards from the tinygltf notes (a
// directory, a FIFO, a symlink leading out of the folder).
void populateFolder() {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(GLTF_FUZZ_SCENES_DIR, error))
        if (entry.is_regular_file() && entry.path().extension() != ".gltf")
            fs::copy_file(entry.path(), gFolder / entry.path().filename(), error);
    writeFile(gFolder / "tex.png", kTinyPng, sizeof kTinyPng);
    fs::create_directory(gFolder / "dir", error);
    ::mkfifo((gFolder / "pipe.bin").c_str(), 0644);
    const fs::path outside = gFolder.parent_path() / (gFolder.filename().string() + "-outside.bin");
    const std::uint8_t secret[16] = {};
    writeFile(outside, secret, sizeof secret);
    fs::create_symlink(outside, gFolder / "link.bin", error);
}

void removeFolder() {
    std::error_code error;
    fs::remove(gFolder.parent_path() / (gFolder.filename().string() + "-outside.bin"), error);
    fs::remove_all(gFolder, error);
}

bool inRange(int index, std::size_t size, bool optional) {
    return (optional && index == -1) || (index >= 0 && static_cast<std::size_t>(index) < size);
}

// Primitive::tangents and DeformedPrimitive::tangents: unit xyz (to float rounding), w +-1.
bool isUnitTangent(const glm::vec4& t) {
    const float length = std::sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
    return std::fabs(length - 1.0f) < 1e-5f && (t.w == 1.0f || t.w == -1.0f);
}

// A material's texture reference: its image exists, its UV set is drawn, its transform is
// finite and its sampler holds glTF's enumerants.
void checkTextureRef(const engine::TextureRef& texture, const engine::Scene& scene, const std::string& name) {
    if (!inRange(texture.image, scene.images.size(), true)) finding(name + ": texture image out of range");
    if (texture.texCoord != 0 && texture.texCoord != 1) finding(name + ": texCoord is not 0 or 1");
    const engine::UvTransform& t = texture.transform;
    if (!std::isfinite(t.offset.x) || !std::isfinite(t.offset.y) || !std::isfinite(t.rotation) ||
        !std::isfinite(t.scale.x) || !std::isfinite(t.scale.y))
        finding(name + ": texture transform not finite");
    const engine::Sampler& s = texture.sampler;
    const auto oneOf = [](int value, std::initializer_list<int> allowed) {
        return std::find(allowed.begin(), allowed.end(), value) != allowed.end();
    };
    if (!oneOf(s.magFilter, {9728, 9729}) || !oneOf(s.minFilter, {9728, 9729, 9984, 9985, 9986, 9987}) ||
        !oneOf(s.wrapS, {33071, 33648, 10497}) || !oneOf(s.wrapT, {33071, 33648, 10497}))
        finding(name + ": sampler enumerant outside glTF's");
}

// What Scene.h promises the renderer; the loader's validation exists to make these true.
void checkSceneContract(const engine::Scene& scene) {
    const std::size_t nodes = scene.nodes.size();
    for (std::size_t i = 0; i < nodes; ++i) {
        const engine::Node& node = scene.nodes[i];
        const std::string name = "nodes[" + std::to_string(i) + "]";
        if (!inRange(node.mesh, scene.meshes.size(), true)) finding(name + ".mesh out of range");
        if (!inRange(node.camera, scene.cameras.size(), true)) finding(name + ".camera out of range");
        if (!inRange(node.light, scene.lights.size(), true)) finding(name + ".light out of range");
        if (!inRange(node.parent, nodes, true)) finding(name + ".parent out of range");
        for (int child : node.children)
            if (!inRange(child, nodes, false) || scene.nodes[child].parent != static_cast<int>(i))
                finding(name + " has a child that is out of range or has another parent");
    }
    for (int root : scene.roots)
        if (!inRange(root, nodes, false) || scene.nodes[root].parent != -1)
            finding("root " + std::to_string(root) + " out of range or not a root");
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        for (const engine::Primitive& p : scene.meshes[m].primitives) {
            const std::string name = "meshes[" + std::to_string(m) + "] primitive";
            if (p.indices.size() % 3 != 0) finding(name + ": indices are not a triangle list");
            for (std::uint32_t index : p.indices)
                if (index >= p.positions.size()) finding(name + ": index past the vertex count");
            if (p.normals.size() != p.positions.size()) finding(name + ": normal count != vertex count");
            if (!p.texcoords.empty() && p.texcoords.size() != p.positions.size())
                finding(name + ": texcoord count != vertex count");
            if (!p.texcoords1.empty() && p.texcoords1.size() != p.positions.size())
                finding(name + ": texcoord1 count != vertex count");
            if (!p.colors.empty() && p.colors.size() != p.positions.size())
                finding(name + ": color count != vertex count");
            for (const glm::vec4& c : p.colors)
                if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b) || !std::isfinite(c.a))
                    finding(name + ": color not finite");
            for (const auto* uvs : {&p.texcoords, &p.texcoords1})
                for (const glm::vec2& uv : *uvs)
                    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) finding(name + ": texcoord not finite");
            if (!p.tangents.empty() && p.tangents.size() != p.positions.size())
                finding(name + ": tangent count != vertex count");
            for (const glm::vec4& t : p.tangents)
                if (!isUnitTangent(t)) finding(name + ": tangent not unit length with w = +1 or -1");
            if (!inRange(p.material, scene.materials.size(), true)) finding(name + ": material out of range");
            for (const glm::vec3& v : p.positions)
                if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                    finding(name + ": position not finite");
        }
    }
    for (const engine::Material& material : scene.materials) {
        const std::string name = "material '" + material.name + "'";
        for (const engine::TextureRef* texture : {&material.baseColorTexture, &material.metallicRoughnessTexture,
                                                  &material.normalTexture, &material.occlusionTexture,
                                                  &material.emissiveTexture})
            checkTextureRef(*texture, scene, name);
        if (!std::isfinite(material.normalScale)) finding(name + ": normalScale not finite");
        if (!(material.occlusionStrength >= 0.0f && material.occlusionStrength <= 1.0f))
            finding(name + ": occlusionStrength not in [0, 1]");
        if (!std::isfinite(material.blendShadowCutoff) || material.blendShadowCutoff < 0.0f)
            finding(name + ": blendShadowCutoff not a finite number >= 0");
    }
    for (const engine::Image& image : scene.images)
        if (image.width <= 0 || image.height <= 0 ||
            image.rgba8.size() != static_cast<std::size_t>(image.width) * image.height * 4)
            finding("image '" + image.name + "': pixel buffer does not match its size");
    for (const auto& instance : scene.meshInstances)
        if (!inRange(instance.node, nodes, false) || !inRange(instance.mesh, scene.meshes.size(), false))
            finding("mesh instance out of range");
    for (const auto& instance : scene.lightInstances)
        if (!inRange(instance.node, nodes, false) || !inRange(instance.light, scene.lights.size(), false))
            finding("light instance out of range");
    for (const auto& instance : scene.cameraInstances)
        if (!inRange(instance.node, nodes, false) || !inRange(instance.camera, scene.cameras.size(), false))
            finding("camera instance out of range");
}

// What Animation.h promises poseAnimation, then a pose at the start, middle and end of
// every animation (which runs the sampling under the sanitizers) must stay finite.
void checkAnimationContract(engine::Scene scene) {
    for (std::size_t a = 0; a < scene.animations.size(); ++a) {
        const engine::Animation& animation = scene.animations[a];
        const std::string name = "animations[" + std::to_string(a) + "]";
        for (const engine::AnimationChannel& channel : animation.channels) {
            if (!inRange(channel.node, scene.nodes.size(), false) ||
                !inRange(channel.sampler, animation.samplers.size(), false))
                finding(name + ": channel node or sampler out of range");
            const engine::AnimationSampler& sampler = animation.samplers[channel.sampler];
            const std::size_t perKey = sampler.interpolation == engine::Interpolation::CubicSpline ? 3 : 1;
            if (sampler.times.empty() || sampler.components == 0 ||
                sampler.values.size() != sampler.times.size() * perKey * sampler.components)
                finding(name + ": a used sampler's keys and values disagree");
            if (!std::is_sorted(sampler.times.begin(), sampler.times.end(), std::less_equal<float>()))
                finding(name + ": key times not strictly increasing");
        }
        for (const double at : {double(animation.startTime), 0.5 * (animation.startTime + animation.endTime),
                                double(animation.endTime)}) {
            engine::poseAnimation(scene, animation, at);
            for (const engine::Node& node : scene.nodes)
                for (int c = 0; c < 16; ++c)
                    if (!std::isfinite(node.local[c / 4][c % 4])) finding(name + ": pose not finite");
            // Skinned and morphed instances are posed here (Deform.h), under the sanitizers.
            scene.updateWorldTransforms();
            for (const engine::MeshInstance& instance : scene.meshInstances)
                if (instance.deformed)
                    for (const engine::DeformedPrimitive& primitive : instance.deformed->primitives) {
                        for (const glm::vec3& p : primitive.positions)
                            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                                finding(name + ": deformed vertex not finite");
                        for (const glm::vec4& t : primitive.tangents)
                            if (!isUnitTangent(t)) finding(name + ": deformed tangent not unit length with w = +1 or -1");
                    }
        }
    }
}

void loadOne(const fs::path& path) {
    try {
        std::vector<std::string> warnings;
        const engine::Scene scene = engine::loadGltf(path, &warnings);
        checkSceneContract(scene);
        checkAnimationContract(scene);
        if (gVerbose)
            std::fprintf(stderr, "%s: loaded: %zu nodes, %zu meshes, %zu images, %zu lights, %zu warnings\n",
                         path.filename().c_str(), scene.nodes.size(), scene.meshes.size(), scene.images.size(),
                         scene.lights.size(), warnings.size());
    } catch (const engine::InputError& error) {
        // The expected outcome for bad input.
        if (gVerbose) std::fprintf(stderr, "%s: InputError: %s\n", path.filename().c_str(), error.what());
    } catch (const std::exception& exception) {
        finding(std::string("exception other than engine::InputError: ") + typeid(exception).name() + ": " +
                exception.what());
    } catch (...) {
        finding("exception of a type not derived from std::exception");
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const char* verbose = std::getenv("GLTF_FUZZ_VERBOSE");
    gVerbose = verbose && *verbose && *verbose != '0';
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/gltf-fuzz-XXXXXX";
    if (!::mkdtemp(pattern.data())) finding("harness: mkdtemp failed for " + pattern);
    gFolder = fs::canonical(pattern);
    populateFolder();
    std::atexit(removeFolder);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    for (const char* name : {"scene.gltf", "scene.glb"}) {
        const fs::path path = gFolder / name;
        writeFile(path, data, size);
        loadOne(path);
    }
    return 0;
}
