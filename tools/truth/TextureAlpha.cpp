#include "truth/TextureAlpha.h"

#include <algorithm>
#include <cmath>

namespace truth {

namespace {

constexpr int kNearest = 0x2600, kClampToEdge = 0x812F, kMirroredRepeat = 0x8370;

// A texel index wrapped into [0, size) as OpenGL's wrap modes do.
int wrapTexel(int i, int size, int mode) {
    if (mode == kClampToEdge) return std::clamp(i, 0, size - 1);
    if (mode == kMirroredRepeat) {
        const int period = 2 * size;
        const int m = ((i % period) + period) % period;
        return m < size ? m : period - 1 - m;
    }
    return ((i % size) + size) % size;  // REPEAT
}

// floor(v) as an int; texel coordinates beyond +-2^30 (a UV of 1e30, say) are clamped
// there first, where float UVs have long lost every texel anyway.
int floorToInt(double v) {
    constexpr double kLimit = 1073741824.0;
    return static_cast<int>(std::floor(std::clamp(std::isfinite(v) ? v : 0.0, -kLimit, kLimit)));
}

double texelAlpha(const engine::Image& image, int x, int y) {
    return image.rgba8[(static_cast<std::size_t>(y) * image.width + x) * 4 + 3] / 255.0;
}

} // namespace

double sampleAlpha(const engine::Image& image, const engine::Sampler& sampler, glm::dvec2 uv) {
    if (image.width <= 0 || image.height <= 0) return 1.0;
    const double x = uv.x * image.width, y = uv.y * image.height;
    if (sampler.magFilter == kNearest)
        return texelAlpha(image, wrapTexel(floorToInt(x), image.width, sampler.wrapS),
                          wrapTexel(floorToInt(y), image.height, sampler.wrapT));
    // Bilinear between the texel centres around (x, y).
    const double fx = x - 0.5, fy = y - 0.5;
    const int x0 = floorToInt(fx), y0 = floorToInt(fy);
    const double ax = fx - std::floor(fx), ay = fy - std::floor(fy);  // in [0, 1) even where clamped
    const int xa = wrapTexel(x0, image.width, sampler.wrapS), xb = wrapTexel(x0 + 1, image.width, sampler.wrapS);
    const int ya = wrapTexel(y0, image.height, sampler.wrapT), yb = wrapTexel(y0 + 1, image.height, sampler.wrapT);
    const double top = (1.0 - ax) * texelAlpha(image, xa, ya) + ax * texelAlpha(image, xb, ya);
    const double bottom = (1.0 - ax) * texelAlpha(image, xa, yb) + ax * texelAlpha(image, xb, yb);
    return (1.0 - ay) * top + ay * bottom;
}

AlphaTestedPrimitive::AlphaTestedPrimitive(const engine::Primitive& primitive, const engine::Material& material,
                                           const engine::Image* image)
    : image_(image), sampler_(material.baseColorTexture.sampler), indices_(primitive.indices),
      cutoff_(engine::shadowAlphaCutoff(material)) {
    const std::size_t vertexCount = primitive.positions.size();
    alphas_.assign(vertexCount, material.baseColorFactor.a);
    for (std::size_t i = 0; i < primitive.colors.size() && i < vertexCount; ++i) alphas_[i] *= primitive.colors[i].a;
    if (!image_) return;
    // Absent UVs read (0, 0), as the GPU's constant attribute does.
    const std::vector<glm::vec2>& set =
        material.baseColorTexture.texCoord == 1 ? primitive.texcoords1 : primitive.texcoords;
    uvs_.assign(vertexCount, glm::dvec2(material.baseColorTexture.transform.apply(glm::vec2(0.0f))));
    for (std::size_t i = 0; i < set.size() && i < vertexCount; ++i)
        uvs_[i] = glm::dvec2(material.baseColorTexture.transform.apply(set[i]));
}

double AlphaTestedPrimitive::alphaAt(unsigned triangle, double u, double v) const {
    const std::uint32_t a = indices_[3 * triangle], b = indices_[3 * triangle + 1], c = indices_[3 * triangle + 2];
    const double w = 1.0 - u - v;
    double alpha = w * alphas_[a] + u * alphas_[b] + v * alphas_[c];
    if (image_) alpha *= sampleAlpha(*image_, sampler_, w * uvs_[a] + u * uvs_[b] + v * uvs_[c]);
    return alpha;
}

} // namespace truth
