#include "technique/LookupParams.h"

#include <algorithm>

namespace shadowmap {

glm::vec4 lookupParams(const ShadowSettings& settings) {
    // The moments lookups' blur is done before they read (the moments passes).
    if (readsMoments(settings.filter))
        return glm::vec4(static_cast<float>(settings.bleedReduction), settings.evsmExponents,
                         static_cast<float>(settings.normalOffset));
    // pcss's blocker search needs fewer taps than its filter: it averages depths, not shades.
    const int searchTaps = std::max(kMinFilterTaps, settings.filterTaps / 2);
    return glm::vec4(static_cast<float>(settings.filterRadius), static_cast<float>(searchTaps),
                     static_cast<float>(settings.filterTaps), static_cast<float>(settings.normalOffset));
}

} // namespace shadowmap
