#include "DebugViews.h"

#include "DepthImage.h"
#include "LightCamera.h"
#include "ProjectedDepth.h"

#include "truth/RayTracedVisibility.h"
#include "truth/ShadowMetrics.h"
#include "truth/SurfaceCapture.h"
#include "truth/TexelDensityImage.h"

#include "ShadowEvaluation.h"

#include <algorithm>
#include <cstdio>

namespace engine_view {

namespace {

bool sameCamera(const engine::FrameCamera& a, const engine::FrameCamera& b) {
    return a.width == b.width && a.height == b.height && a.eyeToWorld == b.eyeToWorld &&
           a.projection == b.projection;
}

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f%%", 100.0 * fraction);
    return text;
}

// Mixes `color` over the pixel by `amount` in [0,1].
void tint(std::uint8_t* pixel, const std::uint8_t (&color)[3], double amount) {
    for (int c = 0; c < 3; ++c) pixel[c] = static_cast<std::uint8_t>(pixel[c] + (color[c] - pixel[c]) * amount + 0.5);
}

const char* const kNoShadowTerm = "no plugin provides a shadow term: shaded view";

// The note of a view that shows the light's map when the light has none this frame. A
// volume light never has one: its shadow is a visibility per camera pixel, exact, which the
// shadow, penumbra and truth views show.
std::string noMapNote(const ViewedLight& light, const engine::ShadowView* view) {
    if (view && view->hasScreenVisibility)
        return light.name + ": volume, no map (exact per pixel; see the shadow and truth views): shaded view";
    return light.name + " has no shadow map this frame: shaded view";
}

// A volume light's map view: the count of shadow volumes holding each pixel's surface, 0
// (lit) black and each volume a quarter of the way to white, so the usual 0, 1 and 2 read
// apart at a glance.
constexpr int kStencilCountStep = 64;

std::vector<std::uint8_t> stencilCountsToGray(const std::vector<std::uint8_t>& counts) {
    std::vector<std::uint8_t> gray(counts.size());
    for (std::size_t i = 0; i < counts.size(); ++i)
        gray[i] = static_cast<std::uint8_t>(std::min(255, counts[i] * kStencilCountStep));
    return gray;
}

// The penumbra view: partly lit pixels mostly magenta (a colour lit scenes rarely show), the
// rest at 30% of their brightness, dark enough that the magenta stands out and light enough
// that the scene stays readable around it.
constexpr std::uint8_t kPenumbraColor[3] = {255, 0, 255}, kBlack[3] = {0, 0, 0};
constexpr double kPenumbraTint = 0.7, kOutsideDimming = 0.7;

// What a light's texel density depends on besides the surfaces: its map's matrices, which
// layers were rendered, the cascade splits and the resolution. Equal keys, equal m image.
std::vector<double> texelDensityKey(const engine::ShadowView& view) {
    std::vector<double> key{static_cast<double>(view.slot), view.settings.value("resolution", 0.0)};
    for (const engine::ShadowMapLayer& layer : view.layers) {
        for (const glm::dmat4* matrix : {&layer.lightToWorld, &layer.projection})
            for (int column = 0; column < 4; ++column)
                for (int row = 0; row < 4; ++row) key.push_back((*matrix)[column][row]);
        key.push_back(layer.rendered ? 1.0 : 0.0);
    }
    key.insert(key.end(), view.cascadeSplits.begin(), view.cascadeSplits.end());
    return key;
}

} // namespace

struct DebugViews::Cache {
    engine::FrameCamera surfacesCamera;
    std::uint64_t surfacesRevision = 0;  // Scene::lastInstanceRevision when captured
    truth::SurfaceBuffer surfaces;
    bool haveSurfaces = false;
    int truthSlot = -1;  // truth below is for this light and surfacesCamera
    std::vector<std::uint8_t> truth, evaluation;
    // The density view's picture and notes, for these surfaces and texelDensityKey (empty:
    // none): a frame in which nothing moved only copies them.
    std::vector<double> densityKey;
    std::vector<std::uint8_t> densityImage;
    std::vector<std::string> densityNotes;
};

DebugViews::DebugViews(engine::Renderer& renderer, const engine::Scene& scene)
    : renderer_(renderer), scene_(scene), cache_(std::make_unique<Cache>()) {}

DebugViews::~DebugViews() = default;

engine::FrameResult DebugViews::renderFrame(engine::FrameRequest request) {
    request.timing = true;  // the overlay shows every light's pass times
    return renderer_.renderFrame(request);
}

