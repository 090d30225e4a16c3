#include "math/Texgen.h"

#include <glm/gtc/matrix_access.hpp>

namespace shadowmap {

Texgen::Texgen()
    : eyePlanes_(planesFromRows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0})) {}

void Texgen::setEyePlanes(const glm::dmat4& planes, const glm::dmat4& modelviewInEffect) {
    // Each row p becomes p * MV^-1; stacked, that is planes * MV^-1.
    eyePlanes_ = planes * glm::inverse(modelviewInEffect);
}

void Texgen::setEyePlane(TexCoord coord, const glm::dvec4& plane,
                         const glm::dmat4& modelviewInEffect) {
    // glm's vec * mat is the row-vector product v^T * m.
    eyePlanes_ =
        glm::row(eyePlanes_, static_cast<int>(coord), plane * glm::inverse(modelviewInEffect));
}

glm::dvec4 Texgen::generate(const glm::dvec4& eyePosition) const {
    return eyePlanes_ * eyePosition;
}

glm::dvec4 Texgen::eyePlane(TexCoord coord) const {
    return glm::row(eyePlanes_, static_cast<int>(coord));
}

glm::dmat4 scaleBias() {
    return planesFromRows({0.5, 0.0, 0.0, 0.5}, {0.0, 0.5, 0.0, 0.5}, {0.0, 0.0, 0.5, 0.5},
                          {0.0, 0.0, 0.0, 1.0});
}

glm::dmat4 scaleBiasZeroToOne() {
    return planesFromRows({0.5, 0.0, 0.0, 0.5}, {0.0, 0.5, 0.0, 0.5}, {0.0, 0.0, 1.0, 0.0},
                          {0.0, 0.0, 0.0, 1.0});
}

glm::dmat4 shadowTexgenPlanes(const glm::dmat4& lightProjection, const glm::dmat4& lightToWorld) {
    return scaleBias() * lightProjection * glm::inverse(lightToWorld);
}

glm::dmat4 eyePlanesForCamera(const glm::dmat4& Epo, const glm::dmat4& eyeToWorld) {
    return Epo * eyeToWorld;
}

glm::dvec4 planeRow(const glm::dmat4& planes, int i) {
    return glm::row(planes, i);
}

glm::dmat4 planesFromRows(const glm::dvec4& s, const glm::dvec4& t, const glm::dvec4& r,
                          const glm::dvec4& q) {
    return glm::transpose(glm::dmat4(s, t, r, q));
}

}  // namespace shadowmap
