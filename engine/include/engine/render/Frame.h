#pragma once
// One frame as plugins see it: the scene, its GPU copy, the camera, and the render graph
// the frame is being built into. Plugins add passes and may install the lit pass's
// per-light visibility hook (the shadow plugin's contribution to shading).
#include "engine/graph/RenderGraph.h"
#include "engine/render/ShadowView.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace engine {

struct Scene;
class SceneGpu;
namespace gl { class Program; }

// The lit pass handles the first kMaxLights entries of Scene::lightInstances; a light's
// "slot" is its index there. A loaded scene with more says so (lightsPastTheLimit). Why 32:
// the lit pass's light block is 64 bytes per light and the shadow plugin's about 112, so
// both stay far inside the 16 KiB every GL 4.5 implementation gives a uniform block, with
// room for per-light plugin data (cascades); and a light a visibility hook shadows needs a
// texture unit, of which llvmpipe has 32 (GL 4.5 guarantees 16), so more slots than units
// would buy only unshadowed lights.
constexpr int kMaxLights = 32;
// A scene with more lights than kMaxLights (or a renderer told to: RendererConfig::
// clusteredLights) is shaded by the clustered lit pass instead (LightTiles.h): every light in
// a texture, the target cut into tiles of kLightTileSize pixels, each listing the lights
// whose screen footprint touches it, and one loop per pixel over its tile's list; a visibility
// hook then shades lights by a slot that is not a constant (Frame::clusteredLights). Why 4096:
// the CPU builds the tile lists each frame, lights x covered tiles, and 4096 lights with
// footprints of a few tiles stay under a millisecond of it; the shadow plugin's atlas holds
// 4096 of its smallest maps (ShadowAtlas.h); and the light texture's height (a row per
// light) stays within the 16384 texels GL 4.5 guarantees.
constexpr int kMaxClusteredLights = 4096;
constexpr int kLightTileSize = 16;
// Whether a renderer whose RendererConfig::clusteredLights is `configured` shades a scene of
// `lightCount` light instances with the clustered lit pass (unset: only past kMaxLights),
// and how many of them it renders (the first ones; a loaded scene names the rest).
inline bool usesClusteredLights(std::optional<bool> configured, std::size_t lightCount) {
    return configured.value_or(lightCount > static_cast<std::size_t>(kMaxLights));
}
inline int renderedLightCount(std::optional<bool> configured, std::size_t lightCount) {
    const int limit = usesClusteredLights(configured, lightCount) ? kMaxClusteredLights : kMaxLights;
    return static_cast<int>(std::min<std::size_t>(lightCount, static_cast<std::size_t>(limit)));
}
// Texture units 0..kFirstPluginTextureUnit-1 belong to the engine: the five material
// textures (MaterialTextures.h) and the shade cache (ShadeCache.h).
constexpr int kFirstPluginTextureUnit = 6;
// The clustered lit pass's textures (lit.frag reads them on these units): the lights, the
// tiles' ranges and their lists. They are textures, not storage buffers, because llvmpipe
// fetches a texel per lane far faster than it loads a storage buffer at a per-lane address
// (measured on a 32-lamp street, 1280x720: the loop's bound alone read from a storage buffer
// cost 17 ms of frame, from a texture none measurable). A clustered hook's textures start
// at kFirstClusteredPluginTextureUnit.
constexpr int kLightDataUnit = kFirstPluginTextureUnit;
constexpr int kTileRangesUnit = kFirstPluginTextureUnit + 1;
constexpr int kTileLightsUnit = kFirstPluginTextureUnit + 2;
constexpr int kFirstClusteredPluginTextureUnit = kFirstPluginTextureUnit + 3;
// The tile lists' texture is this wide (entries per row).
constexpr int kTileListsWidth = 4096;
// The lit pass's lights block (lit.frag reads it as LIGHTS_BLOCK_BINDING, defined from this);
// a visibility hook's blocks start after it.
constexpr unsigned kLightsUniformBinding = 0;
constexpr unsigned kFirstPluginUniformBinding = kLightsUniformBinding + 1;

struct FrameCamera {
    glm::dmat4 eyeToWorld{1.0};  // V (eye -> world); the view matrix is V^-1
    glm::dmat4 projection{1.0};  // P_eye
    int width = 0, height = 0;
    glm::dvec3 position() const { return glm::dvec3(eyeToWorld[3]); }
};

