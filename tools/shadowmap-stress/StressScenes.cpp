#include "StressScenes.h"

#include "engine/scene/Shapes.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace stress {

namespace {

constexpr double kDegree = 0.017453292519943295;

struct Box {
    const char* name;
    glm::dvec3 min, max;  // unit scale, before the offset
};

// The floor slab and what stands on it (unit scale). The floor is 16 x 16, 0.3 thick.
const Box kFloor{"floor", {-8, -0.3, -8}, {8, 0, 8}};
const Box kBlock{"block", {-3, 0, -2}, {-1.5, 1.5, -0.5}};       // in contact with the floor
const Box kTower{"tower", {1, 0, -3}, {2, 3, -2}};                // in contact, tall
const Box kHover{"hover", {-0.5, 1.0, 1.0}, {0.5, 2.0, 2.0}};    // 1 unit above the floor
const Box kPlank{"plank", {0.5, 0.8, 0.5}, {3.5, 0.83, 1.5}};    // 3 cm thin, 0.8 up
const Box kShell{"shell", {-2, 0.4, 1.8}, {0, 2.4, 3.8}};        // hollow: the light inside

const glm::dvec3 kTarget(0, 0, 0);  // what lights aim at: the floor's centre
const glm::dvec3 kCameraEye(7, 7, 11), kCameraTarget(0, 0.5, 0);
constexpr double kCameraFov = 0.75, kCameraNear = 0.1, kCameraFar = 60.0;
constexpr double kSpotDistance = 14.0, kPointDistance = 8.0, kSpotCone = 0.6;
constexpr double kAzimuth = 40.0 * kDegree;  // light from -x,-z: shadows fall toward the camera

// The fence of the masked layouts, in the plane of its node (x in [-3, 3], y in [0, 2]):
// a 96 x 32 texel mask, 6.25 cm per texel at unit scale. Slats at columns 6k+1 .. 6k+3 from
// the top row to row 29 (the two bottom rows open), rails over rows [6, 9) and [21, 24).
constexpr double kFenceWidth = 6.0, kFenceHeight = 2.0;
constexpr int kFenceColumns = 96, kFenceRows = 32;
struct TexelRect {
    int column0, column1, row0, row1;  // ends exclusive, row 0 = top
};
std::vector<TexelRect> fenceRects() {
    std::vector<TexelRect> rects;
    for (int column = 1; column < kFenceColumns; column += 6) rects.push_back({column, column + 3, 0, 30});
    rects.push_back({0, kFenceColumns, 6, 9});
    rects.push_back({0, kFenceColumns, 21, 24});
    return rects;
}
bool fenceOpaque(int column, int row) {
    for (const TexelRect& r : fenceRects())
        if (column >= r.column0 && column < r.column1 && row >= r.row0 && row < r.row1) return true;
    return false;
}
const glm::u8vec3 kFenceColor(196, 150, 104);  // sRGB
constexpr int kClampToEdge = 0x812F;           // GL_CLAMP_TO_EDGE

// Rigid transform at `position` whose -Z looks at `target`; straight up or down takes Z
// as the up vector instead of Y.
glm::dmat4 placeLooking(const glm::dvec3& position, const glm::dvec3& target) {
    const glm::dvec3 forward = glm::normalize(target - position);
    const glm::dvec3 up = std::abs(forward.y) > 0.99 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    return glm::inverse(glm::lookAt(position, target, up));
}


class Builder {
public:
    Builder(double scale, const glm::dvec3& offset, bool bake, bool skinned)
        : scale_(scale), offset_(offset), bake_(bake), skinned_(skinned) {
        engine::Material grey;
        grey.name = "grey";
        grey.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
        grey.metallicFactor = 0.0f;
        grey.roughnessFactor = 0.8f;
        scene_.materials.push_back(grey);
        scene_.sourcePath = "shadowmap-stress generated scene";
    }

    // Unit-scale point -> world.
    glm::dvec3 world(const glm::dvec3& p) const { return p * scale_ + offset_; }

    // Every box added after this is turned by `degrees` about a horizontal axis through the
    // origin that is neither X nor Z, so that no face stays vertical (at unit scale, before
    // the offset).
    void tiltBoxes(double degrees) {
        tilt_ = glm::rotate(glm::dmat4(1.0), degrees * kDegree, glm::normalize(glm::dvec3(1, 0, 0.6)));
    }

