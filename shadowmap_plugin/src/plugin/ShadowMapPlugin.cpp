#include "plugin/ShadowMapPlugin.h"

#include "plugin/DepthFormatGl.h"
#include "plugin/MapCacheKey.h"
#include "plugin/ShadowBlock.h"

#include "engine/scene/FrustumCull.h"
#include "math/LightFrustum.h"
#include "math/Texgen.h"

#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"
#include "engine/scene/SceneNames.h"
#include "engine/util/Error.h"
#include "engine/util/Hasher.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace shadowmap {


namespace {
// Cube maps: the reference depth is lowered by the depth a 45-degree surface spans across
// this many texels of the face (visibility.glsl, shadowMapCube). The faces are axis-aligned
// in world space, so a surface facing a face's axis (any floor under a point light) has zero
// depth slope in that face and the slope-scaled polygon offset gives it no margin at all:
// a small step in it (2CylinderEngine's crankcase top: about 0.07 units, judged by the 4000
// d24 offset units that also hide it) shadowed up to half a texel beside it, a dotted acne
// line that the spot light at the same place, its axis tilted to that surface, does not
// show. Measured with
// engine-render --truth (1280x720, 2048 maps, d24, pcf), acne / leak in percent:
//   bias        0       0.1     0.25    0.5     1
//   engine      1.197   1.113   1.042   0.949   0.809   (key point light; leak 0.342 .. 0.374)
//   showcase    0.070                   0.064           (point_light; leak 0.028 at both)
// 0.5 removes the line (acne -0.25 points for +0.016 leak); tools/shadowmap-stress --quick:
// the point light's acne summed over its cases 18.9 -> 14.1, leak and every other light as
// before, no case worse. Larger biases trade more leak for acne the polygon offset already
// handles.
constexpr double kCubeTexelBias = 0.5;

constexpr int kFirstUnit = engine::kFirstPluginTextureUnit;

// Receivers the camera can see (only they need shadows this frame) and every caster.
ShadowBounds frameBounds(const engine::Frame& frame) {
    const glm::dmat4 cameraViewProjection =
        frame.camera().projection * glm::inverse(frame.camera().eyeToWorld);
    ShadowBounds bounds;
    for (const engine::MeshInstance& instance : frame.scene().meshInstances) {
        if (instance.castShadows) bounds.casters.push_back(instance.worldBounds);
        if (instance.receiveShadows && engine::boxIntersectsFrustum(cameraViewProjection, instance.worldBounds))
            bounds.receivers.push_back(instance.worldBounds);
    }
    return bounds;
}

// polygon_offset_clamp (a slope S) as glPolygonOffsetClamp's window-depth clamp for this
// light: factor * S * (window depth across one texel of a 45-degree surface) plus the units
// part, so the clamp only bites once the slope exceeds S. Perspective maps: taken at the
// nearest receiver, where a texel is smallest and the depth steepest (farther away the
// same clamp allows a steeper slope: it errs toward acne-free). 0: no clamp.
float offsetClamp(const LightShadow& light) {
    const ShadowSettings& settings = light.settings;
    const glm::vec2 offset = settings.effectivePolygonOffset();
    if (!(settings.polygonOffsetClamp > 0.0f) || offset == glm::vec2(0.0f)) return 0.0f;
    const LightShadowFrame& plan = light.frame;
    // Cascades share one style: the nearest cascade's texels are the smallest, so its clamp
    // is the tightest (the farther ones then allow a steeper slope: acne-free side).
    const LightView* cascade = nullptr;  // the nearest cascade that draws anything
    for (const LightView& view : plan.cascades.cascades)
        if (!cascade && !view.empty) cascade = &view;
    const LightView& view = plan.kind == MapKind::Cube       ? plan.pointViews.faces[0]
                            : plan.kind == MapKind::Cascades ? *cascade
                                                             : plan.view;
    const double perTexel = windowDepthPerTexel(view, settings.resolution);
    // Float units are 2^(e-23) of the depth e: at most 2^-23 below 1 (reversed Z).
    const double units = std::abs(offset.y) * (settings.reversedZ ? std::ldexp(1.0, -23) : depthStep(settings.depthFormat));
    return static_cast<float>(std::abs(offset.x) * settings.polygonOffsetClamp * perTexel + units);
}

// Every receiver and caster of the scene, seen or not: what a stable cascade anchors to.
engine::Aabb sceneBounds(const engine::Scene& scene) {
    engine::Aabb bounds;
    for (const engine::MeshInstance& instance : scene.meshInstances)
        if (instance.castShadows || instance.receiveShadows) bounds.extend(instance.worldBounds);
    return bounds;
}

CascadeOptions cascadeOptions(const ShadowSettings& settings, const FrustumFitOptions& fit) {
    CascadeOptions options;
    options.count = settings.cascades;
    options.lambda = settings.cascadeLambda;
    options.blend = settings.cascadeBlend;
    options.stable = settings.stable;
    options.resolution = settings.resolution;
    options.fit = fit;
    return options;
}

// A directional light's cascade count this frame: the setting's, or with `auto` the count
// the view needs (CascadeFit.h autoCascadeCount), remembered for the next frame. The weighing
// fits one map and three cascade sets; while its inputs (camera, light, boxes, settings) stay
// as they were, last frame's answer is reused.
int cascadeCount(LightShadow& light, const engine::LightInstance& placed, const engine::Light& source,
                 const ShadowBounds& bounds, const engine::Aabb& everything, const engine::Frame& frame,
                 const FrustumFitOptions& fit) {
    if (light.settings.cascades != kAutoCascades) return light.settings.cascades;
    LightShadowFrame& plan = light.frame;
    plan.autoCascades = true;
    engine::Hasher inputs;
    inputs.add(everything.min);
    inputs.add(everything.max);
    inputs.add(frame.camera().eyeToWorld);
    inputs.add(frame.camera().projection);
    inputs.add(frame.camera().height);
    inputs.add(placed.world);
    inputs.add(light.settings.resolution);
    inputs.add(light.settings.cascadeLambda);
    inputs.add(light.settings.cascadeBlend);
    inputs.add(light.settings.stable);
    inputs.add(light.settings.reversedZ);
    for (const auto* boxes : {&bounds.receivers, &bounds.casters}) {
        inputs.add(boxes->size());
        for (const engine::Aabb& box : *boxes) {
            inputs.add(box.min);
            inputs.add(box.max);
        }
    }
    if (light.autoCascadeCount > 0 && inputs.value() == light.cascadeNeedKey) {
        plan.cascadeNeed = light.cascadeNeed;
        plan.cascadeNeedReused = true;
        return light.autoCascadeCount;
    }
    plan.cascadeNeed = cascadeNeed(placed, source, bounds, everything,
                                   {frame.camera().eyeToWorld, frame.camera().projection},
                                   cascadeOptions(light.settings, fit), frame.camera().height);
    light.cascadeNeed = plan.cascadeNeed;
    light.cascadeNeedKey = inputs.value();
    light.autoCascadeCount = autoCascadeCount(plan.cascadeNeed, light.autoCascadeCount);
    return light.autoCascadeCount;
}

// The map cache key (MapCacheKey.h) with the depth settings that change a map without
// changing its view-projection: reversed Z's depth state and the slope-offset clamp.
std::uint64_t withDepthSettings(std::uint64_t key, const ShadowSettings& settings) {
    engine::Hasher hasher;
    hasher.add(key);
    hasher.add(settings.reversedZ);
    hasher.add(settings.polygonOffsetClamp);
    return hasher.value();
}

} // namespace

