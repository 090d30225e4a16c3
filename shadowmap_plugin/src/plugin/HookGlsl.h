#pragma once
// The GLSL of the shadow plugin's visibility hook (engine/render/Frame.h), generated from the
// shipped shaders plus, per shadowed light, one sampler, one interpolated coordinate set and
// a dispatch on the slot with constant arguments (visibility.glsl says why). The code depends
// only on which lights have which kind of map, so it is generated once per such layout and
// kept with a version number the lit pass keys its programs by; returning to an earlier
// layout (a light switched off and on again) gives back that layout's version.
#include <compare>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace shadowmap {

class HookGlsl {
public:
    struct Lookup {
        int slot = 0;           // the light's lit-pass slot
        int unit = 0;           // texture unit of its comparing sampler
        bool cube = false;      // a cube map (point light), else a 2D map
        int rawUnit = -1;       // unit of its raw-depth sampler for the comparison view; -1: none
        int cascades = 0;       // > 0: a 2D array map of that many cascades (directional)
        std::string glslName;   // its MapLookup's glslName(): which functions read the map
        // A visibility per camera pixel (variant volume) on `unit`, read at the fragment: no
        // map, no lookup functions, no coordinates.
        bool screen = false;
        auto operator<=>(const Lookup&) const = default;
    };
    struct Code {
        std::string fragment;  // LightVisibilityHook::glsl
        std::string vertex;    // LightVisibilityHook::vertexGlsl
        std::uint64_t version = 0;
    };

    // The code for these lookups (in slot order), generated on first use.
    const Code& codeFor(const std::vector<Lookup>& lookups);
    std::size_t layouts() const { return codes_.size(); }

private:
    std::map<std::vector<Lookup>, Code> codes_;
};

} // namespace shadowmap
