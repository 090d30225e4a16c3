#pragma once
// How the lit pass reads a light's map: one axis of a shadow technique (Techniques.h).
// Today both lookups are the hardware depth comparison, nearest or bilinear (GL_LINEAR on
// a comparing texture is 2x2 percentage-closer filtering); each in lookup/, its GLSL in
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
    // What, beyond the map, decides the shade this lookup gives a pixel.
    virtual void addShadeKey(engine::Hasher& key) const { key.add(filter()); }
    // Its GLSL: source defining <glslName>2D, <glslName>Array and <glslName>Cube, the fetch
    // and comparison for a 2D map, one cascade's layer and a cube map, each given the
    // comparing sampler, the coordinates and the biased, clamped reference depth. The hook
    // writes the map shapes' functions once per name in use (shaders/visibility.glsl), so
    // lookups that differ only in sampler state share one name and one program.
    virtual const char* glslName() const = 0;
    virtual const char* glsl() const = 0;
};

} // namespace shadowmap
