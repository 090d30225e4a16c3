#pragma once
// The lit pass's screen-space shade cache.
// Looking a shadow up per pixel (texgen, comparison, filtering) costs llvmpipe ~20 ms per
// light at 1280x720, several unshadowed frames, even when the map itself is cached. While
// the camera, the visible geometry and a light's visibility inputs (the hook's shade key,
// Frame.h) stay the same, that light's shade at every pixel is what an earlier frame
// computed, so the lit pass reads it back instead: one texelFetch per four lights.
//
// Storage: an RGBA32F 2D array, four lights per layer (at most 7 layers: the first 28
// cacheable lights; the others are evaluated every frame), exact floats (a frame that reads the
// cache shades exactly like the frame that filled it). When some light's shade is stale,
// the lit pass computes it and writes every layer of a second array through extra color
// outputs (stale lights computed, fresh ones copied from the first array); then the two
// swap, so no array is ever read and written by one pass. The value written at a pixel is
// the one of the fragment that wins the depth test (the one whose color lands in the
// image), so overdraw cannot leave a hidden surface's shade behind; and since the key
// covers camera and geometry, the next frame covers exactly the same pixels.
//
// A light whose key changed in this frame and in the one before is moving: it would be
// stale again next frame, so it is evaluated without being stored, and a frame in which
// only moving lights changed writes no array at all (an orbiting light or camera then
// costs its lookups but not the cache writes: measured 1.10 -> 1.06 x (unshadowed + one
// depth pass) for 2CylinderEngine with its light orbiting). A single change is still
// stored at once, and a light that stops is stored on its first still frame.
#include "engine/render/MaterialTextures.h"
#include "engine/gl/Texture.h"
#include "engine/render/Frame.h"

#include <cstdint>
#include <string>
#include <vector>

namespace engine {

class ShadeCache {
public:
    // Where the lit pass takes a light's shade from this frame.
    enum class Source {
        Inline,   // the hook gave no key: evaluated, not cached
        Constant, // the hook says it is one number everywhere: that number
        Fetch,    // still valid: read from the cache
        Compute,  // stale or new: evaluated and written to the cache
        Moving,   // changed last frame too: evaluated, not stored (see above)
    };
    struct Plan {
        std::vector<Source> sources;  // by light slot
        std::vector<int> channels;    // by slot: layer * 4 + component, or -1 (not cached)
        std::vector<float> constants; // by slot: the shade of a Constant light
        int layers = 0;               // 0: nothing cached, the lit pass runs without the cache
        unsigned readArray = 0;       // the array fetched from (0 if nothing is fetched)
        unsigned writeArray = 0;      // the array written (0 if nothing is computed)
        std::vector<std::uint64_t> writtenKeys;  // by channel, once writeArray is drawn

        int count(Source source) const;
        // Some light's shade comes from the visibility hook this frame (not all fetched).
        bool evaluatesHook() const {
            return count(Source::Inline) + count(Source::Compute) + count(Source::Moving) > 0;
        }
        // GLSL appended to the lit fragment shader (see lit.frag): loadShades(), which
        // fills every light's shade from its source, and the cache's sampler and outputs
        // when it has layers. Empty without lights.
        std::string glsl() const;
    };

    // lightCount: the lit pass's lights; the hook's shade keys and constant shades;
    // viewKey: what the engine adds (camera, target size, visible geometry).
    Plan plan(std::uint64_t viewKey, const LightVisibilityHook& hook, int lightCount, int width, int height);
    // Every light evaluated, nothing cached (the cache is off, or the hook gives no keys).
    static Plan uncached(int lightCount);
    // The lit pass has drawn `plan`: its written array is now the valid one.
    void commit(const Plan& plan);
    // Forget everything (a new scene).
    void clear();
    // The array the valid shades are in (0 before the first plan that caches).
    unsigned currentArray() const { return arrays_[current_].id(); }

    // Texture unit of the cache's sampler: the engine's own unit after the material
    // textures' (below kFirstPluginTextureUnit).
    static constexpr int kTextureUnit = static_cast<int>(kMaterialTextureCount);

private:
    void ensureArrays(int width, int height, int layers);

    gl::Texture arrays_[2];
    int current_ = 0;                          // the array channelKeys_ describes
    std::vector<std::uint64_t> channelKeys_;   // per channel of arrays_[current_]; 0 = invalid
    // By light slot, for telling moving lights: the key of the last planned frame (0 = none)
    // and whether it differed from the one before.
    std::vector<std::uint64_t> previousKeys_;
    std::vector<bool> changedLastFrame_;
};

} // namespace engine
