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
#include <numbers>
#include <numeric>
#include <sstream>
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

// A unit vector's two perpendicular unit vectors, continuous except where n.z changes sign
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited"): no branch on a threshold
// that would let the basis jump between neighbouring pixels.
void orthonormalBasis(const glm::dvec3& n, glm::dvec3& e1, glm::dvec3& e2) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    e1 = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    e2 = glm::dvec3(b, sign + n.y * n.y * a, -n.y);
}

// Where the shadow rays of one surface point go: to a point on a positional light (its
// centre, or a point of its disk of `size` = radius facing the ray start, stopping just short
// of it), or along a directional light's direction (its axis, or a direction of its cone of
// `size` = full apex angle). The point on the extent is given on the unit disk, (0,0) = the
// centre: a disk point scales to the light's disk; a cone direction at disk radius rho and
// angle phi leans by alpha, 1 - cos(alpha) = rho^2 (1 - cos(half angle)), towards phi, which
// maps a uniform disk to directions uniform in solid angle over the cone's cap.
class ShadowRayAim {
public:
    ShadowRayAim(const engine::Scene& scene, const engine::LightInstance& placed, double size = 0.0)
        : directional_(scene.lights.at(placed.light).type == engine::Light::Type::Directional),
          lightPosition_(placed.position()), towardLight_(-placed.direction()) {
        if (!directional_) {
            radius_ = size;
            return;
        }
        // 1 - cos(half) as 2 sin^2(half / 2): no cancellation for the sun's 0.0047 rad.
        const double sinQuarter = std::sin(0.25 * size);
        oneMinusCosHalf_ = 2.0 * sinQuarter * sinQuarter;
        orthonormalBasis(towardLight_, coneE1_, coneE2_);
    }

    // False when the start sits on the light itself: no ray, the light counts as visible.
    bool aim(const glm::dvec3& start, const glm::dvec2& onLight, glm::dvec3& direction,
             double& tfar) const {
        tfar = std::numeric_limits<double>::infinity();
        if (directional_) {
            direction = coneDirection(onLight);
            return true;
        }
        glm::dvec3 target = lightPosition_;
        if (radius_ > 0.0) {
            const double centreDistance = glm::length(lightPosition_ - start);
            if (!(centreDistance > 0.0)) return false;
            glm::dvec3 e1, e2;
            orthonormalBasis((lightPosition_ - start) / centreDistance, e1, e2);
            target += radius_ * (onLight.x * e1 + onLight.y * e2);
        }
        const double distance = glm::length(target - start);
        if (!(distance > 0.0)) return false;
        direction = (target - start) / distance;
        // Geometry exactly at the light (a lamp housing) must not count as blocking it.
        tfar = distance * (1.0 - 1e-6);
        return true;
    }

private:
    glm::dvec3 coneDirection(const glm::dvec2& onLight) const {
        const double rho2 = glm::dot(onLight, onLight);
        if (!(oneMinusCosHalf_ > 0.0) || rho2 == 0.0) return towardLight_;
        const double oneMinusCos = rho2 * oneMinusCosHalf_;
        const double sinAlpha = std::sqrt(oneMinusCos * (2.0 - oneMinusCos));
        const glm::dvec2 phi = onLight / std::sqrt(rho2);  // (cos phi, sin phi)
        return (1.0 - oneMinusCos) * towardLight_ + sinAlpha * (phi.x * coneE1_ + phi.y * coneE2_);
    }

    bool directional_;
    glm::dvec3 lightPosition_, towardLight_;
    double radius_ = 0.0;           // positional lights
    double oneMinusCosHalf_ = 0.0;  // directional lights: the cone's half angle, and
    glm::dvec3 coneE1_{0.0}, coneE2_{0.0};  // its basis around towardLight_
};

// One shadow ray's start, or the verdict when no ray is needed, and the point of the light's
// extent it aims at (unit disk; the centre for a point light).
struct RayStart {
    enum class Kind { None, Visible, Trace } kind = Kind::None;
    glm::dvec3 start{0.0};
    glm::dvec2 onLight{0.0};
};