const truth::SurfaceBuffer& DebugViews::surfaces(const engine::FrameCamera& camera) {
    // An animation moves the surfaces under a still camera: the scene's revision says so.
    if (!cache_->haveSurfaces || !sameCamera(cache_->surfacesCamera, camera) ||
        cache_->surfacesRevision != scene_.lastInstanceRevision) {
        if (!capture_) capture_ = std::make_unique<truth::SurfaceCapture>();
        cache_->surfaces = capture_->capture(scene_, renderer_.gpu(), camera);
        cache_->surfacesCamera = camera;
        cache_->surfacesRevision = scene_.lastInstanceRevision;
        cache_->haveSurfaces = true;
        cache_->truthSlot = -1;
        cache_->densityKey.clear();
    }
    return cache_->surfaces;
}

std::size_t paintPenumbra(Image& shaded, const std::vector<std::uint8_t>& shadowTerm) {
    std::size_t count = 0;
    const std::size_t pixels = std::min(shadowTerm.size(), shaded.rgba.size() / 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        const bool partly = inPenumbra(shadowTerm[i]);
        tint(&shaded.rgba[4 * i], partly ? kPenumbraColor : kBlack, partly ? kPenumbraTint : kOutsideDimming);
        count += partly;
    }
    return count;
}

ViewFrame DebugViews::render(DebugView view, const ViewedLight* light, const engine::ShadowView* shadow,
                             const engine::FrameCamera& camera) {
    if (!light && view != DebugView::Shaded) {
        ViewFrame out = render(DebugView::Shaded, nullptr, nullptr, camera);
        out.notes.push_back("no light in the scene: shaded view");
        return out;
    }
    engine::FrameRequest request;
    request.camera = camera;
    ViewFrame out;
    switch (view) {
    case DebugView::Shaded:
        out.frame = renderFrame(request);
        out.image = {camera.width, camera.height, renderer_.readColor()};
        return out;
    case DebugView::LightView:
        request.camera = lightCamera(scene_, light->slot, shadow, std::min(camera.width, camera.height));
        out.frame = renderFrame(request);
        out.image = {request.camera.width, request.camera.height, renderer_.readColor()};
        out.notes.push_back("the scene seen from " + light->name);
        return out;
    case DebugView::DepthMap:
        return depthMap(*light, camera);
    case DebugView::ProjectedDepth:
        return projected(*light, camera);
    case DebugView::Comparison:
        return comparison(*light, camera);
    case DebugView::ShadowTerm:
        return shadowTerm(*light, camera);
    case DebugView::Penumbra:
        return penumbra(*light, camera);
    case DebugView::AcneLeak:
        return acneLeak(*light, camera);
    case DebugView::Cascades:
        return cascades(*light, camera);
    case DebugView::TexelDensity:
        return texelDensity(*light, camera);
    }
    return out;
}

ViewFrame DebugViews::depthMap(const ViewedLight& light, const engine::FrameCamera& camera) {
    engine::FrameRequest request;
    request.camera = camera;
    request.shadowMapSlots.push_back(light.slot);
    ViewFrame out;
    out.frame = renderFrame(request);
    const auto found = out.frame.shadowMaps.find(light.slot);
    const auto counted = out.frame.stencilCounts.find(light.slot);
    if (found == out.frame.shadowMaps.end() && counted != out.frame.stencilCounts.end()) {
        out.image = Image::fromGray(counted->second.width, counted->second.height,
                                    stencilCountsToGray(counted->second.counts));
        out.notes.push_back(light.name + ": volume, no map; the count of shadow volumes at each pixel: black 0 (lit), "
                                         "each volume brighter");
        return out;
    }
    if (found == out.frame.shadowMaps.end()) {
        out.image = {camera.width, camera.height, renderer_.readColor()};
        out.notes.push_back(noMapNote(light, out.frame.shadowView(light.slot)));
        return out;
    }
    int width = 0, height = 0;
    std::vector<std::uint8_t> gray = depthToGray(found->second, width, height);
    if (found->second.cube) labelCubeFaces(gray, width, height, found->second.width);
    out.image = Image::fromGray(width, height, gray);
    out.notes.push_back("depth map of " + light.name + " (" + std::to_string(found->second.width) + "x" +
                        std::to_string(found->second.height) +
                        (found->second.cube ? ", cube: +X -X +Y -Y +Z -Z, labelled" : "") +
                        "): near dark, far white");
    return out;
}