bool ShadowMapPlugin::setLightOption(const std::string& light, const std::string& key, const nlohmann::json& value) {
    // Checked alone now, so a bad key or value is refused before any GL work; checked again
    // combined with the light's other settings in resolveLights (reversed_z needs d32f...).
    const nlohmann::json option = {{key, value}};
    ShadowSettings scratch;
    applySettings(scratch, option, "", "light \"" + light + "\"");
    lightOptions_[light][key] = value;
    return true;
}

nlohmann::json ShadowMapPlugin::sceneLightSettings(const engine::Scene& scene, int slot) const {
    const engine::Light& light = scene.lights[scene.lightInstances[slot].light];
    if (light.extras.is_object() && light.extras.contains("shadow") && light.extras["shadow"].is_object())
        return light.extras["shadow"];
    return nlohmann::json::object();
}

void ShadowMapPlugin::resolveLights(const engine::Scene& scene) {
    const std::string source = scene.sourcePath;
    GLint maxTextureSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize);
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &maxTextureUnits_);
    // Overrides name lights as engine-render resolved them (lightInstanceName).
    for (const auto& [name, options] : lightOptions_) {
        bool found = false;
        for (std::size_t i = 0; i < scene.lightInstances.size() && !found; ++i)
            found = engine::lightInstanceName(scene, static_cast<int>(i)) == name;
        if (!found)
            engine::throwInputError(source, "light \"" + name + "\" (command line)",
                                    "no light of that name in the scene (" + engine::describeLightInstances(scene) + ")");
    }

    lights_.clear();
    scenePath_ = source;
    // The backface variant may cull front faces only of closed casters; a double-sided
    // material means the surface is meant to be seen (and to cast) from both sides, and an
    // alpha-tested one has holes whatever its geometry: light passes through the front face
    // and must still be stopped by the back face's opaque texels, or the other way round.
    closedMeshes_.assign(scene.meshes.size(), false);
    for (std::size_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
        bool closed = scene.meshes[mesh].closed;
        for (const engine::Primitive& primitive : scene.meshes[mesh].primitives) {
            if (primitive.material < 0) continue;
            const engine::Material& material = scene.materials[primitive.material];
            closed = closed && !material.doubleSided && !engine::castsAlphaTested(material);
        }
        closedMeshes_[mesh] = closed;
    }
    for (std::size_t slot = 0; slot < scene.lightInstances.size(); ++slot) {
        if (static_cast<int>(slot) == engine::kMaxLights) break;
        const engine::LightInstance& placed = scene.lightInstances[slot];
        const engine::Light& light = scene.lights[placed.light];
        LightShadow shadow;
        shadow.name = engine::lightInstanceName(scene, static_cast<int>(slot));
        shadow.slot = static_cast<int>(slot);
        shadow.type = light.type;
        shadow.settings = defaults_;
        const std::string object = "light \"" + shadow.name + "\"";
        if (light.extras.is_object() && light.extras.contains("shadow"))
            applySettings(shadow.settings, light.extras["shadow"], source, object + ": extras.shadow");
        // KHR_lights_shadows "castShadows": false: the file says this light casts no shadow,
        // and that wins over our extras (only the command line's variant overrides it).
        if (!light.castShadows) {
            if (shadow.settings.variant != Variant::None && light.extras.contains("shadow") &&
                light.extras["shadow"].contains("variant"))
                warnOnce(shadow, std::string("KHR_lights_shadows castShadows is false: extras.shadow variant \"") +
                                     toString(shadow.settings.variant) + "\" is not used");
            shadow.settings.variant = Variant::None;
        }
        // The command line's per-light settings come last: they win over everything.
        const auto options = lightOptions_.find(shadow.name);
        if (options != lightOptions_.end()) applySettings(shadow.settings, options->second, "", object);
        checkLimits(shadow.settings, maxTextureSize, source,
                    options == lightOptions_.end() ? object + ": extras.shadow" : object);
        lights_.push_back(std::move(shadow));
    }
}

