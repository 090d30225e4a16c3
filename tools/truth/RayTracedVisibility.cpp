#include "truth/RayTracedVisibility.h"

#include "truth/TextureAlpha.h"

#include "engine/scene/Deform.h"
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

constexpr int kTile = 4;  // 4x4 rays = one 16-ray packet

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
        const std::vector<engine::Primitive>& primitives = scene.meshes.at(instance.mesh).primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const engine::Primitive& primitive = primitives[p];
            if (!primitive.castShadows) continue;  // KHR_lights_shadows on the primitive
            // A skinned or morphed instance: the posed floats the passes draw (Deform.h).
            const engine::DeformedPrimitive* posed =
                instance.deformed ? &instance.deformed->primitives.at(p) : nullptr;
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
                const glm::dvec3 object = posed ? instance.deformed->origin + glm::dvec3(posed->positions[v])
                                                : glm::dvec3(primitive.positions[v]);
                const glm::dvec3 world = glm::dvec3(instance.world * glm::dvec4(object, 1.0));
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

namespace {

// Where the shadow ray of one surface point goes: toward a directional light's fixed
// direction, or to a positional light, stopping just short of it.
class ShadowRayAim {
public:
    ShadowRayAim(const engine::Scene& scene, const engine::LightInstance& placed)
        : directional_(scene.lights.at(placed.light).type == engine::Light::Type::Directional),
          lightPosition_(placed.position()), towardLight_(-placed.direction()) {}

    // False when the start sits on the light itself: no ray, the light counts as visible.
    bool aim(const glm::dvec3& start, glm::dvec3& direction, double& tfar) const {
        direction = towardLight_;
        tfar = std::numeric_limits<double>::infinity();
        if (directional_) return true;
        const double distance = glm::length(lightPosition_ - start);
        if (!(distance > 0.0)) return false;
        direction = (lightPosition_ - start) / distance;
        // Geometry exactly at the light (a lamp housing) must not count as blocking it.
        tfar = distance * (1.0 - 1e-6);
        return true;
    }

private:
    bool directional_;
    glm::dvec3 lightPosition_, towardLight_;
};

// One shadow ray's start, or the verdict when no ray is needed.
struct RayStart {
    enum class Kind { None, Visible, Trace } kind = Kind::None;
    glm::dvec3 start{0.0};
};

// Traces `packetCount` packets of 16 shadow rays on all hardware threads. `startOf(packet,
// lane)` gives each ray's start; `record(packet, lane, visible)` receives every lane that
// was not None, on the thread that traced its packet.
template <class StartOf, class Record>
void traceShadowPackets(RTCScene scene, const glm::dvec3& embreeOrigin, const ShadowRayAim& aim,
                        std::size_t packetCount, StartOf startOf, Record record) {
    std::atomic<std::size_t> nextPacket{0};
    auto tracePackets = [&] {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        RTCRay16 rays;  // 64-byte aligned by its declaration
        alignas(64) int valid[16];
        for (std::size_t packet; (packet = nextPacket.fetch_add(1, std::memory_order_relaxed)) < packetCount;) {
            bool any = false;
            for (int lane = 0; lane < 16; ++lane) {
                valid[lane] = 0;
                const RayStart ray = startOf(packet, lane);
                if (ray.kind == RayStart::Kind::None) continue;
                glm::dvec3 direction;
                double tfar = 0.0;
                if (ray.kind == RayStart::Kind::Visible || !aim.aim(ray.start, direction, tfar)) {
                    record(packet, lane, true);
                    continue;
                }
                const glm::vec3 origin(ray.start - embreeOrigin);
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
                valid[lane] = -1;
                any = true;
            }
            if (!any) continue;
            rtcOccluded16(valid, scene, &context, &rays);
            // Embree marks an occluded ray by setting its tfar to -inf.
            for (int lane = 0; lane < 16; ++lane)
                if (valid[lane]) record(packet, lane, rays.tfar[lane] >= 0.0f);
        }
    };
    const unsigned threadCount = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (unsigned t = 1; t < threadCount; ++t) threads.emplace_back(tracePackets);
    tracePackets();
    for (std::thread& thread : threads) thread.join();
}

// The world point where the camera ray through window position (x, y) (pixels, top row
// first, pixel centres at +0.5) meets the plane through `p` with normal `n`; `p` itself when
// the ray runs along the plane.
glm::dvec3 footprintPoint(const engine::FrameCamera& camera, const glm::dmat4& clipToEye,
                          double x, double y, const glm::dvec3& p, const glm::dvec3& n) {
    const double ndcX = 2.0 * x / camera.width - 1.0;
    const double ndcY = 1.0 - 2.0 * y / camera.height;
    auto worldAt = [&](double ndcZ) {
        const glm::dvec4 eye = clipToEye * glm::dvec4(ndcX, ndcY, ndcZ, 1.0);
        return glm::dvec3(camera.eyeToWorld * (eye / eye.w));
    };
    const glm::dvec3 near = worldAt(-1.0), far = worldAt(1.0);
    const glm::dvec3 along = far - near;
    const double denominator = glm::dot(along, n);
    if (std::abs(denominator) <= 1e-12 * glm::length(along)) return p;
    return near + along * (glm::dot(p - near, n) / denominator);
}

} // namespace

