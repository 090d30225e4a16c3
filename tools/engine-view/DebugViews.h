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
//   penumbra    the shaded image with the pixels the light partly lights (its 8-bit shadow
//               term strictly between 0 and 255, read as the shadow view reads it) in
//               magenta and the rest dimmed, so a penumbra's width and reach stand out
//               (paintPenumbra); the count in the notes. The soft truth's penumbra is not
//               drawn beside it: it costs 64 shadow rays per pixel (~5 s a 720p frame on
//               two cores), too slow to follow the keys; the bench scores it;
//   truth       the shaded image with acne (false shadow, red) and leak (false light, blue)
//               against Embree shadow rays from every pixel's surface point, weighted by
//               how wrong the shade is; rates of the metrics (docs/metrics.md) in the notes. The ray
//               tracing (~0.1 s) runs only when the camera, size or light changed;
//   cascades    the shaded image tinted by the cascade each pixel's shadow comes from (red,
//               green, blue, yellow from near to far; ShadowView::cascadeSplits), the split
//               distances in the notes (a light without cascades: the shaded image, said);
//   density     the heat map of the light's map texel size on screen, m, at every pixel
//               (truth/TexelDensityImage.h, engine-render --texel-density's picture): green
//               one texel per pixel, blue finer, yellow and red coarser, grey no value; the
//               scale and m's mean/p95 in the notes. Computed on the CPU from a surface
//               capture, again only when the camera, the scene or the light's map moved.
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

// 0 < term < 255: the light neither fully lights nor fully shadows the pixel.
constexpr bool inPenumbra(std::uint8_t shadowTerm) { return shadowTerm > 0 && shadowTerm < 255; }
// The penumbra view's picture (DebugView::Penumbra) from the shaded image and the light's
// 8-bit shadow term of the same frame: the pixels inPenumbra tinted magenta, the rest
// dimmed. Returns how many pixels are in the penumbra.
std::size_t paintPenumbra(Image& shaded, const std::vector<std::uint8_t>& shadowTerm);

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
    // Renders a frame with the light's shadow term; out.frame is that frame and out.image
    // its shaded picture. Returns the term (8-bit gray, 255 lit), or nothing (and a note in
    // out) when no plugin provides one.
    std::vector<std::uint8_t> renderShadowTerm(const ViewedLight& light, const engine::FrameCamera& camera,
                                               ViewFrame& out);
    ViewFrame comparison(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame shadowTerm(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame penumbra(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame depthMap(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame projected(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame acneLeak(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame cascades(const ViewedLight& light, const engine::FrameCamera& camera);
    ViewFrame texelDensity(const ViewedLight& light, const engine::FrameCamera& camera);

    engine::Renderer& renderer_;
    const engine::Scene& scene_;
    std::unique_ptr<truth::SurfaceCapture> capture_;          // made on first use
    std::unique_ptr<truth::RayTracedVisibility> visibility_;  // made on first use
    struct Cache;  // surfaces, truth and texel density of the last camera (DebugViews.cpp)
    std::unique_ptr<Cache> cache_;
};

} // namespace engine_view
