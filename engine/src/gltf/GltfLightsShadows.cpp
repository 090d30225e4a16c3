#include "GltfLightsShadows.h"

namespace engine::gltf {

ShadowFlags readLightsShadows(const JsonFields& owner, ShadowFlagsOwner kind) {
    ShadowFlags flags;
    const std::optional<JsonFields> extension = owner.extension("KHR_lights_shadows");
    if (!extension) return flags;
    flags.castShadows = extension->boolean("castShadows", flags.castShadows);
    if (kind == ShadowFlagsOwner::Primitive) {
        extension->warnAboutUnknownKeys({"castShadows", "receiveShadows", "extensions", "extras"});
        flags.receiveShadows = extension->boolean("receiveShadows", flags.receiveShadows);
    } else {
        // A light lights what it lights: receiving is the surface's business.
        extension->warnAboutUnknownKeys({"castShadows", "extensions", "extras"});
    }
    return flags;
}

} // namespace engine::gltf