void ShadowMapPlugin::prepareScene(const engine::Scene& scene) {
    resolveLights(scene);
    ++sceneGeneration_;  // new geometry: no map is still right
    cacheHits_ = cacheMisses_ = 0;
}

void ShadowMapPlugin::reloadSettings(const engine::Scene& scene) {
    std::vector<LightShadow> previous = std::move(lights_);
    resolveLights(scene);
    // Keep each light's map: its cache key covers the settings, so a light whose settings
    // changed misses and re-renders, and the others keep hitting.
    for (LightShadow& light : lights_)
        for (LightShadow& old : previous)
            if (old.slot == light.slot) {
                light.map = std::move(old.map);
                light.renderedKey = old.renderedKey;
            }
}

void ShadowMapPlugin::warnOnce(const LightShadow& light, const std::string& message) {
    // Once per scene file, light and message for the plugin's life: a sweep that sets the
    // same scene again for every setting (shadowmap-bench) must not repeat itself.
    const std::string line = std::string(kPluginName) + ": " + scenePath_ + ": light \"" + light.name + "\": " + message;
    if (warned_.insert(line).second) std::cerr << "warning: " << line << "\n";
}

bool ShadowMapPlugin::planLight(LightShadow& light, const engine::Frame& frame,
                                const ShadowBounds& bounds) {
    LightShadowFrame& plan = light.frame;
    plan = {};
    const engine::Scene& scene = frame.scene();
    const engine::LightInstance& placed = scene.lightInstances[light.slot];
    const engine::Light& source = scene.lights[placed.light];
    if (light.settings.variant == Variant::None) {
        plan.skipReason = "variant none";
        return false;
    }
    if (source.intensity <= 0.0f || source.color == glm::vec3(0.0f)) {
        plan.skipReason = "the light emits nothing";
        return false;
    }
    // Cascades slice a directional light's parallel projection; a spot or point light's
    // perspective already spends its texels near the light (said once when set; auto is silent).
    if (light.type != engine::Light::Type::Directional && light.settings.cascades > 1)
        warnOnce(light, "cascades apply to directional lights only: " + std::to_string(light.settings.cascades) +
                            " ignored");
    // Forced near/far and reversed Z (shadowmap/ShadowSettings.h). A directional light's depth is
    // linear and fitted to what it must hold: forced planes are ignored there (said once).
    FrustumFitOptions fitOptions;
    fitOptions.reversedZ = light.settings.reversedZ;
    if (light.type == engine::Light::Type::Directional) {
        if (light.settings.nearPlane > 0.0 || light.settings.farPlane > 0.0)
            warnOnce(light, "near_plane/far_plane apply to spot and point lights; ignored for a directional light");
    } else {
        fitOptions.nearPlane = light.settings.nearPlane;
        fitOptions.farPlane = light.settings.farPlane;
    }
    // Every receiver and caster, what stable cascades anchor to (and auto weighs).
    const engine::Aabb everything =
        light.type == engine::Light::Type::Directional ? sceneBounds(scene) : engine::Aabb{};
    if (light.type == engine::Light::Type::Directional)
        plan.cascadeCount = cascadeCount(light, placed, source, bounds, everything, frame, fitOptions);
    bool valid = false, empty = true;
    std::string invalidReason;
    if (light.type == engine::Light::Type::Point) {
        plan.pointViews = fitPointLight(placed, source, bounds, fitOptions);
        valid = plan.pointViews.valid;
        invalidReason = plan.pointViews.invalidReason;
        for (const LightView& face : plan.pointViews.faces) empty = empty && face.empty;
    } else if (plan.cascadeCount > 1) {
        CascadeOptions options = cascadeOptions(light.settings, fitOptions);
        options.count = plan.cascadeCount;
        plan.cascades = fitDirectionalCascades(placed, source, bounds, everything,
                                               {frame.camera().eyeToWorld, frame.camera().projection}, options);
        valid = plan.cascades.valid;
        invalidReason = plan.cascades.invalidReason;
        // Nothing to draw in any cascade (or no cascade: no visible receiver) is no map at all.
        empty = true;
        for (const LightView& cascade : plan.cascades.cascades) empty = empty && cascade.empty;
    } else {
        plan.view = light.type == engine::Light::Type::Spot ? fitSpotLight(placed, source, bounds, fitOptions)
                                                            : fitDirectionalLight(placed, source, bounds, fitOptions);
        valid = plan.view.valid;
        invalidReason = plan.view.invalidReason;
        empty = plan.view.empty;
        if (!plan.view.clampWarning.empty()) warnOnce(light, plan.view.clampWarning);
    }
    if (!valid) {
        // Never upload NaN: a degenerate light loses its shadow, loudly.
        plan.skipReason = "no shadow: " + invalidReason;
        warnOnce(light, plan.skipReason);
        return false;
    }
    if (empty) {
        plan.skipReason = "no visible receiver in the light's frustum";
        plan.emptyFrustum = true;
        return false;
    }
    // Each shadowed light samples its map on unit kFirstUnit + slot.
    if (kFirstUnit + light.slot >= maxTextureUnits_) {
        plan.skipReason = "no texture unit left for its map (GL_MAX_TEXTURE_IMAGE_UNITS " +
                          std::to_string(maxTextureUnits_) + ")";
        warnOnce(light, plan.skipReason);
        return false;
    }
    plan.kind = light.type == engine::Light::Type::Point ? MapKind::Cube
                : plan.cascades.cascades.empty()          ? MapKind::Map2D
                                                          : MapKind::Cascades;
    return true;
}

