#include "technique/depth/WooDepth.h"

#include "technique/DepthFormatGl.h"
#include "technique/depth/StandardDepth.h"

#include <cmath>
#include <memory>

namespace shadowmap {

namespace shaders {
extern const char woo_peel_vert[];
extern const char woo_peel_frag[];
} // namespace shaders

namespace {

const DepthProgram kPeelProgram{"shadow depth peel", shaders::woo_peel_vert, shaders::woo_peel_frag,
                                /*drawsFullScreenLayer=*/true};

// The peel against the first layer: fragments within a step or two of it are that layer.
DepthPassStyle peelStyle(const DepthPassStyle& style, const ShadowSettings& settings, unsigned firstLayer) {
    DepthPassStyle peel = style;
    peel.program = &kPeelProgram;
    peel.inputTexture = firstLayer;
    // The second layer may be a receiver that casts nothing; the first layer never is (drawn
    // only here, such a receiver cannot hide what lies behind it), and where no caster is in
    // front the peel discards it (z1 is the far depth), so the texel stays far.
    peel.drawsNonCastingReceivers = true;
    const double step = depthStep(settings.depthFormat);
    float epsilon = static_cast<float>(settings.depthFormat == DepthFormat::D32F ? 4.0 * step : 2.0 * step);
    // Reversed Z: relative, eight float steps of z1 (z1 * 2^-20).
    if (settings.reversedZ) epsilon = std::ldexp(1.0f, -20);
    peel.uniforms.push_back({"uPeelEpsilon", epsilon});
    return peel;
}

} // namespace

std::vector<const DepthProgram*> WooDepth::programs() const { return {&nearestDepthProgram(), &kPeelProgram}; }

void WooDepth::addLayerPasses(const LayerPasses& passes) const {
    if (!passes.layer.drawsCasters) {
        addSingleDepthPass(passes);  // nothing to peel: the layer is only cleared
        return;
    }
    // The same style (offset included) for both passes: the peel discards what lies within
    // a depth step or two of z1, so both must rasterize the nearest surface to the same
    // depth. An offset in the peel alone left the nearest surface behind z1, kept as a
    // second layer: acne on 1.2% of the showcase sun's pixels (14.7% at 512).
    const LightState& light = passes.light;
    engine::ResourceHandle& map = passes.map;
    const int layer = passes.layer.layer;
    const DepthPassStyle style = passes.style;
    const glm::dmat4 viewProjection = passes.layer.viewProjection;
    auto firstLayer = std::make_shared<engine::ResourceHandle>();
    const engine::TextureDesc firstLayerDesc{light.settings.resolution, light.settings.resolution,
                                             graphFormat(light.settings.depthFormat)};
    passes.added.push_back(passes.graph.addPass(
        light.firstLayerPass(layer),
        [name = light.firstLayerResource(layer), style, firstLayer, firstLayerDesc](engine::PassBuilder& builder) {
            *firstLayer = builder.create(name, firstLayerDesc);
            builder.setTargets(depthPassTargets(*firstLayer, -1, style));
            builder.setState(depthPassState(style));
        },
        [draw = passes.draw, viewProjection, style](engine::PassContext& context) {
            draw(context, viewProjection, style);
        }));
    passes.added.push_back(passes.graph.addPass(
        light.depthPass(layer),
        [&map, layer, firstLayer, style](engine::PassBuilder& builder) {  // setup runs inside addPass
            builder.read(*firstLayer);
            map = builder.write(map, layer);
            builder.setTargets(depthPassTargets(map, layer, style));
            builder.setState(depthPassState(style));
        },
        [draw = passes.draw, done = passes.done, settings = light.settings, viewProjection, firstLayer,
         style](engine::PassContext& context) {
            draw(context, viewProjection, peelStyle(style, settings, context.texture(*firstLayer)));
            done();
        }));
}

} // namespace shadowmap
