#pragma once
// The engine config (JSON, default content/engine.json):
// {
//   "plugin_dirs": ["relative/or/absolute/dir", ...],     optional; relative to the config
//   "plugins": [ {"library": "shadowmap_plugin", "settings": {...}} ],
//   "renderer": {"ambient": [r,g,b], "clear_color": [r,g,b],          optional
//                "msaa": 1, "shade_cache": "auto", "light_footprints": "auto",
//                "unrolled_light_sum": "auto", "check_gl_errors": false}
// }
// Unknown keys are errors (a typo must not silently change nothing). Where plugins are
// searched: PluginHost::searchDirectories (plugin_dirs first).
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace engine {

struct PluginConfig {
    std::string library;  // a bare name: "shadowmap_plugin" -> shadowmap_plugin.so
    nlohmann::json settings = nlohmann::json::object();
};

// The exposure for a camera at EV100 (the photographic convention of RendererConfig::exposure
// below): 1 / (1.2 * 2^ev100).
inline float exposureFromEv100(double ev100) { return static_cast<float>(1.0 / (1.2 * std::exp2(ev100))); }

// The sample counts renderer.msaa accepts: 1 (no multisampling) and the powers of two GPUs
// offer, up to 8 (GL 4.5 guarantees at least 4; the renderer checks what its GL offers).
inline constexpr std::array<int, 4> kMsaaSampleCounts{1, 2, 4, 8};
bool isMsaaSampleCount(int samples);
// "1, 2, 4 or 8", for messages.
std::string msaaSampleCountsText();

struct RendererConfig {
    glm::vec3 ambient{0.04f};      // linear ambient light, multiplied by albedo
    glm::vec3 clearColor{0.0f};    // linear background
    // The shaded radiance is multiplied by `exposure`, then tone mapped, then sRGB-encoded.
    // The defaults (1, none) suit lights given in display units (an irradiance of about 1
    // lights a white surface fully). For physical units (KHR_lights_punctual: lux, candela)
    // take exposure = 1 / (1.2 * 2^EV100), the photographic convention: a sunlit scene
    // (EV100 15) 2.5e-5, an office (EV100 8) 3.3e-3.
    float exposure = 1.0f;
    enum class ToneMapping {
        None,        // clamp at 1
        PbrNeutral,  // Khronos PBR Neutral: keeps base colors up to 0.8 as they are, then rolls off
    };
    ToneMapping toneMapping = ToneMapping::None;
    // Samples per pixel of the shaded image (kMsaaSampleCounts). Above 1 the lit pass draws
    // into multisampled colour and depth targets, shading once per pixel and fragment
    // (not per sample), tone mapping each fragment as it shades it, and resolves them into the
    // single-sampled image: geometry edges are antialiased, the shade inside a surface is as
    // at 1. Per-pixel outputs (shadow masks, comparison views, the truth's surface capture)
    // stay single-sampled. Multisampling turns the shade cache off: its layers are extra
    // single-sampled outputs of the lit pass, which a multisampled pass cannot have.
    int msaa = 1;
    // The three switches made for llvmpipe (docs/gpu.md). Unset ("auto" in the config file),
    // each is decided for the GL renderer by decideSwitches: on for a software rasterizer, off
    // on a GPU.
    //
    // Reuse a light's per-pixel shade while camera, geometry and light are unchanged
    // (ShadeCache.h); off: every frame asks the visibility hook for every pixel.
    std::optional<bool> shadeCache;
    // Look a spot or ranged point light's shadow up only on the part of the screen its light
    // can reach (LitPass.cpp, ShadingRegions.h); off: on every pixel. Images are the same
    // either way (its term is zero outside), only the time differs.
    std::optional<bool> lightFootprints;
    // The lit shader sums the lights term by term, each with literal slot and light type;
    // off: one loop over the lights with their types in a constant array. Unrolled is what
    // llvmpipe runs fastest (lit.frag's header has the numbers).
    std::optional<bool> unrolledLightSum;
    // Shade with the clustered lit pass (Frame.h, kMaxClusteredLights): every light in one loop
    // over the lights of the pixel's screen tile, shadows from one atlas. Unset ("auto"): for
    // scenes with more lights than the unrolled pass takes (kMaxLights) only; true: always
    // (to measure it against the unrolled pass); false: never (lights past kMaxLights are
    // left out, with a warning).
    std::optional<bool> clusteredLights;
    // glGetError after every pass, and a GlError naming the pass whose commands raised the
    // flag. GL reports errors late and anonymously, so without it a bad call shows up, if
    // ever, far from its cause. On by default in builds without NDEBUG (Debug); it costs a
    // round trip to the driver per pass, which release builds do not pay.
#ifdef NDEBUG
    bool checkGlErrors = false;
#else
    bool checkGlErrors = true;
#endif
};

// The llvmpipe switches as a renderer runs them.
struct RendererSwitches {
    bool shadeCache = true;
    bool lightFootprints = true;
    bool unrolledLightSum = true;
};

// A software rasterizer, by its GL_RENDERER string: Mesa's llvmpipe, softpipe or swrast.
bool isSoftwareRasterizer(std::string_view glRenderer);

// The config's switches, each unset one decided for the renderer named by glRenderer
// (GL_RENDERER): on for a software rasterizer, where each was measured to pay; off on a GPU,
// where on an NVIDIA H200 (docs/gpu.md) they saved no median frame time and their program
// variants compiled after warm-up, in frames of 50 to 660 ms. The shade cache is off with
// msaa above 1 (RendererConfig::msaa).
RendererSwitches decideSwitches(const RendererConfig& config, std::string_view glRenderer);

struct EngineConfig {
    std::filesystem::path sourcePath;  // for messages
    std::vector<std::filesystem::path> pluginDirs;
    std::vector<PluginConfig> plugins;
    RendererConfig renderer;
};

// Throws InputError("config.json: plugins[0].library: ...") on bad input.
EngineConfig loadEngineConfig(const std::filesystem::path& path);
EngineConfig parseEngineConfig(const std::string& jsonText, const std::filesystem::path& path);

// The config a program uses when the user names none, first that exists:
//   1. content/engine.json under the current folder (a source checkout);
//   2. the source tree's content/engine.json, while libengine runs from its build tree
//      (InstallLayout.h: a tool of the build tree, started from any folder);
//   3. <datadir>/shadow-engine/engine.json of the install the running libengine belongs to.
// Throws InputError listing every path tried when none exists.
std::vector<std::filesystem::path> defaultEngineConfigCandidates();
std::filesystem::path findDefaultEngineConfig();
// The first of `candidates` that is a file, else the InputError above.
std::filesystem::path firstExistingEngineConfig(const std::vector<std::filesystem::path>& candidates);

} // namespace engine