namespace {

void addCounts(LightShadowFrame& plan, const DepthDrawCounts& counts) {
    plan.draws += counts.draws;
    plan.triangles += counts.triangles;
    plan.castersCulled += counts.castersCulled;
}

// Woo's peel against the first layer: fragments within a step or two of it are that layer.
DepthPassStyle peelStyle(const DepthPassStyle& style, const ShadowSettings& settings, unsigned firstLayer) {
    DepthPassStyle peel = style;
    peel.firstLayer = firstLayer;
    const double step = depthStep(settings.depthFormat);
    peel.peelEpsilon = static_cast<float>(settings.depthFormat == DepthFormat::D32F ? 4.0 * step : 2.0 * step);
    // Reversed Z: relative, eight float steps of z1 (z1 * 2^-20).
    if (settings.reversedZ) peel.peelEpsilon = std::ldexp(1.0f, -20);
    return peel;
}

} // namespace

void ShadowMapPlugin::addDepthPasses(LightShadow& light, engine::Frame& frame,
                                     engine::ResourceHandle map, std::uint64_t key) {
    const ShadowSettings& settings = light.settings;
    const bool cube = light.frame.kind == MapKind::Cube;
    const bool cascaded = light.frame.kind == MapKind::Cascades;
    light.frame.facesRendered = cube || cascaded ? 0 : 1;
    if (cube)
        for (const LightView& view : light.frame.pointViews.faces)
            (view.empty ? light.frame.facesSkipped : light.frame.facesRendered) += 1;
    if (cascaded)  // rendered: layers drawn this frame; skipped: empty or still right
        for (std::size_t c = 0; c < light.frame.cascades.cascades.size(); ++c)
            (light.frame.cascades.cascades[c].empty || light.frame.cascadeHits[c] ? light.frame.facesSkipped
                                                                                  : light.frame.facesRendered) += 1;

    DepthPassStyle style;
    style.polygonOffset = settings.effectivePolygonOffset();
    style.reversedZ = settings.reversedZ;
    style.offsetClamp = offsetClamp(light);
    if (settings.variant == Variant::Backface) {
        style.backFacesOnly = true;
        style.openCasterOffset = settings.standardPolygonOffset();
        style.closedMeshes = &closedMeshes_;
        reportOpenCasters(light, frame);
    }
    if (cascaded) {
        // One layer per cascade; one whose slice holds no receiver is cleared (reads "far").
        // Layers still right from an earlier frame keep their depth (per-cascade caching).
        const std::vector<LightView>& cascades = light.frame.cascades.cascades;
        for (std::size_t c = 0; c < cascades.size(); ++c) {
            if (light.frame.cascadeHits[c]) continue;
            light.renderedCascadeKeys[c] = 0;  // set again once its passes have run
            addLayerPasses(light, frame, map, static_cast<int>(c), cascades[c].viewProjection(), !cascades[c].empty,
                           style, &light.renderedCascadeKeys[c], light.frame.cascadeKeys[c]);
        }
        return;
    }
    if (!cube) {
        addLayerPasses(light, frame, map, -1, light.frame.view.viewProjection(), true, style, &light.renderedKey, key);
        return;
    }
    // A face that sees no receiver is cleared (lookups there must read "far") but draws nothing.
    for (int face = 0; face < 6; ++face) {
        const LightView& view = light.frame.pointViews.faces[face];
        addLayerPasses(light, frame, map, face, view.viewProjection(), !view.empty, style, &light.renderedKey,
                       face == 5 ? key : 0);
    }
}

