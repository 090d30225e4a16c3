#pragma once
// The glTF 2.0 metallic-roughness BRDF (specification, Appendix B) in double, written from
// the specification's formulas, not from lit.frag, so render tests can check the shader
// against it:
//   c_diff = lerp(baseColor, 0, metallic)      f0 = lerp(0.04, baseColor, metallic)
//   alpha  = roughness^2
//   F = f0 + (1 - f0) (1 - |V.H|)^5                                     (Schlick)
//   D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2)                    (GGX / Trowbridge-Reitz)
//   Vis = 0.5 / (N.L sqrt((N.V)^2 (1 - a^2) + a^2) + N.V sqrt((N.L)^2 (1 - a^2) + a^2))
//         (Smith-GGX, height-correlated, as the Khronos sample viewer evaluates G/(4 N.L N.V))
//   f_diffuse  = (1 - F) c_diff / pi           f_specular = F D Vis
// The outgoing radiance of one light is (f_diffuse + f_specular) * E * N.L, E the light's
// color x intensity x attenuation.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace engine::test {

struct BrdfTerms {
    glm::dvec3 diffuse{0.0};   // f_diffuse * E * N.L
    glm::dvec3 specular{0.0};  // f_specular * E * N.L
};

// The smallest alpha (roughness^2) shaded: a perfectly smooth surface lit by a punctual
// light is a Dirac highlight, which float cannot represent. lit.frag clamps the same way.
constexpr double kMinBrdfAlpha = 0.002;

// One light's diffuse and specular radiance toward V (all unit vectors; N.L <= 0 gives 0).
inline BrdfTerms metallicRoughnessTerms(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                                        const glm::dvec3& baseColor, double metallic, double roughness,
                                        const glm::dvec3& irradiance) {
    constexpr double kPi = 3.14159265358979323846;
    const double nDotL = glm::dot(N, L);
    if (nDotL <= 0.0) return {};
    // A normal turned away from the eye (interpolated normals at silhouettes) is shaded
    // as grazing, as the shader clamps it.
    const double nDotV = std::max(glm::dot(N, V), 1e-4);
    const glm::dvec3 H = glm::normalize(L + V);
    const double nDotH = std::max(glm::dot(N, H), 0.0), vDotH = std::max(glm::dot(V, H), 0.0);
    const double alpha = std::max(roughness * roughness, kMinBrdfAlpha), a2 = alpha * alpha;
    const glm::dvec3 cDiff = baseColor * (1.0 - metallic);
    const glm::dvec3 f0 = glm::mix(glm::dvec3(0.04), baseColor, metallic);
    const glm::dvec3 F = f0 + (1.0 - f0) * std::pow(1.0 - vDotH, 5.0);
    const double d = nDotH * nDotH * (a2 - 1.0) + 1.0;
    const double D = a2 / (kPi * d * d);
    const double vis = 0.5 / (nDotL * std::sqrt(nDotV * nDotV * (1.0 - a2) + a2) +
                              nDotV * std::sqrt(nDotL * nDotL * (1.0 - a2) + a2));
    const glm::dvec3 lit = irradiance * nDotL;
    return {(1.0 - F) * cDiff / kPi * lit, F * D * vis * lit};
}

} // namespace engine::test
