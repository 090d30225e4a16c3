#include "technique/Techniques.h"

#include "technique/depth/BackfaceDepth.h"
#include "technique/depth/StandardDepth.h"
#include "technique/depth/WooDepth.h"
#include "technique/lookup/HardwareCompareLookup.h"
#include "technique/lookup/MomentsLookup.h"
#include "technique/lookup/PcssLookup.h"
#include "technique/lookup/WidePcfLookup.h"
#include "technique/projection/CascadedMapProjection.h"
#include "technique/projection/CubeMapProjection.h"
#include "technique/projection/FittedMapProjection.h"

#include "math/CascadeFit.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace shadowmap {

namespace {

const StandardDepth kStandard;
const WooDepth kWoo;
const BackfaceDepth kBackface;
const DepthTechnique* const kDepthTechniques[] = {&kStandard, &kWoo, &kBackface};

const FittedMapProjection kFittedMap;
const CubeMapProjection kCubeMap;
const CascadedMapProjection kCascadedMap;
const MapProjection* const kProjections[] = {&kFittedMap, &kCubeMap, &kCascadedMap};

const HardwareCompareLookup kNearest(Filter::Nearest, false);
const HardwareCompareLookup kPcf(Filter::Pcf, true);
const PcssLookup kPcss;
const WidePcfLookup kWidePcf;
const MomentsLookup kVsm(Filter::Vsm, 2, "vsm");
const MomentsLookup kEvsm(Filter::Evsm, 4, "evsm");
// A filter's first entry is its lookup; wide pcf is pcf's with a filter radius.
const MapLookup* const kLookups[] = {&kNearest, &kPcf, &kPcss, &kWidePcf, &kVsm, &kEvsm};

// The entry whose key matches, or nullptr.
template <typename Entry, std::size_t N, typename Key, typename KeyOf>
const Entry* find(const Entry* const (&table)[N], Key key, KeyOf keyOf) {
    for (const Entry* entry : table)
        if (keyOf(*entry) == key) return entry;
    return nullptr;
}

} // namespace

const DepthTechnique* depthTechnique(Variant variant) {
    return find(kDepthTechniques, variant, [](const DepthTechnique& t) { return t.variant(); });
}

std::vector<const DepthProgram*> depthPrograms() {
    std::vector<const DepthProgram*> programs;
    for (const DepthTechnique* technique : kDepthTechniques)
        for (const DepthProgram* program : technique->programs())
            if (std::find(programs.begin(), programs.end(), program) == programs.end()) programs.push_back(program);
    return programs;
}

const MapProjection* mapProjection(MapKind kind) {
    return find(kProjections, kind, [](const MapProjection& p) { return p.kind(); });
}

const MapProjection& projectionFor(engine::Light::Type type, int cascadeCount, double shadowDistance) {
    if (type == engine::Light::Type::Point) return kCubeMap;
    if (type == engine::Light::Type::Directional && directionalMapIsSliced(cascadeCount, shadowDistance))
        return kCascadedMap;
    return kFittedMap;
}

const MapLookup& mapLookup(Filter filter) {
    const MapLookup* lookup = find(kLookups, filter, [](const MapLookup& l) { return l.filter(); });
    // Every filter the settings accept has a lookup (TechniquesTest checks each).
    if (!lookup) throw std::logic_error("no lookup for filter " + std::string(toString(filter)));
    return *lookup;
}

const MapLookup& mapLookupFor(const ShadowSettings& settings) {
    if (settings.filter == Filter::Pcf && settings.filterRadius > 0.0) return kWidePcf;
    return mapLookup(settings.filter);
}

const MapLookup& mapLookupNamed(const std::string& glslName) {
    const MapLookup* lookup = find(kLookups, glslName, [](const MapLookup& l) { return std::string(l.glslName()); });
    if (!lookup) throw std::logic_error("no lookup with GLSL name " + glslName);
    return *lookup;
}

} // namespace shadowmap