void ShadowMapPlugin::addLayerPasses(LightShadow& light, engine::Frame& frame, engine::ResourceHandle map,
                                     int layer, const glm::dmat4& viewProjection, bool drawCasters,
                                     const DepthPassStyle& style, std::uint64_t* keyTarget,
                                     std::uint64_t keyWhenDone) {
    // Only now does the map (layer) hold what the key says.
    auto done = [keyTarget, keyWhenDone] {
        if (keyWhenDone) *keyTarget = keyWhenDone;
    };
    if (light.settings.variant != Variant::Woo || !drawCasters) {
        frame.graph().addPass(
            light.depthPass(layer),
            [map, layer, style](engine::PassBuilder& builder) {
                (void)builder.write(map, layer);
                builder.setTargets(depthPassTargets(map, layer, style));
                builder.setState(depthPassState(style));
            },
            [this, &light, &frame, viewProjection, style, drawCasters, done](engine::PassContext& context) {
                if (drawCasters) addCounts(light.frame, depth_->draw(frame, context, viewProjection, style));
                done();
            });
        return;
    }
    // Woo: the nearest layer first (a transient of the map's size), then the midpoint pass
    // peeling it into this layer of the light's map. The same style (offset included) for
    // both: the peel discards what lies within a depth step or two of z1, so both passes
    // must rasterize the nearest surface to the same depth. An offset in the peel alone left
    // the nearest surface behind z1, kept as a second layer: acne on 1.2% of the showcase
    // sun's pixels (14.7% at 512).
    auto firstLayer = std::make_shared<engine::ResourceHandle>();
    const engine::TextureDesc firstLayerDesc{light.settings.resolution, light.settings.resolution,
                                             graphFormat(light.settings.depthFormat)};
    frame.graph().addPass(
        light.firstLayerPass(layer),
        [&light, layer, style, firstLayer, firstLayerDesc](engine::PassBuilder& builder) {
            *firstLayer = builder.create(light.firstLayerResource(layer), firstLayerDesc);
            builder.setTargets(depthPassTargets(*firstLayer, -1, style));
            builder.setState(depthPassState(style));
        },
        [this, &light, &frame, viewProjection, style](engine::PassContext& context) {
            addCounts(light.frame, depth_->draw(frame, context, viewProjection, style));
        });
    frame.graph().addPass(
        light.depthPass(layer),
        [map, layer, firstLayer, style](engine::PassBuilder& builder) {
            builder.read(*firstLayer);
            (void)builder.write(map, layer);
            builder.setTargets(depthPassTargets(map, layer, style));
            builder.setState(depthPassState(style));
        },
        [this, &light, &frame, viewProjection, firstLayer, style, done](engine::PassContext& context) {
            const DepthPassStyle peel = peelStyle(style, light.settings, context.texture(*firstLayer));
            addCounts(light.frame, depth_->draw(frame, context, viewProjection, peel));
            done();
        });
}

