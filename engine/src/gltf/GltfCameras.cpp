// glTF cameras to engine cameras, with the ranges the glTF spec gives each field.
#include "GltfConvert.h"

#include <cmath>
#include <numbers>

namespace engine::gltf {

namespace {

Camera convertCamera(const LoadContext& context, const tinygltf::Camera& source, std::size_t index) {
    const std::string object = indexedNamed("cameras", index, source.name);
    const auto require = [&](bool ok, const std::string& what, double value, const char* rule) {
        if (!ok || !std::isfinite(value))
            context.fail(object, what + " " + formatNumber(value) + " must be a finite number " + rule);
    };
    Camera camera;
    camera.name = source.name;
    if (source.type == "perspective") {
        const tinygltf::PerspectiveCamera& p = source.perspective;
        require(p.yfov > 0.0 && p.yfov < std::numbers::pi, "perspective.yfov", p.yfov, "in (0, pi)");
        require(p.znear > 0.0, "perspective.znear", p.znear, "> 0");
        require(p.zfar == 0.0 || p.zfar > p.znear, "perspective.zfar", p.zfar, "> znear (or absent for infinite)");
        require(p.aspectRatio >= 0.0, "perspective.aspectRatio", p.aspectRatio, "> 0 (or absent)");
        camera.type = Camera::Type::Perspective;
        camera.yfov = p.yfov;
        camera.aspectRatio = p.aspectRatio;
        camera.znear = p.znear;
        camera.zfar = p.zfar;
    } else if (source.type == "orthographic") {
        const tinygltf::OrthographicCamera& o = source.orthographic;
        require(o.xmag != 0.0, "orthographic.xmag", o.xmag, "other than 0");
        require(o.ymag != 0.0, "orthographic.ymag", o.ymag, "other than 0");
        require(o.znear >= 0.0, "orthographic.znear", o.znear, ">= 0");
        require(o.zfar > o.znear, "orthographic.zfar", o.zfar, "> znear");
        camera.type = Camera::Type::Orthographic;
        camera.xmag = o.xmag;
        camera.ymag = o.ymag;
        camera.znear = o.znear;
        camera.zfar = o.zfar;
    } else {
        context.fail(object, "type '" + source.type + "' is not perspective or orthographic");
    }
    return camera;
}

} // namespace

std::vector<Camera> convertCameras(const LoadContext& context, const tinygltf::Model& model) {
    std::vector<Camera> cameras;
    for (std::size_t i = 0; i < model.cameras.size(); ++i) cameras.push_back(convertCamera(context, model.cameras[i], i));
    return cameras;
}

} // namespace engine::gltf
