#include "plugin/VolumePasses.h"

#include "engine/scene/Scene.h"
#include "engine/util/Hasher.h"

namespace shadowmap {

namespace {

// What the visibility depends on: the camera (the pixels and their surfaces), the light's
// placement and every mesh instance's (a caster's volume, a receiver's depth).
std::uint64_t visibilityKey(const LightShadow& light, const engine::Frame& frame, std::uint64_t sceneGeneration) {
    const engine::Scene& scene = frame.scene();
    const engine::FrameCamera& camera = frame.camera();
    engine::Hasher key;
    key.add(sceneGeneration);
    key.add(camera.eyeToWorld);
    key.add(camera.projection);
    key.add(camera.width);
    key.add(camera.height);
    key.add(scene.lightInstances[light.slot].world);
    for (const engine::MeshInstance& instance : scene.meshInstances) {
        key.add(instance.revision);
        key.add(instance.castShadows);
        key.add(instance.receiveShadows);
    }
    return key.value();
}

engine::PassState resolveState() {
    engine::PassState state;  // the pass sets its own state between its steps
    state.depthTest = engine::PassState::DepthTest::Off;
    state.depthWrite = false;
    state.cull = engine::PassState::Cull::None;
    return state;
}

} // namespace

engine::ResourceHandle addVolumePass(LightShadow& light, engine::Frame& frame, VolumeRenderer& volumes,
                                     DepthRenderer& depth, std::uint64_t sceneGeneration, bool cache) {
    const engine::FrameCamera& camera = frame.camera();
    light.ensureVisibility(camera.width, camera.height);
    // The counts are kept only while a viewer shows them: a frame that wants them and finds
    // none for this key makes the volumes again.
    const bool countsWanted = frame.mapReadbackRequested(light.slot);
    if (countsWanted) light.ensureStencilCount(camera.width, camera.height);
    const std::uint64_t key = visibilityKey(light, frame, sceneGeneration);
    LightShadowFrame& plan = light.frame;
    plan.mapKey = key;
    plan.cacheHit = cache && light.visibilityKey == key && (!countsWanted || light.stencilCountKey == key);
    const engine::TextureDesc desc{camera.width, camera.height, engine::TextureFormat::R8};
    engine::ResourceHandle visibility =
        frame.graph().importTexture(light.visibilityResource(), desc, light.visibility.id());
    if (countsWanted)
        plan.stencilCount = frame.graph().importTexture(light.stencilCountResource(), desc, light.stencilCount.id());
    if (plan.cacheHit) return visibility;
    light.visibilityKey = 0;  // until the pass has run
    light.stencilCountKey = 0;
    plan.passes.push_back(frame.graph().addPass(
        light.volumePass(),
        [&visibility, &plan](engine::PassBuilder& builder) {
            visibility = builder.write(visibility);
            engine::PassTargets targets;
            targets.colors.push_back({visibility, -1, std::nullopt});
            if (plan.stencilCount.valid()) plan.stencilCount = builder.write(plan.stencilCount);
            builder.setTargets(targets);
            builder.setState(resolveState());
        },
        [&volumes, &depth, &light, &frame, key, countsWanted](engine::PassContext& context) {
            const VolumeCounts counts =
                volumes.render(frame, context, depth, light, countsWanted ? &light.stencilCount : nullptr);
            light.frame.draws += counts.casters;
            light.frame.triangles += counts.volumeTriangles;
            light.frame.silhouetteEdges += counts.silhouetteEdges;
            light.frame.capTriangles += counts.capTriangles;
            light.frame.gpuVolumeCasters += counts.gpuCasters;
            light.frame.zPassVolumeCasters += counts.zPassCasters;
            light.frame.volumeFillQueried = counts.volumeTriangles > 0 || counts.gpuCasters > 0;
            light.visibilityKey = key;
            if (countsWanted) light.stencilCountKey = key;
        }));
    if (plan.stencilCount.valid()) frame.graph().markOutput(plan.stencilCount);  // read back after the frame
    return visibility;
}

} // namespace shadowmap
