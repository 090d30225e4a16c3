#pragma once
// Renders one frame of the viewer in the chosen debug view (the pictures of Kilgard's GDC 2000 slides), with the
// same Renderer engine-render uses, and returns it as a picture for the Presenter:
//   shaded      the lit image (Renderer::readColor), what engine-render writes;
//   light       the scene rendered from the selected light (LightCamera.h);
//   depth       its shadow map as gray (engine-render's DepthImage: near dark, far white;
//               a point light's cube as a strip of six faces, +X -X +Y -Y +Z -Z);
//   projected   that gray map projected onto the scene from the light: each visible point
//               shows the map texel its light ray lands on (spot and point lights; a
//               directional light's fitted extents are not reported by the plugin, so its
//               projected view falls back to the comparison view and says so);
//   comparison  the plugin's comparison view (FrameRequest::comparisonSlots): green where
//               r/q agrees with the map (lit), red where the map holds something nearer
//               (shadowed), blue where the offset decided, grey where the map has no say;
//   shadow      the light's shadow term alone (FrameRequest::shadowMaskSlots), gray;
//   truth       the shaded image with acne (false shadow, red) and leak (false light, blue)
//               against Embree shadow rays from every pixel's surface point, weighted by
//               how wrong the shade is; rates of the metrics (docs/metrics.md) in the notes. The ray
//               tracing (~0.1 s) runs only when the camera, size or light changed;
//   cascades    the shaded image tinted by the cascade each pixel's shadow comes from (red,
//               green, blue, yellow from near to far; ShadowView::cascadeSplits), the split
//               distances in the notes (a light without cascades: the shaded image, said).
#include "Image.h"
#include "ViewerState.h"

#include "engine/render/Renderer.h"

#include <memory>
#include <string>
#include <vector>

namespace truth {
class SurfaceCapture;
class RayTracedVisibility;
struct SurfaceBuffer;
}

namespace engine_view {

struct ViewFrame {
    Image image;
    engine::FrameResult frame;       // the frame that was rendered (timings, plugin stats)
    std::vector<std::string> notes;  // what the picture shows, for the overlay
};

class DebugViews {
public:
    // GL context current; the renderer has `scene` set. Both outlive this object.
    DebugViews(engine::Renderer& renderer, const engine::Scene& scene);
    ~DebugViews();

    // `light`: the selected light (null: none, every view is then the shaded one);
    // `shadow`: its shadow view of the previous frame (for the light's L), or null.
    ViewFrame render(DebugView view, const ViewedLight* light, const engine::ShadowView* shadow,
                     const engine::FrameCamera& camera);

private:
    engine::FrameResult renderFrame(engine::FrameRequest request);
    const truth::SurfaceBuffer& surfaces(const engine::FrameCamera& camera);
    ViewFrame depthMap(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame projected(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame acneLeak(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame cascades(const ViewedLight& light, const engine::FrameCamera& camera);

    engine::Renderer& renderer_;
    const engine::Scene& scene_;
    std::unique_ptr<truth::SurfaceCapture> capture_;          // made on first use
    std::unique_ptr<truth::RayTracedVisibility> visibility_;  // made on first use
    struct Cache;  // surfaces and truth of the last camera (DebugViews.cpp)
    std::unique_ptr<Cache> cache_;
};

} // namespace engine_view