void ShadowMapPlugin::reportOpenCasters(LightShadow& light, const engine::Frame& frame) {
    const engine::Scene& scene = frame.scene();
    for (const engine::MeshInstance& instance : scene.meshInstances) {
        if (!instance.castShadows || closedMeshes_[instance.mesh]) continue;
        const std::string& name = scene.nodes[instance.node].name;
        light.frame.openCasters.push_back(name.empty() ? "node " + std::to_string(instance.node) : name);
    }
    // One line per light, however many casters (an imported CAD model has hundreds).
    const std::vector<std::string>& open = light.frame.openCasters;
    if (open.empty()) return;
    constexpr std::size_t kNamed = 3;
    std::string names;
    for (std::size_t i = 0; i < std::min(open.size(), kNamed); ++i) names += (i ? ", \"" : "\"") + open[i] + "\"";
    if (open.size() > kNamed) names += ", ...";
    warnOnce(light, "backface variant: " + std::to_string(open.size()) + " caster(s) not closed meshes (" + names +
                        "); drawn two-sided with polygon offset (all in --stats open_casters)");
}

engine::LightVisibilityHook ShadowMapPlugin::makeHook(const engine::Frame& frame) {
    const glm::dmat4& eyeToWorld = frame.camera().eyeToWorld;  // V
    const glm::dmat4 view = glm::inverse(eyeToWorld);          // V^-1
    // Lights without a map this frame: fully visible, nothing dimmed.
    ShadowBlock block{};
    glm::vec4* params = block.params;
    for (int slot = 0; slot < engine::kMaxLights; ++slot) {
        params[slot] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        block.pointFar[slot].x = 1.0f;
    }
    block.eyeToWorld = glm::mat4(glm::mat3(glm::dmat3(eyeToWorld)));
    std::vector<std::pair<int, unsigned>> units;      // texture unit, map (comparing)
    std::vector<std::pair<int, unsigned>> rawUnits;   // texture unit, map (raw depth, debug)
    std::vector<std::uint64_t> shadeKeys(lights_.size(), 0);  // 0: not to be reused
    // A light without a map this frame has one shade everywhere (1, or 0 for a spot light
    // whose frustum holds nothing visible): the lit pass needs no lookup for it.
    std::map<int, float> constantShades;

    // What the generated GLSL depends on: per shadowed light its slot, map kind and whether
    // its comparison view has a texture unit.
    std::vector<HookGlsl::Lookup> lookups;
    for (const LightShadow& light : lights_) {
        const LightShadowFrame& plan = light.frame;
        // Outside a spot light's frustum is outside its cone: never lit by it. Directional
        // frusta hold every visible receiver, so what lies outside has nothing to fear.
        const float outsideShade = light.type == engine::Light::Type::Spot ? 0.0f : 1.0f;
        if (plan.kind == MapKind::None) {
            if (plan.emptyFrustum) params[light.slot] = glm::vec4(0.0f, 0.0f, 0.0f, outsideShade);
            constantShades[light.slot] = params[light.slot].w;
            continue;
        }
        // What the lookup uploads must be finite: a light whose eye planes (or eye-space
        // position) are not loses its shadow, loudly, instead of shading with NaN.
        const bool cascaded = plan.kind == MapKind::Cascades;
        const glm::dmat4 planes = plan.kind == MapKind::Map2D
                                      ? eyePlanesForCamera(plan.view.texgenPlanes(), eyeToWorld)
                                      : glm::dmat4(view[0], view[1], view[2],
                                                   view * glm::dvec4(frame.scene().lightInstances[light.slot].position(), 1.0));
        const glm::mat4 uploaded(planes);  // as the GPU gets it: float
        std::vector<glm::mat4> cascadePlanes;  // per cascade, Ee as for a 2D map
        if (cascaded)
            for (const LightView& cascade : plan.cascades.cascades)
                cascadePlanes.emplace_back(eyePlanesForCamera(cascade.texgenPlanes(), eyeToWorld));
        bool finite = true;
        for (const glm::mat4& matrix : cascaded ? cascadePlanes : std::vector<glm::mat4>{uploaded})
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(matrix[c][r]);
        if (!finite) {
            warnOnce(light, "no shadow: its texgen planes for this camera are not finite");
            constantShades[light.slot] = params[light.slot].w;
            continue;
        }
        // x: 1 = reversed Z (near 1, far 0: GL_GEQUAL, out of range flipped);
        // y: reference bias subtracted from r: d32f without reversed Z computes r near 1 with
        //    an absolute float error, which float polygon-offset units (relative) do not
        //    cover below depth 0.5; units * 2^-24 restores the d24 meaning of units there
        //    (shadowmap/ShadowSettings.h).
        const bool floatForward = light.settings.depthFormat == DepthFormat::D32F && !light.settings.reversedZ;
        const float referenceBias =
            floatForward ? static_cast<float>(std::abs(light.settings.effectivePolygonOffset().y) * std::ldexp(1.0, -24))
                         : 0.0f;
        params[light.slot] = glm::vec4(light.settings.reversedZ ? 1.0f : 0.0f, referenceBias,
                                       light.settings.dimming, outsideShade);
        // The lit pass may reuse this light's shade per pixel while this key (and the camera
        // and geometry, which the engine adds) holds: the map's content and how it is read.
        engine::Hasher shadeKey;
        shadeKey.add(light.frame.mapKey);
        shadeKey.add(params[light.slot]);
        shadeKey.add(light.settings.filter);
        // Cascades: which one a pixel reads (the splits) and how it fades into the next.
        for (const double split : plan.cascades.splits) shadeKey.add(split);
        shadeKey.add(light.settings.cascadeBlend);
        // Without map caching nothing is reused: a depth pass whose map no pass reads
        // would be culled, and timing runs (bench, cache_maps false) would time nothing.
        if (cacheMaps_) shadeKeys[light.slot] = shadeKey.value();
        units.emplace_back(kFirstUnit + light.slot, light.map.id());
        // The comparison view reads the same map's raw depth on a second unit, through a
        // sampler object with comparison off, when the GL has units to spare: counted down
        // from the last unit, above every light's comparing unit.
        const int rawUnit = maxTextureUnits_ - 1 - light.slot;
        const bool debuggable = rawUnit >= kFirstUnit + static_cast<int>(lights_.size());
        if (debuggable) rawUnits.emplace_back(rawUnit, light.map.id());
        const bool cube = plan.kind == MapKind::Cube;
        const int cascadeCount = cascaded ? static_cast<int>(cascadePlanes.size()) : 0;
        lookups.push_back({light.slot, kFirstUnit + light.slot, cube, debuggable ? rawUnit : -1, cascadeCount});
        if (cascaded) {
            // The far view depth of each cascade; unused entries never match (visibility.glsl).
            for (int c = 0; c < kMaxCascades; ++c) {
                if (c < cascadeCount) block.cascadePlanes[light.slot * kMaxCascades + c] = cascadePlanes[c];
                block.cascadeFar[light.slot][c] =
                    c < cascadeCount ? static_cast<float>(plan.cascades.splits[c + 1]) : std::numeric_limits<float>::max();
            }
            block.cascadeBlend[light.slot] = glm::vec4(static_cast<float>(light.settings.cascadeBlend),
                                                       static_cast<float>(plan.cascades.splits.front()), 0.0f, 0.0f);
        } else if (!cube) {
            // Ee = Epo * V with Epo = S * P_light * L^-1, composed in double (Texgen.h).
            block.eyePlanes[light.slot] = uploaded;
        } else {
            const glm::dvec3 lightPosition = frame.scene().lightInstances[light.slot].position();
            block.pointLight[light.slot] = glm::vec4(glm::vec3(view * glm::dvec4(lightPosition, 1.0)),
                                                     static_cast<float>(plan.pointViews.nearPlane));
            // 0 stands for an infinite far plane (GLSL has no infinity to pass).
            block.pointFar[light.slot].x =
                std::isinf(plan.pointViews.farPlane) ? 0.0f : static_cast<float>(plan.pointViews.farPlane);
            // y: the bias in face widths (a 90-degree face spans 2 * distance over resolution texels).
            block.pointFar[light.slot].y = static_cast<float>(kCubeTexelBias * 2.0 / light.settings.resolution);
        }
    }

    engine::LightVisibilityHook hook;
    hook.owner = name();
    hook.constantShades = std::move(constantShades);
    hook.shadeKeys = std::move(shadeKeys);
    for (const glm::vec4& light : block.params) hook.dimming.push_back(light.z);
    const HookGlsl::Code& code = hookGlsl_.codeFor(lookups);
    hook.glsl = code.fragment;
    hook.vertexGlsl = code.vertex;
    hook.glslVersion = code.version;
    // Uploaded now, before any pass of the frame runs (GL keeps the order), once for every
    // program variant of the frame.
    if (!shadowBlock_.id())
        shadowBlock_ = engine::gl::Buffer::create(sizeof(ShadowBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(shadowBlock_.id(), 0, sizeof(ShadowBlock), &block);
    const unsigned rawSampler = rawDepthSampler().id();
    const unsigned blockBuffer = shadowBlock_.id();
    hook.bind = [=](const engine::gl::Program&, const engine::PassContext&) {
        glBindBufferBase(GL_UNIFORM_BUFFER, kShadowBlockBinding, blockBuffer);
        for (const auto& [unit, map] : units) glBindTextureUnit(unit, map);
        for (const auto& [unit, map] : rawUnits) {
            glBindTextureUnit(unit, map);
            glBindSampler(unit, rawSampler);
        }
    };
    return hook;
}

const engine::gl::Sampler& ShadowMapPlugin::rawDepthSampler() {
    if (!rawDepthSampler_.id()) {
        rawDepthSampler_ = engine::gl::Sampler::create();
        rawDepthSampler_.set(GL_TEXTURE_COMPARE_MODE, GL_NONE);
        rawDepthSampler_.set(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        rawDepthSampler_.set(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        rawDepthSampler_.set(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        rawDepthSampler_.set(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    return rawDepthSampler_;
}

void ShadowMapPlugin::addPasses(engine::Frame& frame) {
    if (!depth_) {
        depth_ = std::make_unique<DepthRenderer>();
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // PCF across cube face edges
    }
    const ShadowBounds bounds = frameBounds(frame);
    std::vector<engine::ResourceHandle> maps;
    for (LightShadow& light : lights_) {
        if (!planLight(light, frame, bounds)) continue;
        light.ensureMap();
        // Reversed Z compares the other way round (lit where r >= stored: near is 1).
        light.map.setParameter(GL_TEXTURE_COMPARE_FUNC, light.settings.reversedZ ? GL_GEQUAL : GL_LEQUAL);
        const bool cascaded = light.frame.kind == MapKind::Cascades;
        const std::uint64_t key =
            cascaded ? cascadeKeys(light, frame.scene())
                     : withDepthSettings(mapCacheKey(light, frame.scene(), sceneGeneration_), light.settings);
        light.frame.mapKey = key;
        light.frame.cacheHit =
            cascaded ? std::find(light.frame.cascadeHits.begin(), light.frame.cascadeHits.end(), false) ==
                           light.frame.cascadeHits.end()
                     : cacheMaps_ && key == light.renderedKey;
        const int size = light.settings.resolution;
        const int layers = light.frame.kind == MapKind::Cascades ? static_cast<int>(light.frame.cascades.cascades.size()) : 1;
        const engine::TextureDesc desc{size, size, graphFormat(light.settings.depthFormat), layers,
                                       light.type == engine::Light::Type::Point};
        const engine::ResourceHandle map =
            frame.graph().importTexture(light.mapResource(), desc, light.map.id());
        if (light.frame.cacheHit) {
            ++cacheHits_;  // the map is an input nobody writes this frame: no depth pass
        } else {
            ++cacheMisses_;
            if (!cascaded) light.renderedKey = 0;  // set again once the passes have run
            addDepthPasses(light, frame, map, key);
        }
        maps.push_back(map);
    }
    // Every light instance's view, shadowed or not (ShadowView.h): what the tools read.
    for (const LightShadow& light : lights_) frame.publishShadowView(light.view());
    engine::LightVisibilityHook hook = makeHook(frame);
    hook.reads = std::move(maps);
    frame.setLightVisibility(std::move(hook));
}

std::uint64_t ShadowMapPlugin::cascadeKeys(LightShadow& light, const engine::Scene& scene) {
    LightShadowFrame& plan = light.frame;
    const std::size_t count = plan.cascades.cascades.size();
    plan.cascadeKeys.assign(count, 0);
    plan.cascadeHits.assign(count, false);
    engine::Hasher combined;
    for (std::size_t c = 0; c < count; ++c) {
        plan.cascadeKeys[c] =
            withDepthSettings(cascadeCacheKey(light, static_cast<int>(c), scene, sceneGeneration_), light.settings);
        plan.cascadeHits[c] = cacheMaps_ && plan.cascadeKeys[c] == light.renderedCascadeKeys[c];
        combined.add(plan.cascadeKeys[c]);
    }
    return combined.value();
}

nlohmann::json ShadowMapPlugin::frameStats() const {
    nlohmann::json lights = nlohmann::json::array();
    for (const LightShadow& light : lights_) {
        nlohmann::json stats = light.stats();
        // JSON has no infinity: an infinite far plane (far_plane "infinite", reversed_z)
        // is reported as the string "infinite".
        if (stats.contains("far") && stats["far"].is_number() && std::isinf(stats["far"].get<double>()))
            stats["far"] = "infinite";
        if (light.settings.reversedZ) stats["reversed_z"] = true;
        lights.push_back(std::move(stats));
    }
    return {{"lights", lights}, {"cache_hits", cacheHits_}, {"cache_misses", cacheMisses_},
            {"cache_maps", cacheMaps_}};
}

} // namespace shadowmap
