#pragma once
// A light's depth passes for this frame: per layer its projection asks for, the passes its
// depth technique declares, in the style its settings give (offsets, depth direction, the
// slope-offset clamp), drawing through the DepthRenderer.
#include "plugin/CasterLods.h"
#include "plugin/DepthRenderer.h"
#include "plugin/LightShadow.h"

#include "engine/render/Frame.h"

#include <vector>

namespace shadowmap {

// closedMeshes: per Scene::meshes, closed and not double-sided (backface culls only those).
// Counts what is drawn into light.frame; each layer's key is recorded once its passes ran.
// `map` is the light's imported map; on return it names the version the last pass wrote.
// casterLods: the scene's simplified levels, drawn per the light's caster_lod (null: none);
// levelDraws: where the passes add their draws per level when they run.
void addDepthPasses(LightShadow& light, engine::Frame& frame, engine::ResourceHandle& map, DepthRenderer& renderer,
                    const std::vector<bool>& closedMeshes, const CasterLods* casterLods,
                    std::vector<std::uint64_t>& levelDraws, DepthPassStyle::Viewport atlasViewport = {});

} // namespace shadowmap
