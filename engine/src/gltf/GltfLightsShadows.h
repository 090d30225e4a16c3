#pragma once
// KHR_lights_shadows (draft, KhronosGroup/glTF PR #2220): "castShadows" on a
// KHR_lights_punctual light, "castShadows" and "receiveShadows" on a mesh primitive; both
// booleans, default true. Read from our own parse (see GltfJsonFields.h).
#include "GltfJsonFields.h"

namespace engine::gltf {

struct ShadowFlags {
    bool castShadows = true;
    bool receiveShadows = true;
};

// Which object carries the extension: a light has no "receiveShadows".
enum class ShadowFlagsOwner { Light, Primitive };

// The flags of `owner`'s extensions.KHR_lights_shadows (defaults when absent).
ShadowFlags readLightsShadows(const JsonFields& owner, ShadowFlagsOwner kind);

} // namespace engine::gltf