std::vector<std::uint8_t> RayTracedVisibility::visibility(const engine::Scene& scene,
                                                          int lightInstance,
                                                          const SurfaceBuffer& surfaces) const {
    const ShadowRayAim aim(scene, lightAt(scene, lightInstance));
    const int width = surfaces.width, height = surfaces.height;
    std::vector<std::uint8_t> visible(surfaces.pixelCount(), 0);
    // One packet = a 4x4 pixel tile, so neighbours trace coherently.
    const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
    auto pixelOf = [&](std::size_t tile, int lane) -> std::ptrdiff_t {
        const int x = static_cast<int>(tile % tilesX) * kTile + lane % kTile;
        const int y = static_cast<int>(tile / tilesX) * kTile + lane / kTile;
        if (x >= width || y >= height) return -1;
        return static_cast<std::ptrdiff_t>(y) * width + x;
    };
    traceShadowPackets(
        embree_->scene, origin_, aim, static_cast<std::size_t>(tilesX) * tilesY,
        [&](std::size_t tile, int lane) {
            const std::ptrdiff_t i = pixelOf(tile, lane);
            if (i < 0 || !surfaces.covered[i]) return RayStart{};
            const glm::dvec3& p = surfaces.worldPosition[i];
            return RayStart{RayStart::Kind::Trace,
                            p + surfaces.worldNormal[i] * rayOffset(p, surfaces.cameraPosition)};
        },
        [&](std::size_t tile, int lane, bool lit) { visible[pixelOf(tile, lane)] = lit ? 1 : 0; });
    return visible;
}

std::vector<float> RayTracedVisibility::litFraction(const engine::Scene& scene, int lightInstance,
                                                    const SurfaceBuffer& surfaces) const {
    const ShadowRayAim aim(scene, lightAt(scene, lightInstance));
    const engine::FrameCamera& camera = surfaces.camera;
    if (camera.width != surfaces.width || camera.height != surfaces.height)
        throw std::invalid_argument("ray-traced truth: the surface buffer's camera is " +
                                    std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                                    ", its pixels " + std::to_string(surfaces.width) + "x" +
                                    std::to_string(surfaces.height));
    const glm::dmat4 clipToEye = glm::inverse(camera.projection);
    // One packet = one pixel's 4x4 stratified samples (sample centres at (k + 0.5) / 4).
    std::vector<std::uint8_t> litSamples(surfaces.pixelCount(), 0);
    traceShadowPackets(
        embree_->scene, origin_, aim, surfaces.pixelCount(),
        [&](std::size_t i, int lane) {
            if (!surfaces.covered[i]) return RayStart{};
            const double x = static_cast<double>(i % surfaces.width) + (lane % kTile + 0.5) / kTile;
            const double y = static_cast<double>(i / surfaces.width) + (lane / kTile + 0.5) / kTile;
            const glm::dvec3& n = surfaces.worldNormal[i];
            const glm::dvec3 p = footprintPoint(camera, clipToEye, x, y, surfaces.worldPosition[i], n);
            return RayStart{RayStart::Kind::Trace, p + n * rayOffset(p, surfaces.cameraPosition)};
        },
        [&](std::size_t i, int, bool lit) {
            if (lit) ++litSamples[i];  // a pixel is one packet, traced by one thread
        });
    std::vector<float> fraction(surfaces.pixelCount(), 0.0f);
    for (std::size_t i = 0; i < fraction.size(); ++i)
        fraction[i] = static_cast<float>(litSamples[i]) / (kTile * kTile);
    return fraction;
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
