#include "technique/depth/StandardDepth.h"

namespace shadowmap {

void addSingleDepthPass(const LayerPasses& passes) {
    engine::ResourceHandle& map = passes.map;
    const int layer = passes.layer.layer;
    const DepthPassStyle style = passes.style;
    passes.added.push_back(passes.graph.addPass(
        passes.light.depthPass(layer),
        [&map, layer, style](engine::PassBuilder& builder) {  // setup runs inside addPass
            map = style.inAtlas() ? builder.writePart(map) : builder.write(map, layer);
            builder.setTargets(depthPassTargets(map, layer, style));
            builder.setState(depthPassState(style));
        },
        [draw = passes.draw, done = passes.done, viewProjection = passes.layer.viewProjection, style,
         drawCasters = passes.layer.drawsCasters](engine::PassContext& context) {
            if (drawCasters) draw(context, viewProjection, style);
            done();
        }));
}

void StandardDepth::addLayerPasses(const LayerPasses& passes) const { addSingleDepthPass(passes); }

} // namespace shadowmap
