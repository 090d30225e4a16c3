#pragma once
// The views a setting is scored over (--views): every glTF camera of the scene, or N views
// on a circle around it at the framing camera's distance and height, so a setting is not
// fitted to one picture.
#include "TuneOptions.h"

#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

#include <string>
#include <vector>

namespace shadowmap_tune {

// An InputError naming the scene when --views cameras is given and it has no camera.
std::vector<engine::FrameCamera> tuneViews(const engine::Scene& scene, const ViewSpec& spec, int width, int height,
                                           const std::string& sceneFile);

} // namespace shadowmap_tune