    void addBox(const Box& box, bool receivesShadows = true) {
        engine::Mesh mesh;
        mesh.name = box.name;
        mesh.primitives.push_back(engine::boxPrimitive((box.max - box.min) * scale_));
        mesh.closed = true;
        addMesh(std::move(mesh), glm::translate(glm::dmat4(1.0), (box.min + box.max) * 0.5 * scale_), receivesShadows);
    }

    // The masked fence (one textured quad, alpha-tested) or its opaque twin (a quad per
    // slat and rail), standing on the floor at its centre, its +Z facing the light's azimuth.
    void addFence(bool masked) {
        const double s = scale_;
        engine::Material material;
        material.metallicFactor = 0.0f;
        material.roughnessFactor = 0.8f;
        material.doubleSided = true;
        engine::Mesh mesh;
        mesh.name = masked ? "masked_fence" : "opaque_fence";
        if (masked) {
            scene_.images.push_back(engine::binaryAlphaImage("fence_mask", kFenceColumns, kFenceRows, kFenceColor,
                                                             fenceOpaque));
            material.name = "fence_masked";
            material.alphaMode = engine::AlphaMode::Mask;
            material.alphaCutoff = 0.5f;
            material.baseColorTexture.image = static_cast<int>(scene_.images.size()) - 1;
            material.baseColorTexture.sampler.wrapS = kClampToEdge;
            material.baseColorTexture.sampler.wrapT = kClampToEdge;
            // Sampler filters: the defaults, LINEAR magnification, LINEAR_MIPMAP_LINEAR.
        } else {
            material.name = "fence_opaque";
            material.baseColorFactor = glm::vec4(glm::pow(glm::vec3(kFenceColor) / 255.0f, glm::vec3(2.2f)), 1.0f);
        }
        scene_.materials.push_back(material);
        const int materialIndex = static_cast<int>(scene_.materials.size()) - 1;
        const auto corner = [&](int column, int row) {  // texel corner -> fence plane
            return glm::dvec2((-0.5 + double(column) / kFenceColumns) * kFenceWidth * s,
                              (1.0 - double(row) / kFenceRows) * kFenceHeight * s);
        };
        if (masked) {
            mesh.primitives.push_back(
                engine::texturedQuadPrimitive(corner(0, kFenceRows), corner(kFenceColumns, 0), materialIndex));
        } else {
            // Rails overlap the slats: the union is the mask and has no T-junction cracks.
            engine::Primitive fence;
            for (const TexelRect& r : fenceRects())
                engine::appendPrimitive(
                    fence, engine::texturedQuadPrimitive(
                               corner(r.column0, r.row1), corner(r.column1, r.row0), materialIndex,
                               {float(r.column0) / kFenceColumns, float(r.row0) / kFenceRows},
                               {float(r.column1) / kFenceColumns, float(r.row1) / kFenceRows}));
            fence.material = materialIndex;
            mesh.primitives.push_back(std::move(fence));
        }
        // +Z turned to (-sin azimuth, 0, -cos azimuth): toward the light.
        addMesh(std::move(mesh), glm::rotate(glm::dmat4(1.0), glm::pi<double>() + kAzimuth, glm::dvec3(0, 1, 0)));
    }

