#pragma once
// How the lit pass reads a light's map: one axis of a shadow technique (Techniques.h).
// The hardware depth comparison, nearest or bilinear (GL_LINEAR on a comparing texture is
// 2x2 percentage-closer filtering), percentage-closer soft shadows, which read raw depths,
// and variance maps, which read moments made from them; each in lookup/, its GLSL in
// shaders/lookup/.
#include "shadowmap/ShadowSettings.h"

#include "engine/util/Hasher.h"

namespace shadowmap {

class MapLookup {
public:
    virtual ~MapLookup() = default;
    virtual Filter filter() const = 0;
    // The comparing texture's min/mag filter: bilinear (true) or nearest.
    virtual bool bilinearCompare() const = 0;
    // false: the lookup reads the map's depths and compares them itself, through a plain
    // sampler (sampler2D, sampler2DArray, samplerCube) with comparison off.
    virtual bool comparesInHardware() const { return true; }
    // > 0: the lookup reads a filterable map of this many moments per texel, made from the
    // depth map by the plugin's moments passes (lookup/MomentsLookup.h), not the depth map.
    virtual int momentChannels() const { return 0; }
    // What, beyond the map, decides the shade this lookup gives a pixel.
    virtual void addShadeKey(engine::Hasher& key) const { key.add(filter()); }
    // Its GLSL: source defining <glslName>2D, <glslName>Array and <glslName>Cube, the fetch
    // and comparison for a 2D map, one cascade's layer and a cube map, each given the light's
    // slot, the sampler, the coordinates (and the layer) and the biased, clamped reference
    // depth. The hook
    // writes the map shapes' functions once per name in use (shaders/visibility.glsl), so
    // lookups that differ only in sampler state share one name and one program.
    virtual const char* glslName() const = 0;
    // How many texels from the looked-up point the lookup may read with these settings (the
    // receiver-aware caster culling widens each receiver by it: UnseenShadows.h).
    virtual double reachTexels(const ShadowSettings&) const { return 1.0; }
    virtual const char* glsl() const = 0;
};

} // namespace shadowmap
