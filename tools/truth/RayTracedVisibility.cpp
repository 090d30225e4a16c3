#include "truth/RayTracedVisibility.h"

#include "truth/TextureAlpha.h"

#include "engine/scene/Scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace truth {

namespace {

std::string embreeErrorName(RTCError error) {
    switch (error) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "error " + std::to_string(static_cast<int>(error));
}

void throwIfEmbreeFailed(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree failed to ") + what + ": " +
                                 embreeErrorName(error));
}

const engine::LightInstance& lightAt(const engine::Scene& scene, int lightInstance) {
    if (lightInstance < 0 || lightInstance >= static_cast<int>(scene.lightInstances.size()))
        throw std::invalid_argument("ray-traced truth: no light instance " +
                                    std::to_string(lightInstance) + " (the scene has " +
                                    std::to_string(scene.lightInstances.size()) + ")");
    return scene.lightInstances[lightInstance];
}

double maxAbs(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

constexpr int kTile = 4;  // 4x4 pixels = one 16-ray packet: neighbours trace coherently

// Embree's occlusion filter for an alpha-tested caster: a hit where the material's alpha
// is below its shadow cutoff is no hit, and the ray goes on through the hole.
void alphaOcclusionFilter(const RTCFilterFunctionNArguments* args) {
    const auto* caster = static_cast<const AlphaTestedPrimitive*>(args->geometryUserPtr);
    for (unsigned lane = 0; lane < args->N; ++lane) {
        if (args->valid[lane] != -1) continue;
        const unsigned triangle = RTCHitN_primID(args->hit, args->N, lane);
        const double u = RTCHitN_u(args->hit, args->N, lane), v = RTCHitN_v(args->hit, args->N, lane);
        if (caster->alphaAt(triangle, u, v) < caster->cutoff()) args->valid[lane] = 0;
    }
}

} // namespace

struct RayTracedVisibility::Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    // The filters' user data; released after the scene (declared first, destroyed last).
    std::vector<std::unique_ptr<AlphaTestedPrimitive>> alphaTested;
    ~Embree() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

RayTracedVisibility::RayTracedVisibility(const engine::Scene& scene)
    : embree_(std::make_unique<Embree>()) {
    if (!scene.worldBounds.empty()) {
        origin_ = scene.worldBounds.center();
        sceneRadius_ = 0.5 * glm::length(scene.worldBounds.extent());
    }
    if (!(sceneRadius_ > 0.0)) sceneRadius_ = 1.0;  // one point, or nothing at all

    embree_->device = rtcNewDevice(nullptr);
    if (!embree_->device)
        throw std::runtime_error("Embree failed to create a device: " +
                                 embreeErrorName(rtcGetDeviceError(nullptr)));
    // An Embree built with back-face culling would let light through the back of every
    // caster; Debian's is not, but the truth must not depend on that silently.
    if (rtcGetDeviceProperty(embree_->device, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED))
        throw std::runtime_error("Embree was built with back-face culling: shadow rays would "
                                 "pass through the back of casters");

    embree_->scene = rtcNewScene(embree_->device);
    // Robust = watertight triangle test: a ray through the shared edge of two triangles of a
    // closed caster must not slip through and show up as a light leak in the truth.
    rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);

    for (const engine::MeshInstance& instance : scene.meshInstances) {
        if (!instance.castShadows) continue;
        for (const engine::Primitive& primitive : scene.meshes.at(instance.mesh).primitives) {
            if (!primitive.castShadows) continue;  // KHR_lights_shadows on the primitive
            const std::size_t vertexCount = primitive.positions.size();
            const std::size_t triangleCount = primitive.indices.size() / 3;
            if (triangleCount == 0) continue;
            for (std::uint32_t index : primitive.indices)
                if (index >= vertexCount)
                    throw std::invalid_argument("ray-traced truth: mesh '" +
                                                scene.meshes[instance.mesh].name +
                                                "' has an index past its vertices");

            RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
                geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                vertexCount));
            auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
                geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t),
                triangleCount));
            if (!vertices || !indices) {
                rtcReleaseGeometry(geometry);
                throwIfEmbreeFailed(embree_->device, "allocate a geometry buffer");
            }
            // World in double, then relative to the bounds' centre: only small numbers are
            // rounded to float.
            for (std::size_t v = 0; v < vertexCount; ++v) {
                const glm::dvec3 world =
                    glm::dvec3(instance.world * glm::dvec4(glm::dvec3(primitive.positions[v]), 1.0));
                const glm::vec3 relative(world - origin_);
                vertices[3 * v + 0] = relative.x;
                vertices[3 * v + 1] = relative.y;
                vertices[3 * v + 2] = relative.z;
            }
            std::copy(primitive.indices.begin(), primitive.indices.begin() + 3 * triangleCount,
                      indices);
            static const engine::Material kDefaultMaterial{};
            const engine::Material& material =
                primitive.material >= 0 ? scene.materials.at(primitive.material) : kDefaultMaterial;
            if (engine::castsAlphaTested(material)) {
                const int image = material.baseColorTexture.image;
                const bool hasImage = image >= 0 && image < static_cast<int>(scene.images.size());
                embree_->alphaTested.push_back(std::make_unique<AlphaTestedPrimitive>(
                    primitive, material, hasImage ? &scene.images[image] : nullptr));
                rtcSetGeometryUserData(geometry, embree_->alphaTested.back().get());
                rtcSetGeometryOccludedFilterFunction(geometry, alphaOcclusionFilter);
            }
            rtcCommitGeometry(geometry);
            rtcAttachGeometry(embree_->scene, geometry);
            rtcReleaseGeometry(geometry);  // the scene holds it now
            triangles_ += triangleCount;
        }
    }
    rtcCommitScene(embree_->scene);
    throwIfEmbreeFailed(embree_->device, "build the caster scene");
}

