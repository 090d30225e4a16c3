#include "technique/depth/BackfaceDepth.h"

#include <algorithm>

namespace shadowmap {

void BackfaceDepth::adjustStyle(LightState& light, const DepthStyleContext& context, DepthPassStyle& style) const {
    style.backFacesOnly = true;
    style.openCasterOffset = light.settings.standardPolygonOffset();
    style.closedMeshes = &context.closedMeshes;
    std::vector<std::string>& open = light.frame.openCasters;
    for (const engine::MeshInstance& instance : context.scene.meshInstances) {
        if (!instance.castShadows || context.closedMeshes[instance.mesh]) continue;
        const std::string& name = context.scene.nodes[instance.node].name;
        open.push_back(name.empty() ? "node " + std::to_string(instance.node) : name);
    }
    // One line per light, however many casters (an imported CAD model has hundreds).
    if (open.empty()) return;
    constexpr std::size_t kNamed = 3;
    std::string names;
    for (std::size_t i = 0; i < std::min(open.size(), kNamed); ++i) names += (i ? ", \"" : "\"") + open[i] + "\"";
    if (open.size() > kNamed) names += ", ...";
    light.frame.warnings.push_back("backface variant: " + std::to_string(open.size()) +
                                   " caster(s) not closed meshes (" + names +
                                   "); drawn two-sided with polygon offset (all in --stats open_casters)");
}

void BackfaceDepth::addStats(const LightState& light, nlohmann::json& stats) const {
    stats["open_casters"] = light.frame.openCasters;
}

} // namespace shadowmap
