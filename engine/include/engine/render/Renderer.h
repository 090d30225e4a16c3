#pragma once
// Renders frames of one scene: builds each frame's render graph (plugin passes, the lit
// pass, optional shadow-mask passes), compiles it, executes it and reports per pass.
// Needs a current GL 4.5 context for its whole life.
#include "engine/config/EngineConfig.h"
#include "engine/gl/Texture.h"
#include "engine/plugin/RenderPlugin.h"
#include "engine/render/Frame.h"
#include "engine/render/GlPassTargets.h"
#include "engine/render/GlTexturePool.h"
#include "engine/render/LitPass.h"
#include "engine/render/SceneGpu.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <memory>
#include <vector>

namespace engine {

struct FrameRequest {
    FrameCamera camera;
    std::vector<int> shadowMaskSlots;  // lights (slots) whose shade is also rendered
    std::vector<int> comparisonSlots;  // lights whose comparison view is also rendered
    bool timing = false;               // close every pass with glFinish and time it
    // Lights (slots) whose shadow map is read back after the frame (FrameResult::shadowMaps),
    // found through the shadow views the plugin published. A light without a map this frame
    // is skipped.
    std::vector<int> shadowMapSlots;
};

struct DepthReadback {
    int width = 0, height = 0, layers = 1;  // layers: kCubeFaces for a cube (GL face order)
    bool cube = false;                      // the layers are a cube map's faces
    std::vector<float> depth;               // layer after layer, each top row first
};

struct StencilCountReadback {
    int width = 0, height = 0;
    std::vector<std::uint8_t> counts;
};

// Where the shaded image took each light's shade from (ShadeCache.h), by light slot.
struct ShadeCacheReport {
    int layers = 0;                 // of the cache's array (0: nothing cacheable)
    std::vector<int> fetched;       // reused from the cache
    std::vector<int> computed;      // recomputed and cached
    std::vector<int> moving;        // recomputed, not stored: changed two frames running
    std::vector<int> uncached;      // looked up, no cache
    std::vector<int> constant;      // one shade everywhere (no map): no lookup
    // Whether some light's shade was recomputed this frame (computed or moving).
    bool recomputed() const { return !computed.empty() || !moving.empty(); }
    // {"layers", "fetched", "computed", "moving", "uncached", "constant"}, for --stats.
    nlohmann::json toJson() const;
};

struct FrameResult {
    std::vector<PassReport> passes;
    // Wall time of the whole frame: graph build to glFinish when timing, else to the last
    // command's submission (the GPU may still be working).
    double frameMs = 0.0;
    nlohmann::json pluginStats = nlohmann::json::object();
    std::string graphviz;
    bool shadowTermProvided = false;  // a plugin installed the lit pass's visibility hook
    int litInstancesCulled = 0;       // mesh instances outside the camera frustum (not drawn)
    ShadeCacheReport shadeCache;  // the shaded image's
    // The lights (slots) whose shadow the shaded image looked up only inside their screen
    // footprint, and the regions that split the lit pass into (1: not split).
    std::vector<int> footprintLimitedLights;
    int shadingRegions = 1;
    // Whether the clustered lit pass shaded the image (Frame::clusteredLights), and then its
    // tile lists' entries over all tiles and its longest list (LightTiles.h).
    bool clusteredLights = false;
    std::int64_t tileListEntries = 0;
    int longestTileList = 0;
    // And each tile's list length, row by row from the bottom (window coordinates), in
    // tileColumns x tileRows tiles of kLightTileSize pixels.
    std::vector<std::uint32_t> tileLightCounts;
    int tileColumns = 0, tileRows = 0;
    // GL programs linked while rendering this frame (the lit pass's and the plugins'):
    // after warm-up, each is a frame that waited for the shader compiler.
    int programsLinked = 0;
    std::map<int, DepthReadback> shadowMaps;  // by light slot (FrameRequest::shadowMapSlots)
    // The same lights' ShadowView::stencilCount where they have one instead of a map (shadow
    // volumes): width × height counts, top row first.
    std::map<int, StencilCountReadback> stencilCounts;
    // Every light instance's shadow as the shadow plugin published it (ShadowView.h), by slot.
    std::vector<ShadowView> shadowViews;
    const ShadowView* shadowView(int slot) const;
    // The wall time of the passes `view` names that ran this frame; `ran` says whether any did
    // (none: the map was cached, or the light has none).
    double shadowPassMs(const ShadowView& view, bool& ran) const;
    // What `view`'s passes drew and left out as outside their views this frame (a culled
    // pass draws nothing).
    struct PassWork {
        std::uint64_t draws = 0, triangles = 0, drawsCulled = 0;
    };
    PassWork shadowPassWork(const ShadowView& view) const;
};

// The most samples per pixel renderer.msaa may ask of the current GL context (the lit
// pass's colour and depth formats both offer that many); a Renderer made with more throws
// InputError naming renderer.msaa, the request and this maximum.
int maxMsaaSamples();

class Renderer {
public:
    Renderer(const RendererConfig& config, std::vector<RenderPlugin*> plugins);
    ~Renderer();