ViewFrame DebugViews::projected(const ViewedLight& light, const engine::FrameCamera& camera) {
    engine::FrameRequest request;
    request.camera = camera;
    request.shadowMapSlots.push_back(light.slot);
    ViewFrame out;
    out.frame = renderFrame(request);
    const Image shaded{camera.width, camera.height, renderer_.readColor()};
    const auto found = out.frame.shadowMaps.find(light.slot);
    // The matrices of this frame's map (the view of the frame just rendered).
    const engine::ShadowView* view = out.frame.shadowView(light.slot);
    if (found == out.frame.shadowMaps.end() || !view || view->layers.empty()) {
        out.image = shaded;
        out.notes.push_back(noMapNote(light, view));
        return out;
    }
    int width = 0, height = 0;
    const std::vector<std::uint8_t> gray = depthToGray(found->second, width, height);
    ProjectedMap map;
    map.kind = view->cube ? ProjectedMap::Kind::Cube : ProjectedMap::Kind::Map2D;
    const engine::ShadowMapLayer& layer = view->layers.front();
    map.viewProjection = layer.projection * glm::inverse(layer.lightToWorld);
    map.position = scene_.lightInstances[light.slot].position();
    map.faceSize = found->second.width;
    map.gray = &gray;
    out.image = projectDepthMap(shaded, surfaces(camera), map);
    out.notes.push_back("depth map of " + light.name + " projected from the light: near dark, far white");
    return out;
}

std::vector<std::uint8_t> DebugViews::renderShadowTerm(const ViewedLight& light, const engine::FrameCamera& camera,
                                                       ViewFrame& out) {
    engine::FrameRequest request;
    request.camera = camera;
    request.shadowMaskSlots.push_back(light.slot);
    out.frame = renderFrame(request);
    out.image = {camera.width, camera.height, renderer_.readColor()};
    if (out.frame.shadowTermProvided) return renderer_.readShadowMask(light.slot);
    out.notes.push_back(kNoShadowTerm);
    return {};
}

ViewFrame DebugViews::comparison(const ViewedLight& light, const engine::FrameCamera& camera) {
    engine::FrameRequest request;
    request.camera = camera;
    request.comparisonSlots.push_back(light.slot);
    ViewFrame out;
    out.frame = renderFrame(request);
    if (!out.frame.shadowTermProvided) {
        out.image = {camera.width, camera.height, renderer_.readColor()};
        out.notes.push_back(kNoShadowTerm);
        return out;
    }
    const engine::ShadowView* view = out.frame.shadowView(light.slot);
    if (view && view->hasScreenVisibility) {
        // No map to compare a depth with: the visibility the volumes gave is the answer.
        ViewFrame term = shadowTerm(light, camera);
        term.notes.insert(term.notes.begin(), light.name + ": volume, no map to compare with (exact per pixel): "
                                                           "its shadow term");
        return term;
    }
    out.image = {camera.width, camera.height, renderer_.readComparison(light.slot)};
    out.notes.push_back("comparison: green lit, red shadowed, blue offset decided, grey no say");
    return out;
}

ViewFrame DebugViews::shadowTerm(const ViewedLight& light, const engine::FrameCamera& camera) {
    ViewFrame out;
    const std::vector<std::uint8_t> term = renderShadowTerm(light, camera, out);
    if (term.empty()) return out;
    out.image = Image::fromGray(camera.width, camera.height, term);
    out.notes.push_back("shadow term of " + light.name + ": white lit, black shadowed");
    return out;
}

ViewFrame DebugViews::penumbra(const ViewedLight& light, const engine::FrameCamera& camera) {
    ViewFrame out;
    const std::vector<std::uint8_t> term = renderShadowTerm(light, camera, out);
    if (term.empty()) return out;
    const std::size_t count = paintPenumbra(out.image, term);
    out.notes.push_back("penumbra of " + light.name + " (magenta: partly lit, shadow term strictly between 0 and 1): " +
                        std::to_string(count) + " pixels, " +
                        percent(static_cast<double>(count) / static_cast<double>(term.size())) + " of the view");
    const engine::ShadowView* view = out.frame.shadowView(light.slot);
    if (view && !(view->lightRadius > 0.0) && !(view->angularDiameter > 0.0))
        out.notes.push_back(light.name + " has no size: only the filter's edge is partly lit (keys - =)");
    return out;
}