// Where a surface point's shadow rays start: pushed off along its normal by rayOffset.
glm::dvec3 offSurface(const RayTracedVisibility& tracer, const glm::dvec3& p, const glm::dvec3& n,
                      const glm::dvec3& cameraPosition) {
    return p + n * tracer.rayOffset(p, cameraPosition);
}

// A lane that traces nothing. rtcOccluded16 on a CPU without 16-wide kernels (AVX2) goes
// through Embree's ray stream filter, which ignores the valid mask and takes every lane with
// tnear <= tfar as active: an idle lane left uninitialised is traced (and fails the
// asserts of Debian's Embree), so it gets a finite ray with tnear > tfar.
void idleLane(RTCRay16& rays, int lane) {
    rays.org_x[lane] = rays.org_y[lane] = rays.org_z[lane] = 0.0f;
    rays.dir_x[lane] = rays.dir_y[lane] = 0.0f;
    rays.dir_z[lane] = 1.0f;
    rays.tnear[lane] = 1.0f;
    rays.tfar[lane] = 0.0f;
    rays.time[lane] = 0.0f;
    rays.mask[lane] = 0u;
    rays.id[lane] = static_cast<unsigned>(lane);
    rays.flags[lane] = 0;
}

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
                idleLane(rays, lane);
                const RayStart ray = startOf(packet, lane);
                if (ray.kind == RayStart::Kind::None) continue;
                glm::dvec3 direction;
                double tfar = 0.0;
                if (ray.kind == RayStart::Kind::Visible ||
                    !aim.aim(ray.start, ray.onLight, direction, tfar)) {
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
                rays.mask[lane] = ~0u;
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

// The square's point (a, b) in [0,1)^2 on the unit disk by Shirley and Chiu's concentric map
// ("A Low Distortion Map Between Disk and Square", 1997): area-preserving, so equal cells
// of the square are equal-area strata of the disk, and compact ones.
glm::dvec2 concentricDisk(double a, double b) {
    constexpr double kQuarterPi = 0.25 * std::numbers::pi;
    const double x = 2.0 * a - 1.0, y = 2.0 * b - 1.0;
    if (x == 0.0 && y == 0.0) return glm::dvec2(0.0);
    const bool nearXAxis = std::abs(x) > std::abs(y);
    const double r = nearXAxis ? x : y;
    const double phi = nearXAxis ? kQuarterPi * (y / x) : 2.0 * kQuarterPi - kQuarterPi * (x / y);
    return r * glm::dvec2(std::cos(phi), std::sin(phi));
}

// A pixel's offset of the sample pattern, in [0,1)^2: splitmix64's finaliser of its index,
// the high and low 32 bits. Deterministic, and unrelated between neighbours.
glm::dvec2 patternRotation(std::size_t pixel) {
    std::uint64_t z = static_cast<std::uint64_t>(pixel) + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    constexpr double kTwoToMinus32 = 1.0 / 4294967296.0;
    return {static_cast<double>(z >> 32) * kTwoToMinus32,
            static_cast<double>(z & 0xffffffffull) * kTwoToMinus32};
}

// The unit-disk point of cell (cellX, cellY) of the kLightSamplesPerAxis^2 strata: the cell's
// centre shifted by `rotation` and wrapped into the unit square (Cranley-Patterson), which
// keeps one sample per cell.
glm::dvec2 lightSample(int cellX, int cellY, const glm::dvec2& rotation) {
    auto wrapped = [](double v) { return v - std::floor(v); };
    constexpr double kCell = 1.0 / kLightSamplesPerAxis;
    return concentricDisk(wrapped((cellX + 0.5) * kCell + rotation.x),
                          wrapped((cellY + 0.5) * kCell + rotation.y));
}

// The size of `extent` that applies to the light's type: its radius, or its angular diameter.
double appliedSize(const engine::Light& light, int lightInstance, const LightExtent& extent) {
    const bool directional = light.type == engine::Light::Type::Directional;
    const double size = directional ? extent.angularDiameter : extent.radius;
    if (!std::isfinite(size) || size < 0.0) {
        std::ostringstream message;
        message << "ray-traced truth: light instance " << lightInstance << " ('" << light.name
                << "'): " << (directional ? "angular diameter " : "radius ") << size
                << " is not a size (finite, >= 0)";
        throw std::invalid_argument(message.str());
    }
    return size;
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
            return RayStart{RayStart::Kind::Trace, offSurface(*this, surfaces.worldPosition[i],
                                                              surfaces.worldNormal[i],
                                                              surfaces.cameraPosition)};
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
            return RayStart{RayStart::Kind::Trace, offSurface(*this, p, n, surfaces.cameraPosition)};
        },
        [&](std::size_t i, int, bool lit) {
            if (lit) ++litSamples[i];  // a pixel is one packet, traced by one thread
        });
    std::vector<float> fraction(surfaces.pixelCount(), 0.0f);
    for (std::size_t i = 0; i < fraction.size(); ++i)
        fraction[i] = static_cast<float>(litSamples[i]) / (kTile * kTile);
    return fraction;
}

