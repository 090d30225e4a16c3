#pragma once
// Stenciled shadow volumes (Everitt and Kilgard 2002) for the lights whose variant is volume:
// the camera's depth (drawn once per frame), then per light its casters' volumes counted in
// the stencil buffer with z-fail (Carmack's reverse: only the volume faces behind the nearest
// surface count, so a camera standing inside a volume needs no special case), extruded to
// infinity and depth-clamped, and the count resolved into the light's visibility texture
// (1 where it is 0). Exact at every pixel centre, whatever the light's type or distance.
//
// The volumes are made on the CPU from each mesh's edge adjacency (math/ShadowVolumeMesh.h),
// in camera-relative eye space composed in double, or for closed meshes optionally in a
// geometry shader (GpuVolumeExtrusion.h).
#include "math/CameraInVolume.h"
#include "math/ShadowVolumeMesh.h"
#include "plugin/DepthRenderer.h"
#include "plugin/GpuVolumeExtrusion.h"
#include "plugin/LightShadow.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/Framebuffer.h"
#include "engine/gl/Program.h"
#include "engine/gl/Texture.h"
#include "engine/gl/VertexArray.h"
#include "engine/render/Frame.h"
#include "engine/scene/ScreenFootprint.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace shadowmap {

struct VolumeCounts {
    std::uint64_t casters = 0;          // mesh instances that cast a volume
    std::uint64_t volumeTriangles = 0;  // triangles drawn into the stencil buffer
    std::uint64_t silhouetteEdges = 0;
    std::uint64_t capTriangles = 0;
    std::uint64_t gpuCasters = 0;       // of `casters`, those extruded in the geometry shader
    std::uint64_t zPassCasters = 0;     // of `casters`, those counted with z-pass (no caps)
};

class VolumeRenderer {
public:
    // onGpu: closed, undeformed casters' volumes are extruded in a geometry shader
    // (GpuVolumeExtrusion.h); the rest on the CPU.
    // zPass: volumes that cannot hold the camera are counted with z-pass, without caps (else
    // every volume with z-fail).
    VolumeRenderer(bool onGpu, bool zPass);

    // Each mesh's edge adjacency, from its casting primitives, once per scene (alpha-tested
    // ones left out: a light with such casters gets a map instead, LightResolver.h).
    void prepareScene(const engine::Scene& scene);

    // Inside the light's volume pass: makes light.visibility for this frame's camera, and with
    // `stencilCounts` the count of volumes at each pixel into it (R8, the camera's size).
    VolumeCounts render(const engine::Frame& frame, engine::PassContext& context, DepthRenderer& depth,
                        const LightShadow& light, const engine::gl::Texture* stencilCounts = nullptr);

private:
    void ensureTargets(int width, int height);
    void drawCameraDepth(const engine::Frame& frame, engine::PassContext& context, DepthRenderer& depth);
    // The volumes of every caster, in eye space, into scratch_.
    VolumeCounts buildVolumes(const engine::Frame& frame, const LightShadow& light);
    void upload();
    void writeStencilCounts(const engine::gl::Texture& target, const engine::PixelRect& footprint);

    std::vector<ShadowVolumeMesh> meshes_;  // per Scene::meshes; empty ones cast nothing
    engine::gl::Program volumeProgram_, resolveProgram_;
    engine::gl::Program countProgram_;  // compiled when a viewer first asks for the counts
    engine::gl::Framebuffer countFramebuffer_;
    engine::gl::Texture depthStencil_;
    engine::gl::Framebuffer framebuffer_;
    // The frame whose camera depth depthStencil_ holds (all volume lights of a frame share it).
    std::uint64_t depthFrame_ = std::numeric_limits<std::uint64_t>::max();
    engine::gl::Buffer points_;
    std::size_t pointCapacity_ = 0;
    engine::gl::VertexArray pointArray_, empty_;
    std::vector<glm::vec4> scratch_;       // z-fail volumes, then from zPassFirst_ z-pass ones
    std::vector<glm::vec4> zPassScratch_;  // the z-pass ones while they are made
    std::size_t zPassFirst_ = 0;
    bool zPass_ = true;
    std::unique_ptr<GpuVolumeExtrusion> gpu_;  // volume_extrusion "gpu"
    std::vector<const engine::MeshInstance*> gpuCasters_;  // this light's casters gpu_ draws
};

} // namespace shadowmap