// The per-light visibility term of the lit pass (the ambient-retaining modulate, lit.frag).
// `glsl` is inserted into the lit fragment shader (GLSL 4.50 core, after the engine's own
// declarations) and must define
//     float lightVisibility(int lightSlot, vec3 eyePosition, vec3 eyeNormal);
// the shade in [0,1] of that light at that eye-space point, and
//     vec4 lightDebugColor(int lightSlot, vec3 eyePosition, vec3 eyeNormal);
// a picture of how it decided (engine-render --shadow-compare shows it).
// `vertexGlsl` (optional) is inserted into the lit vertex shader and must then define
//     void lightTexgen(vec3 eyePosition);
// called once per vertex with its eye-space position, to set the hook's own outputs
// (e.g. shadow-map coordinates, which the fragment part declares as inputs).
// `dimming` (by light slot; missing = 0) is each light's dimming d in [0,1]: the lit pass
// uses diffuseShade = d + (1 - d) * shade for diffuse and shade for specular.
// `bind` runs before the lit pass draws (uniforms, blocks on bindings
// >= kFirstPluginUniformBinding, textures on units >= kFirstPluginTextureUnit), and `reads`
// are the graph resources it samples.
// `glslVersion` names the code: the lit pass keeps its programs by (owner, glslVersion) and
// never reads the sources of a version it has compiled, so a plugin must give a new version
// to different code (and may give an old one back when its code returns to what it was).
// Version 0 promises nothing: such a hook's programs are found by comparing its text.
//
// `shadeKeys` (by light slot; missing or 0 = "evaluate every frame") lets the lit pass
// reuse a light's shade from the previous frame, per pixel (ShadeCache.h): a plugin gives
// a light a key that changes whenever lightVisibility could return something else for the
// same eye-space point under the same camera (its map, its parameters). The engine adds
// the camera and the visible geometry to the key itself. A frame that takes every light's
// shade from the cache leaves the hook's code (both parts) and `bind` out of its program.
// `constantShades` (by light slot) names lights whose shade is the same at every point this
// frame (e.g. no map: 1, or 0 for a spot whose frustum holds nothing visible); the lit pass
// then uses that number instead of calling lightVisibility for them.
struct LightVisibilityHook {
    std::string owner;  // plugin name, for messages
    std::string glsl;
    std::string vertexGlsl;
    std::uint64_t glslVersion = 0;
    std::vector<ResourceHandle> reads;
    std::function<void(const gl::Program&, const PassContext&)> bind;
    std::vector<float> dimming;
    std::vector<std::uint64_t> shadeKeys;
    std::map<int, float> constantShades;
};

class Frame {
public:
    Frame(const Scene& scene, const SceneGpu& gpu, RenderGraph& graph, const FrameCamera& camera,
          std::uint64_t index, bool clusteredLights = false)
        : scene_(scene), gpu_(gpu), graph_(graph), camera_(camera), index_(index), clusteredLights_(clusteredLights) {}

    const Scene& scene() const { return scene_; }
    const SceneGpu& gpu() const { return gpu_; }
    RenderGraph& graph() { return graph_; }
    const FrameCamera& camera() const { return camera_; }
    std::uint64_t index() const { return index_; }
    // Whether this frame's lit pass is the clustered one (kMaxClusteredLights). Its hook's
    // lightVisibility and lightDebugColor are then called with slots that are not constants,
    // in a loop over a tile's lights (so the hook must index its data and textures
    // uniformly: one texture for every light), the hook's vertex part is not used, and
    // shadeKeys and constantShades are ignored (nothing is cached per pixel); its `bind`
    // must leave units below kFirstClusteredPluginTextureUnit to the engine.
    bool clusteredLights() const { return clusteredLights_; }

    // Only one plugin may shade lights; a second hook is a configuration error.
    void setLightVisibility(LightVisibilityHook hook);
    const std::optional<LightVisibilityHook>& lightVisibility() const { return visibility_; }

    // A shadow plugin publishes one view per light instance (ShadowView.h); the frame's
    // result hands them to the tools.
    void publishShadowView(ShadowView view) { shadowViews_.push_back(std::move(view)); }
    const std::vector<ShadowView>& shadowViews() const { return shadowViews_; }

    // The lights (slots) whose map the caller reads back after the frame (FrameRequest::
    // shadowMapSlots): a plugin may make, for those only, what it shows in a map's place.
    void setMapReadbackSlots(std::vector<int> slots) { mapReadbackSlots_ = std::move(slots); }
    bool mapReadbackRequested(int slot) const {
        return std::find(mapReadbackSlots_.begin(), mapReadbackSlots_.end(), slot) != mapReadbackSlots_.end();
    }

private:
    const Scene& scene_;
    const SceneGpu& gpu_;
    RenderGraph& graph_;
    FrameCamera camera_;
    std::uint64_t index_;
    bool clusteredLights_ = false;
    std::optional<LightVisibilityHook> visibility_;
    std::vector<ShadowView> shadowViews_;
    std::vector<int> mapReadbackSlots_;
};

} // namespace engine
