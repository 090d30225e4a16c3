#include "AutoExposure.h"

#include "engine/render/Renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tools {

namespace {

// The photographic convention of engine::exposureFromEv100: exposure = 1 / (1.2 * 2^EV100).
constexpr double kEv100Calibration = 1.2;

// An 8-bit sRGB code's linear value (IEC 61966-2-1).
double decodeSrgb(std::uint8_t code) {
    const double v = code / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

bool saturated(const std::uint8_t* pixel) { return pixel[0] == 255 || pixel[1] == 255 || pixel[2] == 255; }

} // namespace

bool probeSaturates(const std::vector<std::uint8_t>& rgba) {
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
        if (saturated(&rgba[i])) return true;
    return false;
}

MeteredScene meterProbes(const std::vector<ExposureProbe>& probes) {
    MeteredScene metered;
    if (probes.empty()) return metered;
    double sumLog = 0.0;
    const std::size_t size = probes.front().rgba.size();
    for (std::size_t i = 0; i + 3 < size; i += 4) {
        const std::uint8_t* first = &probes.front().rgba[i];
        if (first[0] == 0 && first[1] == 0 && first[2] == 0) continue;  // black: nothing to measure
        std::size_t k = 0;
        while (k + 1 < probes.size() && saturated(&probes[k].rgba[i])) ++k;
        const std::uint8_t* pixel = &probes[k].rgba[i];
        metered.saturated += saturated(pixel) ? 1 : 0;
        const double luminance =
            0.2126 * decodeSrgb(pixel[0]) + 0.7152 * decodeSrgb(pixel[1]) + 0.0722 * decodeSrgb(pixel[2]);
        // A pixel not black in the brightest probe is not black in a darker one that reads
        // it: it saturated the probes before.
        sumLog += std::log(luminance / static_cast<double>(probes[k].exposure));
        ++metered.pixels;
    }
    if (metered.pixels > 0) metered.logAverage = std::exp(sumLog / static_cast<double>(metered.pixels));
    return metered;
}

double ev100ForLogAverage(double logAverage) { return std::log2(logAverage / (kEv100Calibration * kMiddleGrey)); }

AutoExposure chooseAutoExposure(const engine::RendererConfig& config, const std::vector<engine::RenderPlugin*>& plugins,
                                const engine::Scene& scene, const engine::FrameCamera& camera) {
    engine::FrameRequest request;
    request.camera = camera;
    const double shrink = std::min(1.0, static_cast<double>(kProbeSide) / std::max(camera.width, camera.height));
    request.camera.width = std::max(1, static_cast<int>(std::lround(camera.width * shrink)));
    request.camera.height = std::max(1, static_cast<int>(std::lround(camera.height * shrink)));
    engine::RendererConfig probeConfig = config;
    probeConfig.toneMapping = engine::RendererConfig::ToneMapping::None;  // invertible below 1
    probeConfig.clearColor = glm::vec3(0.0f);  // the background is no radiance of the scene
    std::vector<ExposureProbe> probes;
    for (double ev100 = kMinEv100; ev100 <= kMaxEv100; ev100 += kProbeStepEv) {
        probeConfig.exposure = engine::exposureFromEv100(ev100);
        engine::Renderer renderer(probeConfig, plugins);
        renderer.setScene(scene);
        renderer.renderFrame(request);
        probes.push_back({probeConfig.exposure, renderer.readColor()});
        if (!probeSaturates(probes.back().rgba)) break;
    }
    AutoExposure chosen;
    chosen.probes = static_cast<int>(probes.size());
    chosen.metered = meterProbes(probes);
    chosen.exposure = config.exposure;
    if (chosen.metered.pixels == 0) return chosen;
    chosen.measured = true;
    chosen.ev100 = std::clamp(ev100ForLogAverage(chosen.metered.logAverage), kMinEv100, kMaxEv100);
    chosen.exposure = engine::exposureFromEv100(chosen.ev100);
    return chosen;
}

std::string describe(const AutoExposure& chosen) {
    char text[256];
    if (!chosen.measured)
        std::snprintf(text, sizeof text, "auto exposure: nothing lit in view to measure; exposure %g kept",
                      static_cast<double>(chosen.exposure));
    else
        std::snprintf(text, sizeof text,
                      "auto exposure: EV100 %.2f (exposure %.3g: log-average luminance %.3g of %zu pixels to middle "
                      "grey %g)",
                      chosen.ev100, static_cast<double>(chosen.exposure), chosen.metered.logAverage,
                      chosen.metered.pixels, kMiddleGrey);
    return text;
}

} // namespace tools
