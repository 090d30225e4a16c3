#pragma once
// The lit pass's programs: one per visibility hook (by owner and version), light defines,
// output view, shade-cache plan and material variant, compiled on first use and kept, keyed
// without comparing shader text.
#include "engine/config/EngineConfig.h"
#include "engine/gl/Program.h"
#include "engine/render/Frame.h"
#include "engine/render/MaterialShading.h"

#include <compare>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace engine {

// lit.frag's views: the shaded image, one light's shade as gray, or the hook's debug picture.
enum class LitOutput { Color, ShadowMask, Comparison };

class LitPrograms {
public:
    explicit LitPrograms(const RendererConfig& config) : config_(config) {}

    // hook null: every light fully visible (no plugin, or none of its code needed).
    const gl::Program& programFor(const LightVisibilityHook* hook, const std::string& lightDefinesGlsl, LitOutput output,
                                  const std::string& loadShadesGlsl, unsigned variant);
    // The program programFor would return if it is compiled already; null if not.
    const gl::Program* compiled(const LightVisibilityHook* hook, const std::string& lightDefinesGlsl, LitOutput output,
                                const std::string& loadShadesGlsl, unsigned variant) const;

private:
    // What a lit program is compiled from, without its text: the hook by owner and version
    // (Frame.h), the light and shade-cache defines (a few lines), output and variant.
    struct ProgramKey {
        std::string hookIdentity;  // its owner; empty: no hook (or none of its code needed)
        std::uint64_t hookVersion = 0;
        std::string lightDefines, loadShades;
        LitOutput output = LitOutput::Color;
        unsigned variant = 0;
        auto operator<=>(const ProgramKey&) const = default;
    };

    static ProgramKey keyFor(const LightVisibilityHook* hook, const std::string& lightDefinesGlsl, LitOutput output,
                             const std::string& loadShadesGlsl, unsigned variant);

    RendererConfig config_;
    std::map<ProgramKey, std::unique_ptr<gl::Program>> programs_;
};

// The material variants (MaterialShading.h) the scene's primitives use (at least the plain
// one, for an empty scene).
std::vector<unsigned> variantsInUse(const Scene& scene, const SceneGpu& gpu);

} // namespace engine