    // `local` places the mesh (already at this scale) about the origin; the tilt and the
    // offset are applied on top, through the node or baked into the positions.
    void addMesh(engine::Mesh mesh, const glm::dmat4& local, bool receivesShadows = true) {
        const glm::dmat4 place = glm::translate(glm::dmat4(1.0), offset_) * tilt_ * local;
        if (bake_) {  // world positions rounded to float, as such a file stores them
            for (engine::Primitive& primitive : mesh.primitives) {
                primitive.bounds = {};
                for (glm::vec3& p : primitive.positions) {
                    p = glm::vec3(place * glm::dvec4(glm::dvec3(p), 1.0));
                    primitive.bounds.extend(glm::dvec3(p));
                }
                for (glm::vec3& n : primitive.normals)
                    n = glm::vec3(glm::normalize(glm::dmat3(place) * glm::dvec3(n)));
            }
        }
        mesh.bounds = {};
        for (const engine::Primitive& primitive : mesh.primitives) mesh.bounds.extend(primitive.bounds);
        engine::Node node;
        node.name = mesh.name;
        node.receiveShadows = receivesShadows;
        node.local = bake_ ? glm::dmat4(1.0) : place;
        if (skinned_) {
            for (engine::Primitive& primitive : mesh.primitives) {
                primitive.joints.assign(primitive.positions.size(), glm::uvec4(0));
                primitive.weights.assign(primitive.positions.size(), glm::vec4(1, 0, 0, 0));
            }
            engine::Node joint;
            joint.name = mesh.name + "_joint";
            joint.local = node.local;
            addNode(joint);
            scene_.skins.push_back({mesh.name + "_skin", {static_cast<int>(scene_.nodes.size()) - 1}, {glm::dmat4(1.0)}});
            node.skin = static_cast<int>(scene_.skins.size()) - 1;
            node.local = glm::dmat4(1.0);  // ignored for a skinned mesh (glTF 2.0 3.7.3)
        }
        scene_.meshes.push_back(std::move(mesh));
        node.mesh = static_cast<int>(scene_.meshes.size()) - 1;
        addNode(node);
    }

    // Position and target at unit scale.
    void addLight(const std::string& name, LightKind kind, const glm::dvec3& position,
                  const glm::dvec3& target, double outerCone, const nlohmann::json& shadow) {
        engine::Light light;
        light.name = name;
        light.type = lightType(kind);
        light.intensity = 10.0f;
        light.outerConeAngle = outerCone;
        light.innerConeAngle = outerCone * 0.8;
        light.extras = {{"shadow", shadow}};
        scene_.lights.push_back(light);
        engine::Node node;
        node.name = name;
        node.light = static_cast<int>(scene_.lights.size()) - 1;
        node.local = placeLooking(world(position), world(target));
        addNode(node);
        lightPosition_ = world(position);
    }


    engine::FrameCamera camera(const glm::dvec3& eye, const glm::dvec3& target, double yfov, int width,
                               int height) const {
        engine::FrameCamera camera;
        camera.width = width;
        camera.height = height;
        camera.eyeToWorld = placeLooking(world(eye), world(target));
        camera.projection = glm::perspectiveRH_NO(yfov, double(width) / height, kCameraNear * scale_,
                                                  kCameraFar * scale_);
        return camera;
    }

    engine::Scene& scene() { return scene_; }

private:
    void addNode(engine::Node node) {
        scene_.nodes.push_back(std::move(node));
        scene_.roots.push_back(static_cast<int>(scene_.nodes.size()) - 1);
    }

    double scale_;
    glm::dvec3 offset_;
    bool bake_, skinned_;
    engine::Scene scene_;
    glm::dmat4 tilt_{1.0};
    glm::dvec3 lightPosition_{0.0};
};

// The largest distance from `from` to a corner of any mesh instance's world bounds.
double farthestCorner(const engine::Scene& scene, const glm::dvec3& from) {
    double farthest = 0.0;
    for (const engine::MeshInstance& instance : scene.meshInstances)
        for (int c = 0; c < 8; ++c)
            farthest = std::max(farthest, glm::length(instance.worldBounds.corner(c) - from));
    return farthest;
}

glm::dvec3 towardLight(double elevationDeg) {
    const double e = elevationDeg * kDegree;
    return {-std::cos(e) * std::sin(kAzimuth), std::sin(e), -std::cos(e) * std::cos(kAzimuth)};
}

} // namespace

const char* toString(LightKind kind) {
    switch (kind) {
    case LightKind::Spot: return "spot";
    case LightKind::Directional: return "directional";
    case LightKind::Point: return "point";
    }
    return "?";
}

const char* toString(Layout layout) {
    switch (layout) {
    case Layout::Standard: return "standard";
    case Layout::LightInsideBox: return "light_inside_box";
    case Layout::LightOnSurface: return "light_on_surface";
    case Layout::CameraAtLight: return "camera_at_light";
    case Layout::LightStraightDown: return "light_straight_down";
    case Layout::MaskedFence: return "masked_fence";
    case Layout::OpaqueFence: return "opaque_fence";
    }
    return "?";
}

