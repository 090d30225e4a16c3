#include "plugin/LightResolver.h"

#include "engine/render/Frame.h"
#include "engine/scene/SceneNames.h"
#include "engine/util/Error.h"

#include <set>

namespace shadowmap {

namespace {

// The materials of the primitives that cast a shadow through an alpha test.
std::vector<std::string> alphaTestedCasterMaterials(const engine::Scene& scene) {
    std::set<int> materials;
    for (const engine::MeshInstance& instance : scene.meshInstances) {
        if (!instance.castShadows || instance.mesh < 0) continue;
        for (const engine::Primitive& primitive : scene.meshes[instance.mesh].primitives)
            if (primitive.castShadows && primitive.material >= 0 &&
                engine::castsAlphaTested(scene.materials[primitive.material]))
                materials.insert(primitive.material);
    }
    std::vector<std::string> names;
    for (int material : materials) {
        const std::string& name = scene.materials[material].name;
        names.push_back(name.empty() ? "material " + std::to_string(material) : name);
    }
    return names;
}

// A shadow volume is made of triangles and cannot test a texture: a light whose casters
// include alpha-tested ones gets a standard map instead, so its cutouts shadow right (said once).
void fallBackFromVolumes(const engine::Scene& scene, LightShadow& shadow,
                         const std::function<void(const LightState&, const std::string&)>& warn) {
    const std::vector<std::string> masked = alphaTestedCasterMaterials(scene);
    if (masked.empty()) return;
    std::string named = "\"" + masked.front() + "\"";
    if (masked.size() > 1) named += " (and " + std::to_string(masked.size() - 1) + " more)";
    warn(shadow, "alpha-tested material " + named +
                     " cannot cast a shadow volume (a volume has no texture to test): this light uses a standard "
                     "map instead");
    shadow.settings.variant = Variant::Standard;
}

} // namespace

std::vector<LightShadow> resolveLights(const engine::Scene& scene, const ShadowSettings& defaults,
                                       const LightOptions& lightOptions, int maxTextureSize,
                                       const std::function<void(const LightState&, const std::string&)>& warn) {
    const std::string& source = scene.sourcePath;
    // Overrides name lights as engine-render resolved them (lightInstanceName).
    for (const auto& [name, options] : lightOptions) {
        bool found = false;
        for (std::size_t i = 0; i < scene.lightInstances.size() && !found; ++i)
            found = engine::lightInstanceName(scene, static_cast<int>(i)) == name;
        if (!found)
            engine::throwInputError(source, "light \"" + name + "\" (command line)",
                                    "no light of that name in the scene (" + engine::describeLightInstances(scene) + ")");
    }
    std::vector<LightShadow> lights;
    for (std::size_t slot = 0; slot < scene.lightInstances.size(); ++slot) {
        if (static_cast<int>(slot) == engine::kMaxClusteredLights) break;
        const engine::LightInstance& placed = scene.lightInstances[slot];
        const engine::Light& light = scene.lights[placed.light];
        LightShadow shadow;
        shadow.name = engine::lightInstanceName(scene, static_cast<int>(slot));
        shadow.slot = static_cast<int>(slot);
        shadow.type = light.type;
        shadow.settings = defaults;
        const std::string object = "light \"" + shadow.name + "\"";
        if (light.extras.is_object() && light.extras.contains("shadow")) {
            applySettings(shadow.settings, light.extras["shadow"], source, object + ": extras.shadow");
            checkSizeKeyForType(light.extras["shadow"], light.type, source, object + ": extras.shadow");
            checkProjectionKeyForType(light.extras["shadow"], light.type, source, object + ": extras.shadow");
        }
        // KHR_lights_shadows "castShadows": false: the file says this light casts no shadow,
        // and that wins over our extras (only the command line's variant overrides it).
        if (!light.castShadows) {
            if (shadow.settings.variant != Variant::None && light.extras.contains("shadow") &&
                light.extras["shadow"].contains("variant"))
                warn(shadow, std::string("KHR_lights_shadows castShadows is false: extras.shadow variant \"") +
                                 toString(shadow.settings.variant) + "\" is not used");
            shadow.settings.variant = Variant::None;
        }
        // The command line's per-light settings come last: they win over everything.
        const auto options = lightOptions.find(shadow.name);
        if (options != lightOptions.end()) {
            applySettings(shadow.settings, options->second, "", object);
            checkSizeKeyForType(options->second, light.type, "", object);
            checkProjectionKeyForType(options->second, light.type, "", object);
        }
        const std::string checked = options == lightOptions.end() ? object + ": extras.shadow" : object;
        checkLimits(shadow.settings, maxTextureSize, source, checked);
        if (shadow.settings.variant == Variant::Volume) fallBackFromVolumes(scene, shadow, warn);
        checkFilterForType(shadow.settings, light.type, source, checked);
        lights.push_back(std::move(shadow));
    }
    return lights;
}

std::vector<bool> closedCasterMeshes(const engine::Scene& scene) {
    std::vector<bool> closed(scene.meshes.size(), false);
    for (std::size_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
        bool closedMesh = scene.meshes[mesh].closed;
        for (const engine::Primitive& primitive : scene.meshes[mesh].primitives) {
            if (primitive.material < 0) continue;
            const engine::Material& material = scene.materials[primitive.material];
            closedMesh = closedMesh && !material.doubleSided && !engine::castsAlphaTested(material);
        }
        closed[mesh] = closedMesh;
    }
    return closed;
}

} // namespace shadowmap
