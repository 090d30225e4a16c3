#pragma once
// A horizontal "grille" for alpha-tested caster tests: one double-sided quad at y = 3 over
// |x|, |z| <= 2.5 whose base color texture (8 x 8 texels) has a known pattern of opaque and
// transparent texels, and the alpha it has at any point of its plane, worked out here from
// the pattern, the UVs, the wrap mode and the texture transform (NEAREST magnification
// only: texel edges are then exact). Used by the shadow-mask render tests and the
// ray-traced truth's tests alike.
#include "TestScenes.h"

#include "engine/scene/Shapes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace engine::test {

inline constexpr double kGrilleY = 3.0, kHalf = 2.5;  // the grille: y = 3, |x|, |z| <= 2.5
inline constexpr int kTexels = 8;                      // its texture: 8 x 8
inline constexpr int kNearest = 0x2600, kLinear = 0x2601;
inline constexpr int kRepeat = 0x2901, kClampToEdge = 0x812F, kMirroredRepeat = 0x8370;

// The pattern: asymmetric under swapping or flipping u and v, so a transposed or mirrored
// lookup shows.
inline bool opaqueTexel(int column, int row) { return (column + 2 * row) % 3 == 0 || (row == 1 && column < 6); }

// How the grille's material and texture coordinates are set up.
struct Grille {
    int magFilter = kNearest;
    int wrap = kClampToEdge;
    glm::vec2 uvMin{0.0f}, uvMax{1.0f};  // TEXCOORD at the corners (x, z) = (-2.5, -2.5) and (2.5, 2.5)
    engine::UvTransform transform;
    bool viaTexcoord1 = false;  // the pattern's UVs in TEXCOORD_1, TEXCOORD_0 a constant that misses it
    bool vertexAlphaOnly = false;  // no texture: COLOR_0 alpha 1 at x = -2.5 falling to 0 at x = 2.5
    engine::AlphaMode mode = engine::AlphaMode::Mask;
    float opaqueAlpha = 1.0f, clearAlpha = 0.0f;  // texel alphas
    float blendShadowCutoff = 0.5f;
    bool castShadows = true;  // KHR_lights_shadows on the grille's primitive
};

inline int wrapTexel(int i, int mode) {
    if (mode == kClampToEdge) return std::clamp(i, 0, kTexels - 1);
    const int m = ((i % (2 * kTexels)) + 2 * kTexels) % (2 * kTexels);
    if (mode == kMirroredRepeat) return m < kTexels ? m : 2 * kTexels - 1 - m;
    return m % kTexels;
}

// The grille's alpha at world (x, z) on its plane, from the pattern (NEAREST only).
inline double grilleAlpha(const Grille& grille, double x, double z) {
    const glm::dvec2 across((x + kHalf) / (2 * kHalf), (z + kHalf) / (2 * kHalf));
    if (grille.vertexAlphaOnly) return 1.0 - across.x;
    const glm::vec2 raw = grille.uvMin + (grille.uvMax - grille.uvMin) * glm::vec2(across);
    const glm::vec2 uv = grille.transform.apply(raw);
    const int column = wrapTexel(static_cast<int>(std::floor(uv.x * kTexels)), grille.wrap);
    const int row = wrapTexel(static_cast<int>(std::floor(uv.y * kTexels)), grille.wrap);
    return opaqueTexel(column, row) ? grille.opaqueAlpha : grille.clearAlpha;
}

inline double grilleCutoff(const Grille& grille) {
    return grille.mode == engine::AlphaMode::Blend ? grille.blendShadowCutoff : 0.5;
}

// Adds the grille: an image, a material and a node turning the XY quad to face up.
inline void addGrille(SceneBuilder& builder, const Grille& grille) {
    engine::Scene& scene = builder.scene;
    engine::Material material;
    material.name = "grille";
    material.doubleSided = true;
    material.alphaMode = grille.mode;
    material.alphaCutoff = 0.5f;
    material.blendShadowCutoff = grille.blendShadowCutoff;
    if (!grille.vertexAlphaOnly) {
        engine::Image image = engine::binaryAlphaImage("pattern", kTexels, kTexels, {200, 200, 200}, opaqueTexel);
        for (std::size_t i = 3; i < image.rgba8.size(); i += 4)
            image.rgba8[i] = static_cast<std::uint8_t>(std::lround((image.rgba8[i] ? grille.opaqueAlpha : grille.clearAlpha) * 255.0f));
        scene.images.push_back(image);
        material.baseColorTexture.image = static_cast<int>(scene.images.size()) - 1;
        material.baseColorTexture.sampler = {grille.magFilter, kNearest, grille.wrap, grille.wrap};
        material.baseColorTexture.texCoord = grille.viaTexcoord1 ? 1 : 0;
        material.baseColorTexture.transform = grille.transform;
    }
    scene.materials.push_back(material);

    engine::Primitive quad = engine::texturedQuadPrimitive({-kHalf, -kHalf}, {kHalf, kHalf},
                                                           static_cast<int>(scene.materials.size()) - 1,
                                                           grille.uvMin, grille.uvMax);
    quad.castShadows = grille.castShadows;
    if (grille.viaTexcoord1) {
        quad.texcoords1 = quad.texcoords;
        // Texel (1, 0): clear. Read by mistake, it would cast no shadow at all.
        quad.texcoords.assign(quad.texcoords.size(), glm::vec2(1.5f / kTexels, 0.5f / kTexels));
    }
    if (grille.vertexAlphaOnly) {
        quad.texcoords.clear();
        for (const glm::vec3& p : quad.positions)
            quad.colors.push_back({1.0f, 1.0f, 1.0f, p.x < 0.0f ? 1.0f : 0.0f});
    }
    engine::Mesh mesh;
    mesh.name = "grille";
    mesh.bounds = quad.bounds;
    mesh.primitives.push_back(std::move(quad));
    scene.meshes.push_back(std::move(mesh));
    engine::Node node;
    node.name = "grille";
    node.mesh = static_cast<int>(scene.meshes.size()) - 1;
    // XY plane facing +Z -> XZ plane facing +Y, at height kGrilleY: quad (x, y) -> (x, 3, -y).
    node.local = glm::rotate(glm::translate(glm::dmat4(1.0), {0.0, kGrilleY, 0.0}), -glm::half_pi<double>(),
                             glm::dvec3(1, 0, 0));
    builder.addNode(node);
}

} // namespace engine::test
