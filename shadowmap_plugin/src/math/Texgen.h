#pragma once
// CPU mirror of OpenGL's EYE_LINEAR texture-coordinate generation, and the matrices that
// set it up for shadow mapping (Everitt et al., NVIDIA "Hardware Shadow Mapping", Equations 1-5
// and Appendix A).
//
// Notation (the engine's, used in code, tests and the README):
//   M        object -> world (model)
//   V        eye    -> world, so the view matrix is V^-1
//   L        light  -> world, so the light's view matrix is L^-1
//   P_light  the light's projection (OpenGL clip convention, z in [-w, w])
//   S        scale-bias to [0,1]: rows (1/2 0 0 1/2)(0 1/2 0 1/2)(0 0 1/2 1/2)(0 0 0 1)
//   Epo      the planes as specified to OpenGL ("in their own object space")
//   Ee       the planes OpenGL stores: Ee = Epo * (modelview at specification time)^-1
//
// A "planes" matrix holds one plane per ROW, in the order s, t, r, q, so that
// (s,t,r,q) = Ee * (x_e, y_e, z_e, w_e). glm stores matrices column-major: the plane for
// coordinate i is glm::row(m, i), not m[i].
//
// The shadow setup of the seed: planes Epo = S * P_light * L^-1 (world-space planes)
// specified while the modelview is V^-1, hence Ee = Epo * V and, per vertex,
//   (s,t,r,q) = Ee * V^-1 * M * x_o = S * P_light * L^-1 * M * x_o          (Equation 2)
// Compose Ee in double on the CPU and feed the GPU floats of Ee and of camera-relative
// eye coordinates: both stay small even when the scene is 10^7 units from the origin.
#include <glm/glm.hpp>

namespace shadowmap {

// The texture coordinate a plane generates (glTexGen's GL_S .. GL_Q).
enum class TexCoord { S = 0, T = 1, R = 2, Q = 3 };

class Texgen {
public:
    // OpenGL's initial eye planes: s = (1,0,0,0), t = (0,1,0,0), r = q = (0,0,0,0).
    Texgen();

    // glTexGen(GL_S..GL_Q, GL_EYE_PLANE, row i of planes) for all four coordinates while
    // modelviewInEffect is the modelview: stores Ee = planes * modelviewInEffect^-1.
    // As in OpenGL, a singular modelview gives undefined (non-finite) planes.
    void setEyePlanes(const glm::dmat4& planes, const glm::dmat4& modelviewInEffect);

    // glTexGendv(coord, GL_EYE_PLANE, plane) alone: the stored plane is
    // plane * modelviewInEffect^-1 (a row vector times the inverse), the others are kept.
    void setEyePlane(TexCoord coord, const glm::dvec4& plane, const glm::dmat4& modelviewInEffect);

    // (s,t,r,q) = Ee * eyePosition, for a vertex in eye coordinates (modelview * x_o).
    glm::dvec4 generate(const glm::dvec4& eyePosition) const;

    // Ee, rows = stored s, t, r, q eye planes.
    const glm::dmat4& eyePlanes() const { return eyePlanes_; }
    glm::dvec4 eyePlane(TexCoord coord) const;

private:
    glm::dmat4 eyePlanes_;
};

// S: maps clip-space [-1,1] (after the divide) to [0,1] for s, t and r.
glm::dmat4 scaleBias();
// S for a projection whose depth is already [0,1] (glClipControl ZERO_TO_ONE, e.g. reversed
// Z): s and t as scaleBias(), r left as it is: rows (1/2 0 0 1/2)(0 1/2 0 1/2)(0 0 1 0)(0 0 0 1).
glm::dmat4 scaleBiasZeroToOne();

// Epo = S * P_light * L^-1: the shadow texgen planes in world space (rows s, t, r, q).
glm::dmat4 shadowTexgenPlanes(const glm::dmat4& lightProjection, const glm::dmat4& lightToWorld);

// Ee = Epo * V: the eye planes that result from specifying the world-space planes Epo while
// the modelview is V^-1 (what OpenGL would store), composed directly in double.
glm::dmat4 eyePlanesForCamera(const glm::dmat4& Epo, const glm::dmat4& eyeToWorld);

// Row i of a planes matrix (glm is column-major) and the inverse operation.
glm::dvec4 planeRow(const glm::dmat4& planes, int i);
glm::dmat4 planesFromRows(const glm::dvec4& s, const glm::dvec4& t, const glm::dvec4& r,
                          const glm::dvec4& q);

}  // namespace shadowmap