engine::Light::Type lightType(LightKind kind) {
    switch (kind) {
    case LightKind::Spot: return engine::Light::Type::Spot;
    case LightKind::Directional: return engine::Light::Type::Directional;
    case LightKind::Point: return engine::Light::Type::Point;
    }
    return engine::Light::Type::Point;
}

StressScene buildStressScene(const SceneSpec& spec, int width, int height) {
    Builder builder(spec.scale, spec.offset, spec.bakeOffset, spec.skinned);
    // Straight down, the boxes' sides would be exactly edge-on (N.L = 0): whether such a
    // pixel is in the evaluation set, and what the truth ray grazing it says, is decided by
    // rounding. The light stays exactly vertical; the scene is turned 3 degrees under it.
    if (spec.layout == Layout::LightStraightDown) builder.tiltBoxes(3.0);
    // A point light on the floor lies in the floor's plane (N.L = 0 there, the same
    // rounding lottery): the floor still casts but is not a receiver in that case.
    const bool lightInFloor = spec.layout == Layout::LightOnSurface && spec.light == LightKind::Point;
    builder.addBox(kFloor, !lightInFloor);
    if (spec.layout == Layout::MaskedFence || spec.layout == Layout::OpaqueFence) {
        builder.addFence(spec.layout == Layout::MaskedFence);  // alone on the floor
    } else {
        builder.addBox(kBlock);
        builder.addBox(kTower);
        builder.addBox(kPlank);
        if (spec.layout == Layout::LightInsideBox) builder.addBox(kShell);
        else builder.addBox(kHover);
    }

    // Where the light is and what it aims at (unit scale).
    glm::dvec3 position, target = kTarget;
    double cone = kSpotCone;
    switch (spec.layout) {
    case Layout::Standard:
    case Layout::CameraAtLight:
    case Layout::MaskedFence:
    case Layout::OpaqueFence:
        position = target + towardLight(spec.elevationDeg) *
                                (spec.light == LightKind::Point ? kPointDistance : kSpotDistance);
        break;
    case Layout::LightInsideBox:
        position = (kShell.min + kShell.max) * 0.5;
        target = glm::dvec3(2, 0, 0);  // spot: down and out, through the shell's walls
        cone = 0.7;
        break;
    case Layout::LightOnSurface:
        if (spec.light == LightKind::Point) {
            position = glm::dvec3(0.0, kFloor.max.y, -0.2);  // on the floor's top face
        } else {
            position = glm::dvec3(0.5 * (kTower.min.x + kTower.max.x), kTower.max.y,
                                  0.5 * (kTower.min.z + kTower.max.z));  // on the tower's top
            target = glm::dvec3(-1, 0, 2);
            cone = 0.7;
        }
        break;
    case Layout::LightStraightDown:
        position = glm::dvec3(0, 12, 0);
        target = glm::dvec3(0, 0, 0);
        break;
    }

    StressScene out;
    nlohmann::json shadow = spec.shadow;
    builder.addLight(out.lightName, spec.light, position, target, cone, nlohmann::json::object());
    builder.scene().updateWorldTransforms();
    out.farthestCorner = farthestCorner(builder.scene(), builder.world(position));
    if (spec.nearOverFar && spec.light != LightKind::Directional) {
        if (spec.infiniteFar) {
            shadow["far_plane"] = "infinite";
            shadow["near_plane"] = *spec.nearOverFar * out.farthestCorner;
        } else {
            const double farPlane = out.farthestCorner * 1.01;
            shadow["far_plane"] = farPlane;
            shadow["near_plane"] = *spec.nearOverFar * farPlane;
        }
    }
    builder.scene().lights.back().extras = {{"shadow", shadow}};

    if (spec.layout == Layout::CameraAtLight) {
        // From the apex along the light's axis, inside its cone (the width is wider than the
        // cone: pixels outside it are not in the evaluation set).
        out.camera = builder.camera(position, target, 1.6 * cone, width, height);
    } else {
        out.camera = builder.camera(kCameraEye, kCameraTarget, kCameraFov, width, height);
    }
    out.scene = std::move(builder.scene());
    out.scene.updateWorldTransforms();
    return out;
}

} // namespace stress
