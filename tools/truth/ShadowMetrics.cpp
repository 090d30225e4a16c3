#include "truth/ShadowMetrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace truth {

std::vector<std::uint8_t> truthEdges(int width, int height, std::span<const std::uint8_t> truth,
                                     std::span<const std::uint8_t> covered) {
    const std::size_t count = static_cast<std::size_t>(width) * height;
    if (truth.size() != count || covered.size() != count)
        throw std::invalid_argument("truthEdges: image sizes differ from width*height");
    std::vector<std::uint8_t> edges(count, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            if (!covered[i]) continue;
            const bool lit = truth[i] != 0;
            for (int dy = -1; dy <= 1 && !edges[i]; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    const std::size_t n = static_cast<std::size_t>(ny) * width + nx;
                    if (covered[n] && (truth[n] != 0) != lit) {
                        edges[i] = 1;
                        break;
                    }
                }
        }
    return edges;
}

namespace {

// A shade or truth value as the metrics take it: clamped to [0,1], in double.
double unit(float value) { return std::clamp(static_cast<double>(value), 0.0, 1.0); }

// The metrics with a truth in [0,1] per pixel (the lit fraction): acne is where the shade is
// darker than the truth, leak where it is brighter. For a binary truth these are exactly the
// definitions of docs/metrics.md.
ShadowErrors errorsAgainst(std::size_t count, std::span<const float> litFraction,
                           std::span<const float> shade, std::span<const std::uint8_t> evaluation,
                           std::span<const std::uint8_t> edges) {
    // Sums in double: a 4K image has 8 M pixels, float sums would lose the small errors.
    double acne = 0.0, leak = 0.0, acneNoEdge = 0.0, leakNoEdge = 0.0;
    ShadowErrors errors;
    for (std::size_t i = 0; i < count; ++i) {
        if (!evaluation[i]) continue;
        const double s = unit(shade[i]);
        const double t = unit(litFraction[i]);
        const double a = std::max(t - s, 0.0);
        const double l = std::max(s - t, 0.0);
        acne += a;
        leak += l;
        ++errors.evaluated;
        if (edges[i]) continue;
        acneNoEdge += a;
        leakNoEdge += l;
        ++errors.evaluatedNoEdge;
    }
    if (errors.evaluated > 0) {
        errors.acne = acne / errors.evaluated;
        errors.leak = leak / errors.evaluated;
        errors.error = errors.acne + errors.leak;
    }
    if (errors.evaluatedNoEdge > 0) {
        errors.acneNoEdge = acneNoEdge / errors.evaluatedNoEdge;
        errors.leakNoEdge = leakNoEdge / errors.evaluatedNoEdge;
        errors.errorNoEdge = errors.acneNoEdge + errors.leakNoEdge;
    }
    return errors;
}

// The penumbra figures of softShadowErrors into `errors`.
void addPenumbraErrors(ShadowErrors& errors, std::size_t count, std::span<const float> visibleFraction,
                       std::span<const float> shade, std::span<const std::uint8_t> evaluation) {
    auto partial = [](double v) { return v > 0.0 && v < 1.0; };
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!evaluation[i]) continue;
        const double s = unit(shade[i]);
        const double t = unit(visibleFraction[i]);
        if (!partial(t) && !partial(s)) continue;
        sum += std::abs(t - s);
        ++errors.evaluatedPenumbra;
    }
    if (errors.evaluatedPenumbra > 0) errors.penumbraError = sum / errors.evaluatedPenumbra;
}

} // namespace

ShadowErrors shadowErrors(int width, int height, std::span<const std::uint8_t> truth,
                          std::span<const float> shade, std::span<const std::uint8_t> evaluation,
                          std::span<const std::uint8_t> covered) {
    const std::size_t count = static_cast<std::size_t>(width) * height;
    if (shade.size() != count || evaluation.size() != count)
        throw std::invalid_argument("shadowErrors: image sizes differ from width*height");
    const std::vector<std::uint8_t> edges = truthEdges(width, height, truth, covered);
    std::vector<float> litFraction(count);
    std::transform(truth.begin(), truth.end(), litFraction.begin(),
                   [](std::uint8_t lit) { return lit ? 1.0f : 0.0f; });
    return errorsAgainst(count, litFraction, shade, evaluation, edges);
}

ShadowErrors areaShadowErrors(int width, int height, std::span<const float> litFraction,
                              std::span<const std::uint8_t> truth, std::span<const float> shade,
                              std::span<const std::uint8_t> evaluation,
                              std::span<const std::uint8_t> covered) {
    const std::size_t count = static_cast<std::size_t>(width) * height;
    if (litFraction.size() != count || shade.size() != count || evaluation.size() != count)
        throw std::invalid_argument("areaShadowErrors: image sizes differ from width*height");
    return errorsAgainst(count, litFraction, shade, evaluation,
                         truthEdges(width, height, truth, covered));
}

ShadowErrors softShadowErrors(int width, int height, std::span<const float> visibleFraction,
                              std::span<const float> shade, std::span<const std::uint8_t> evaluation,
                              std::span<const std::uint8_t> covered) {
    const std::size_t count = static_cast<std::size_t>(width) * height;
    if (visibleFraction.size() != count || shade.size() != count || evaluation.size() != count)
        throw std::invalid_argument("softShadowErrors: image sizes differ from width*height");
    // The edges of the shadow as a hard filter would draw it: lit where most of the light is.
    std::vector<std::uint8_t> binarised(count);
    std::transform(visibleFraction.begin(), visibleFraction.end(), binarised.begin(),
                   [](float t) { return t >= 0.5f ? 1 : 0; });
    ShadowErrors errors = errorsAgainst(count, visibleFraction, shade, evaluation,
                                        truthEdges(width, height, binarised, covered));
    addPenumbraErrors(errors, count, visibleFraction, shade, evaluation);
    return errors;
}

std::vector<float> shadeFromMask8(std::span<const std::uint8_t> mask) {
    std::vector<float> shade(mask.size());
    std::transform(mask.begin(), mask.end(), shade.begin(),
                   [](std::uint8_t v) { return static_cast<float>(v) / 255.0f; });
    return shade;
}

} // namespace truth