RayTracedVisibility::~RayTracedVisibility() = default;
RayTracedVisibility::RayTracedVisibility(RayTracedVisibility&&) noexcept = default;
RayTracedVisibility& RayTracedVisibility::operator=(RayTracedVisibility&&) noexcept = default;

// The ray starts off the surface along the geometric normal (towards the camera side, the
// side that was seen), by the largest of:
//  - 1e-4 x scene radius: a margin far above the float rounding of the triangles (stored
//    relative to the bounds' centre, |coordinate| <= radius, so rounding ~6e-8 x radius)
//    yet small against any shadow feature: it only shortens contact shadows by 1e-4 R.
//  - 64 float ulps of the distance to the camera: the captured position was a float
//    camera-relative offset, interpolated by the rasterizer (a few ulps of error).
//  - 64 float ulps of the coordinate relative to Embree's origin: how finely Embree can place
//    the origin at all (only matters for points outside the scene bounds).
double RayTracedVisibility::rayOffset(const glm::dvec3& p, const glm::dvec3& cameraPosition) const {
    constexpr double kUlps = 64.0 * FLT_EPSILON;
    return std::max({1e-4 * sceneRadius_, kUlps * glm::length(p - cameraPosition),
                     kUlps * maxAbs(p - origin_)});
}

std::vector<std::uint8_t> RayTracedVisibility::visibility(const engine::Scene& scene,
                                                          int lightInstance,
                                                          const SurfaceBuffer& surfaces) const {
    const engine::LightInstance& placed = lightAt(scene, lightInstance);
    const bool directional = scene.lights.at(placed.light).type == engine::Light::Type::Directional;
    const glm::dvec3 lightPosition = placed.position();
    const glm::dvec3 towardLight = -placed.direction();  // directional: same for every ray

    const int width = surfaces.width, height = surfaces.height;
    std::vector<std::uint8_t> visible(surfaces.pixelCount(), 0);
    const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
    const int tileCount = tilesX * tilesY;
    std::atomic<int> nextTile{0};

    auto traceTiles = [&] {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        RTCRay16 rays;  // 64-byte aligned by its declaration
        alignas(64) int valid[16];
        std::size_t pixelOf[16];
        for (int tile; (tile = nextTile.fetch_add(1, std::memory_order_relaxed)) < tileCount;) {
            const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
            bool any = false;
            for (int lane = 0; lane < 16; ++lane) {
                valid[lane] = 0;
                const int x = x0 + lane % kTile, y = y0 + lane / kTile;
                if (x >= width || y >= height) continue;
                const std::size_t i = static_cast<std::size_t>(y) * width + x;
                if (!surfaces.covered[i]) continue;
                const glm::dvec3& p = surfaces.worldPosition[i];
                const glm::dvec3 start =
                    p + surfaces.worldNormal[i] * rayOffset(p, surfaces.cameraPosition);
                glm::dvec3 direction = towardLight;
                double tfar = std::numeric_limits<double>::infinity();
                if (!directional) {
                    const double distance = glm::length(lightPosition - start);
                    if (!(distance > 0.0)) {  // the light sits on the surface: call it visible
                        visible[i] = 1;
                        continue;
                    }
                    direction = (lightPosition - start) / distance;
                    // Stop just short of the light: geometry exactly at the light (a lamp
                    // housing) must not count as blocking it.
                    tfar = distance * (1.0 - 1e-6);
                }
                const glm::vec3 origin(start - origin_);
                rays.org_x[lane] = origin.x;
                rays.org_y[lane] = origin.y;
                rays.org_z[lane] = origin.z;
                rays.dir_x[lane] = static_cast<float>(direction.x);
                rays.dir_y[lane] = static_cast<float>(direction.y);
                rays.dir_z[lane] = static_cast<float>(direction.z);
                rays.tnear[lane] = 0.0f;
                rays.tfar[lane] = static_cast<float>(tfar);
                rays.time[lane] = 0.0f;
                rays.mask[lane] = ~0u;
                rays.id[lane] = static_cast<unsigned>(lane);
                rays.flags[lane] = 0;
                pixelOf[lane] = i;
                valid[lane] = -1;
                any = true;
            }
            if (!any) continue;
            rtcOccluded16(valid, embree_->scene, &context, &rays);
            // Embree marks an occluded ray by setting its tfar to -inf.
            for (int lane = 0; lane < 16; ++lane)
                if (valid[lane]) visible[pixelOf[lane]] = rays.tfar[lane] >= 0.0f ? 1 : 0;
        }
    };

    const unsigned threadCount = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (unsigned t = 1; t < threadCount; ++t) threads.emplace_back(traceTiles);
    traceTiles();
    for (std::thread& thread : threads) thread.join();
    return visible;
}