std::vector<float> RayTracedVisibility::visibleFraction(const engine::Scene& scene, int lightInstance,
                                                        const SurfaceBuffer& surfaces,
                                                        const LightExtent& extent) const {
    const engine::LightInstance& placed = lightAt(scene, lightInstance);
    const double size = appliedSize(scene.lights.at(placed.light), lightInstance, extent);
    if (size == 0.0) {
        const std::vector<std::uint8_t> visible = visibility(scene, lightInstance, surfaces);
        return std::vector<float>(visible.begin(), visible.end());  // 0 -> 0.0f, 1 -> 1.0f
    }
    const ShadowRayAim aim(scene, placed, size);
    // One packet = a kTile x kTile block of one pixel's cells: neighbouring cells aim at
    // neighbouring parts of the light, so a packet's rays stay coherent.
    static_assert(kLightSamplesPerAxis % kTile == 0, "a pixel's samples fill whole packets");
    constexpr int kBlocksPerAxis = kLightSamplesPerAxis / kTile;
    constexpr int kPacketsPerPixel = kBlocksPerAxis * kBlocksPerAxis;
    std::vector<std::uint8_t> litSamples(surfaces.pixelCount() * kPacketsPerPixel, 0);
    traceShadowPackets(
        embree_->scene, origin_, aim, litSamples.size(),
        [&](std::size_t packet, int lane) {
            const std::size_t i = packet / kPacketsPerPixel;
            if (!surfaces.covered[i]) return RayStart{};
            const int block = static_cast<int>(packet % kPacketsPerPixel);
            const int cellX = block % kBlocksPerAxis * kTile + lane % kTile;
            const int cellY = block / kBlocksPerAxis * kTile + lane / kTile;
            return RayStart{RayStart::Kind::Trace,
                            offSurface(*this, surfaces.worldPosition[i], surfaces.worldNormal[i],
                                       surfaces.cameraPosition),
                            lightSample(cellX, cellY, patternRotation(i))};
        },
        [&](std::size_t packet, int, bool lit) {
            if (lit) ++litSamples[packet];  // a packet is traced by one thread
        });
    std::vector<float> fraction(surfaces.pixelCount(), 0.0f);
    for (std::size_t i = 0; i < fraction.size(); ++i) {
        const auto pixelPackets = litSamples.begin() + static_cast<std::ptrdiff_t>(i * kPacketsPerPixel);
        const int lit = std::accumulate(pixelPackets, pixelPackets + kPacketsPerPixel, 0);
        fraction[i] = static_cast<float>(lit) / (kLightSamplesPerAxis * kLightSamplesPerAxis);
    }
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
