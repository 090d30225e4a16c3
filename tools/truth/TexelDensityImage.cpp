#include "truth/TexelDensityImage.h"

#include "truth/TexelMetric.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace truth {

std::array<std::uint8_t, 4> texelDensityColor(double m) {
    const auto opaque = [](const std::array<std::uint8_t, 3>& rgb) {
        return std::array<std::uint8_t, 4>{rgb[0], rgb[1], rgb[2], 255};
    };
    // m <= 0 cannot come from the metric (a length); it has no log either.
    if (!std::isfinite(m) || !(m > 0.0)) return opaque(kTexelDensityNoValue);
    return opaque(heatColor(m, kTexelDensityScale));
}

std::vector<std::uint8_t> texelDensityImage(std::span<const double> m) {
    std::vector<std::uint8_t> rgba(4 * m.size());
    for (std::size_t i = 0; i < m.size(); ++i) {
        const std::array<std::uint8_t, 4> color = texelDensityColor(m[i]);
        std::copy(color.begin(), color.end(), rgba.begin() + 4 * i);
    }
    return rgba;
}

std::vector<double> texelOnScreenImage(const engine::ShadowView& view, const SurfaceBuffer& surfaces,
                                       std::span<const std::uint8_t> evaluated) {
    std::vector<double> m(surfaces.pixelCount(), std::numeric_limits<double>::quiet_NaN());
    const int resolution = view.settings.value("resolution", 0);
    if (resolution <= 0) return m;
    std::vector<glm::dmat4> mapViewProjection;
    for (const engine::ShadowMapLayer& layer : view.layers)
        mapViewProjection.push_back(layer.projection * glm::inverse(layer.lightToWorld));
    for (std::size_t i = 0; i < m.size() && i < evaluated.size(); ++i) {
        if (!evaluated[i]) continue;
        const int layer = shadowLayerAt(view, surfaces.camera, surfaces.worldPosition[i]);
        if (layer < 0) continue;
        m[i] = texelOnScreen(surfaces.worldPosition[i], surfaces.worldNormal[i], surfaces.camera,
                             mapViewProjection[layer], resolution);
    }
    return m;
}

std::string texelDensityLegend() {
    std::string legend = "m (px per texel)";
    for (std::size_t i = 0; i < kTexelDensityScale.size(); ++i) {
        char stop[48];
        const char* bound = i == 0 ? "<=" : i + 1 == kTexelDensityScale.size() ? ">=" : "";
        std::snprintf(stop, sizeof stop, "%s %s%g %s", i == 0 ? "" : ",", bound, kTexelDensityScale[i].value,
                      kTexelDensityScale[i].name);
        legend += stop;
    }
    return legend + ", log scale; grey: no value";
}

} // namespace truth