std::vector<std::uint8_t> visibility(const engine::Scene& scene, int lightInstance,
                                     const SurfaceBuffer& surfaces) {
    return RayTracedVisibility(scene).visibility(scene, lightInstance, surfaces);
}

std::vector<std::uint8_t> evaluationSet(const engine::Scene& scene, int lightInstance,
                                        const SurfaceBuffer& surfaces) {
    const engine::LightInstance& placed = lightAt(scene, lightInstance);
    const engine::Light& light = scene.lights.at(placed.light);
    const glm::dvec3 lightPosition = placed.position();
    const glm::dvec3 axis = placed.direction();
    const double cosOuter = std::cos(light.outerConeAngle);

    std::vector<std::uint8_t> inSet(surfaces.pixelCount(), 0);
    for (std::size_t i = 0; i < inSet.size(); ++i) {
        if (!surfaces.covered[i]) continue;
        const int instance = surfaces.instance[i];
        const bool instanceReceives = !(instance >= 0 && instance < static_cast<int>(scene.meshInstances.size())) ||
                                      scene.meshInstances[instance].receiveShadows;
        const bool surfaceReceives = surfaces.receivesShadows.empty() || surfaces.receivesShadows[i];
        if (!instanceReceives || !surfaceReceives)
            continue;  // the engine never shadows it, so its error says nothing
        const glm::dvec3& p = surfaces.worldPosition[i];
        glm::dvec3 towardLight = -axis;
        if (light.type != engine::Light::Type::Directional) {
            const double distance = glm::length(lightPosition - p);
            if (!(distance > 0.0)) continue;
            towardLight = (lightPosition - p) / distance;
            if (light.range > 0.0 && distance > light.range) continue;
            if (light.type == engine::Light::Type::Spot && glm::dot(-towardLight, axis) < cosOuter)
                continue;
        }
        if (glm::dot(surfaces.worldNormal[i], towardLight) <= 0.0) continue;
        inSet[i] = 1;
    }
    return inSet;
}

} // namespace truth