    // The scene must outlive the renderer (or the next setScene). Calls every plugin's
    // prepareScene, which throws InputError for bad per-light settings.
    void setScene(const Scene& scene);
    // The scene's settings changed (e.g. a light's extras.shadow edited in a viewer), not its
    // geometry: plugins re-read them without a GPU upload. Throws like setScene.
    void reloadSettings();

    FrameResult renderFrame(const FrameRequest& request);

    // The llvmpipe switches as this renderer runs them: the config's, with each one it left
    // unset decided for the GL renderer current at construction (decideSwitches).
    const RendererSwitches& switches() const { return switches_; }

    // Renders `request` untimed until a frame compiles no lit program it has not compiled
    // before (at least `minFrames`, at most `maxFrames` frames); returns the frames rendered.
    // Timed frames after it pay for no compilation: the first frame compiles (and llvmpipe
    // JIT-compiles at first draw) the lit pass's programs for the scene's materials and
    // lights, the shadow plugins' depth programs and the requested masks' and comparisons'
    // views; the second, once the shade cache holds still lights' shade, the programs that
    // fetch it instead of computing it; a cached shadow map is cached from then on. Ends with
    // glFinish, so no timed frame waits for warm-up work still queued.
    // `motion`: what will move after it (ExpectedMotion, LitPass.h): the programs the first
    // moving frames draw with are compiled, and drawn once, too.
    int warmUp(const FrameRequest& request, int minFrames, int maxFrames, const ExpectedMotion& motion = {});

    // The scene's GPU copy (for tools that draw it their own way, e.g. a surface capture).
    const SceneGpu& gpu() const { return *gpu_; }

    // The last frame's image as 8-bit RGBA (sRGB encoded), top row first.
    std::vector<std::uint8_t> readColor() const;
    // The last frame's shade of light `slot` as 8-bit gray (255 = lit), top row first.
    std::vector<std::uint8_t> readShadowMask(int slot) const;
    // The last frame's comparison view of light `slot` as RGBA8, top row first.
    std::vector<std::uint8_t> readComparison(int slot) const;

private:
    // The RGBA8 target of a per-light view, (re)created at the frame's size.
    const gl::Texture& lightViewTarget(LitPass::LightView view, int slot, int width, int height);

    RendererConfig config_;
    RendererSwitches switches_;
    std::vector<RenderPlugin*> plugins_;
    const Scene* scene_ = nullptr;
    std::unique_ptr<SceneGpu> gpu_;
    std::unique_ptr<LitPass> litPass_;
    GlTexturePool pool_;
    GlPassTargets targets_;
    gl::Texture color_;
    std::map<std::pair<LitPass::LightView, int>, gl::Texture> lightViews_;  // (view, slot)
    std::uint64_t frameIndex_ = 0;
};

} // namespace engine
