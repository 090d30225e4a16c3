#pragma once
// SurfaceCapture: what the camera sees, per pixel, as world-space points and normals, so the
// ray-traced truth (RayTracedVisibility.h) can shoot a shadow ray from exactly the surface
// the engine shaded in that pixel.
//
// The GPU renders camera-relative eye-space positions (floats stay small, as in the lit pass:
// modelview V^-1 * M composed in double, then cast); the CPU turns them into world positions
// with V in double, so a scene 10^6 units from the origin keeps its precision.
#include "engine/gl/Program.h"
#include "engine/render/Frame.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace engine {
struct Scene;
class SceneGpu;
}

namespace truth {

// Rows top first (image order, like the PNGs the engine writes); index = row * width + col.
struct SurfaceBuffer {
    int width = 0, height = 0;
    glm::dvec3 cameraPosition{0.0};  // world; the capture's precision scales with distance to it
    engine::FrameCamera camera;      // the view captured: gives each pixel's footprint
    std::vector<glm::dvec3> worldPosition;  // (0,0,0) where not covered
    // Unit geometric (face) normal, turned to face the camera: for single-sided geometry that
    // is its winding normal, for a double-sided back face the flipped one.
    std::vector<glm::dvec3> worldNormal;
    std::vector<std::uint8_t> covered;  // 1 = some surface, 0 = background
    std::vector<std::int32_t> instance; // index into Scene::meshInstances, -1 = background
    // 1 = the surface receives shadows (its node and its primitive both say so).
    std::vector<std::uint8_t> receivesShadows;

    std::size_t pixelCount() const { return static_cast<std::size_t>(width) * height; }
};

// Holds the small GLSL program; needs a current GL 4.5 context for its whole life.
class SurfaceCapture {
public:
    SurfaceCapture();

    // Draws every mesh instance of `scene` (uploaded as `gpu`) as the lit pass does: same
    // culling (material doubleSided -> none, mirroring transforms flip the winding), same
    // depth test and the same material code (MaterialShading.h: texture, sampler, UV set
    // and transform, vertex color, alpha test), so coverage matches the engine's image.
    SurfaceBuffer capture(const engine::Scene& scene, const engine::SceneGpu& gpu,
                          const engine::FrameCamera& camera) const;

private:
    // One program per material variant, compiled on first use.
    const engine::gl::Program& program(unsigned materialFeatures) const;
    mutable std::map<unsigned, engine::gl::Program> programs_;
};

} // namespace truth
