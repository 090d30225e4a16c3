#pragma once
// Placed lights and cameras as people name them: the names the tools print and accept,
// the one rule that turns a command-line word into an instance, and the list an error
// about an unknown name shows. Inside, lights and cameras are identified by instance.
#include "engine/scene/Scene.h"

#include <string>

namespace engine {

const char* toString(Light::Type type);
const char* toString(Camera::Type type);

// The light's (camera's) own name, else its node's (glTF lights and cameras are often
// unnamed while their nodes are not), else "light N" ("camera N"), N its 1-based number.
std::string lightInstanceName(const Scene& scene, int instance);
std::string cameraInstanceName(const Scene& scene, int instance);

// The instance `text` means: the first light (camera) whose name or node's name is `text`;
// else, when `text` is a whole number N from 1 to the count, the N-th (the numbers
// engine-render --list prints, in glTF scene order; a name wins over a number, so a light
// called "2" is never light number 2). -1 when neither.
int findLightInstanceByNameOrNumber(const Scene& scene, const std::string& text);
int findCameraInstanceByNameOrNumber(const Scene& scene, const std::string& text);

// For messages about a name that matched nothing: "the scene's lights: 1 spot_light,
// 2 sun" (at most 10, then "..."), or "the scene has no lights".
std::string describeLightInstances(const Scene& scene);

// "the scene has 34 lights; only the first 32 are rendered, not: 33 lamp_33, 34 lamp_34" (at most 10
// names, then "..."), or "" when the scene has at most `limit`.
std::string lightsPastTheLimit(const Scene& scene, int limit);
std::string describeCameraInstances(const Scene& scene);

} // namespace engine
