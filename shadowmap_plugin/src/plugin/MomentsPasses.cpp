#include "plugin/MomentsPasses.h"

#include "technique/SoftShadowLayers.h"
#include "technique/Techniques.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <memory>

namespace shadowmap {

MomentsDepth momentsKind(const LightShadow& light) {
    MomentsDepth kind;
    kind.perspective = light.type != engine::Light::Type::Directional;
    kind.reversed = light.settings.reversedZ;
    kind.evsm = light.settings.filter == Filter::Evsm;
    return kind;
}

namespace {

// How a layer's window depths become the moments' depth: its planes are the ones the lookup
// reads from softLayers (the same functions pack both).
MomentsDepth momentsDepth(const LightShadow& light, int layer) {
    MomentsDepth depth = momentsKind(light);
    const glm::vec4 terms = light.frame.kind == MapKind::Cube      ? softCubeLayer(light.frame.pointViews, light)
                            : light.frame.kind == MapKind::Cascades ? softLayer(light.frame.cascades.cascades[layer], light)
                                                                    : softLayer(light.frame.view, light);
    depth.nearPlane = terms.z;
    depth.farPlane = terms.w;
    depth.exponents = light.settings.evsmExponents;
    return depth;
}

// A full-screen pass writing colour only.
engine::PassState momentsPassState() {
    engine::PassState state;
    state.depthTest = engine::PassState::DepthTest::Off;
    state.depthWrite = false;
    state.cull = engine::PassState::Cull::None;
    return state;
}

engine::PassTargets colorTarget(engine::ResourceHandle resource, int layer) {
    engine::PassTargets targets;
    targets.colors.push_back({resource, layer, std::nullopt});
    return targets;
}

constexpr glm::ivec2 kAlongS{1, 0}, kAlongT{0, 1};

} // namespace

void addMomentsPasses(LightShadow& light, engine::Frame& frame, engine::ResourceHandle map,
                      engine::ResourceHandle& moments, const MomentsRenderer& renderer) {
    engine::RenderGraph& graph = frame.graph();
    const MapProjection& projection = *mapProjection(light.frame.kind);
    const float radius = static_cast<float>(light.settings.filterRadius);
    const unsigned mapLayers = light.mapLayers.id();
    const engine::TextureDesc momentsDesc = light.momentsDesc();
    const engine::TextureDesc rowsDesc{momentsDesc.width, momentsDesc.height, momentsDesc.format};
    // Only a 2D map has mipmaps (one layer): its last pass builds them from what it wrote.
    const unsigned mipmapped = light.moments.levels() > 1 ? light.moments.id() : 0;
    const auto buildMipmaps = [mipmapped] {
        if (mipmapped) glGenerateTextureMipmap(mipmapped);
    };
    for (const MapLayer& layer : projection.layers(light)) {
        const int target = layer.layer;       // -1: the 2D map
        const int source = std::max(target, 0);  // its layer in the map's 2D-array view
        const MomentsDepth depth = momentsDepth(light, source);
        if (radius == 0.0f) {
            light.frame.passes.push_back(graph.addPass(
                light.momentsPass(target),
                [&moments, map, target](engine::PassBuilder& builder) {
                    builder.read(map);
                    moments = builder.write(moments, target);
                    builder.setTargets(colorTarget(moments, target));
                    builder.setState(momentsPassState());
                },
                [&renderer, mapLayers, source, depth, buildMipmaps](engine::PassContext&) {
                    renderer.fromDepth(mapLayers, source, depth, 0.0f, kAlongS);
                    buildMipmaps();
                }));
            continue;
        }
        auto rows = std::make_shared<engine::ResourceHandle>();
        light.frame.passes.push_back(graph.addPass(
            light.momentsPass(target),
            [rows, map, name = light.momentsRowsResource(target), rowsDesc](engine::PassBuilder& builder) {
                builder.read(map);
                *rows = builder.create(name, rowsDesc);
                builder.setTargets(colorTarget(*rows, -1));
                builder.setState(momentsPassState());
            },
            [&renderer, mapLayers, source, depth, radius](engine::PassContext&) {
                renderer.fromDepth(mapLayers, source, depth, radius, kAlongS);
            }));
        light.frame.passes.push_back(graph.addPass(
            light.momentsBlurPass(target),
            [rows, &moments, target](engine::PassBuilder& builder) {
                builder.read(*rows);
                moments = builder.write(moments, target);
                builder.setTargets(colorTarget(moments, target));
                builder.setState(momentsPassState());
            },
            [&renderer, rows, radius, buildMipmaps](engine::PassContext& context) {
                renderer.blur(context.texture(*rows), radius, kAlongT);
                buildMipmaps();
            }));
    }
}

} // namespace shadowmap