ViewFrame DebugViews::acneLeak(const ViewedLight& light, const engine::FrameCamera& camera) {
    ViewFrame out;
    const std::vector<std::uint8_t> term = renderShadowTerm(light, camera, out);
    if (term.empty()) return out;
    const std::vector<float> shade = truth::shadeFromMask8(term);
    const truth::SurfaceBuffer& buffer = surfaces(camera);
    if (cache_->truthSlot != light.slot) {
        if (!visibility_) visibility_ = std::make_unique<truth::RayTracedVisibility>(scene_);
        cache_->truth = visibility_->visibility(scene_, light.slot, buffer);
        cache_->evaluation = truth::evaluationSet(scene_, light.slot, buffer);
        cache_->truthSlot = light.slot;
    }
    const truth::ShadowErrors errors = truth::shadowErrors(camera.width, camera.height, cache_->truth, shade,
                                                           cache_->evaluation, buffer.covered);
    static constexpr std::uint8_t kAcne[3] = {255, 0, 0}, kLeak[3] = {0, 64, 255};
    for (std::size_t i = 0; i < buffer.pixelCount(); ++i) {
        if (!cache_->evaluation[i]) continue;
        const double wrong = cache_->truth[i] ? 1.0 - shade[i] : shade[i];
        if (wrong > 0.02) tint(&out.image.rgba[4 * i], cache_->truth[i] ? kAcne : kLeak, 0.5 + 0.5 * std::min(wrong, 1.0));
    }
    out.notes.push_back(light.name + " vs ray-traced truth: acne (red) " + percent(errors.acne) + ", leak (blue) " +
                        percent(errors.leak));
    out.notes.push_back("error " + percent(errors.error) + ", off shadow edges " + percent(errors.errorNoEdge) + ", of " +
                        std::to_string(errors.evaluated) + " evaluated pixels");
    return out;
}

ViewFrame DebugViews::cascades(const ViewedLight& light, const engine::FrameCamera& camera) {
    engine::FrameRequest request;
    request.camera = camera;
    ViewFrame out;
    out.frame = renderFrame(request);
    out.image = {camera.width, camera.height, renderer_.readColor()};
    const engine::ShadowView* view = out.frame.shadowView(light.slot);
    if (!view || view->cascadeSplits.size() < 2) {
        out.notes.push_back(view && view->hasScreenVisibility
                                ? noMapNote(light, view)
                                : light.name + " has no cascades this frame (one map or none): shaded view");
        return out;
    }
    // The lookup's rule (visibility.glsl cascadeIndex): the first cascade whose far split lies
    // beyond the pixel's view depth, the last one for anything farther.
    static constexpr std::uint8_t kTints[4][3] = {{255, 40, 40}, {40, 220, 40}, {60, 90, 255}, {240, 220, 40}};
    const std::vector<double>& splits = view->cascadeSplits;
    const int count = static_cast<int>(splits.size()) - 1;
    const truth::SurfaceBuffer& buffer = surfaces(camera);
    const glm::dmat4& v = camera.eyeToWorld;
    for (std::size_t i = 0; i < buffer.pixelCount(); ++i) {
        if (!buffer.covered[i]) continue;
        const double depth = -glm::dot(glm::dvec3(v[2]), buffer.worldPosition[i] - glm::dvec3(v[3]));
        int cascade = 0;
        while (cascade < count - 1 && depth > splits[cascade + 1]) ++cascade;
        tint(&out.image.rgba[4 * i], kTints[cascade % 4], 0.35);
    }
    std::string bounds;
    for (double split : splits) {
        char text[32];
        std::snprintf(text, sizeof text, "%s%.3g", bounds.empty() ? "" : " | ", split);
        bounds += text;
    }
    out.notes.push_back(std::to_string(count) + " cascades of " + light.name + " (red, green, blue, yellow from near)");
    out.notes.push_back("split view depths: " + bounds);
    return out;
}

ViewFrame DebugViews::texelDensity(const ViewedLight& light, const engine::FrameCamera& camera) {
    engine::FrameRequest request;
    request.camera = camera;
    ViewFrame out;
    out.frame = renderFrame(request);
    const engine::ShadowView* view = out.frame.shadowView(light.slot);
    if (!view || !view->hasMap) {
        out.image = {camera.width, camera.height, renderer_.readColor()};
        out.notes.push_back(noMapNote(light, view));
        return out;
    }
    const truth::SurfaceBuffer& buffer = surfaces(camera);  // clears the density when it recaptures
    std::vector<double> key = texelDensityKey(*view);
    if (key != cache_->densityKey) {
        const std::vector<double> m =
            truth::texelOnScreenImage(*view, buffer, truth::evaluationSet(scene_, light.slot, buffer));
        cache_->densityImage = truth::texelDensityImage(m);
        cache_->densityNotes = {"texel density of " + light.name + ": " + truth::texelDensityLegend()};
        // The figures --truth prints for this light and view.
        const evaluation::TexelOnScreen texel = evaluation::summarizeTexelOnScreen(m);
        char figures[96] = "no pixel has a value";
        if (texel.count > 0)
            std::snprintf(figures, sizeof figures, "m mean %.2f, p95 %.2f over %zu pixels", texel.mean, texel.p95,
                          texel.count);
        cache_->densityNotes.push_back(figures);
        cache_->densityKey = std::move(key);
    }
    out.image = {camera.width, camera.height, cache_->densityImage};
    out.notes = cache_->densityNotes;
    return out;
}

} // namespace engine_view
