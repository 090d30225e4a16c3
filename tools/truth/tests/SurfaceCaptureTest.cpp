// The capture puts every pixel's surface point where the geometry is, in double, near the
// origin and 10^6 away from it.
#include "truth/SurfaceCapture.h"

#include "TruthTestScene.h"

#include "TruthGlTest.h"

#include "engine/render/SceneGpu.h"

#include <gtest/gtest.h>

namespace truth {
namespace {

class SurfaceCaptureTest : public test::TruthGlTest,
                           public ::testing::WithParamInterface<double> {};

TEST_P(SurfaceCaptureTest, PointsLieOnTheGeometryThatCoversThePixel) {
    const glm::dvec3 offset(GetParam(), 0.0, GetParam());
    const engine::Scene scene = test::boxOverPlane(engine::Light::Type::Spot, offset);
    const engine::SceneGpu gpu(scene);
    const SurfaceBuffer surfaces =
        SurfaceCapture().capture(scene, gpu, test::sideCamera(320, 240, offset));
    ASSERT_EQ(surfaces.pixelCount(), 320u * 240u);

    std::size_t plane = 0, box = 0, background = 0;
    for (std::size_t i = 0; i < surfaces.pixelCount(); ++i) {
        if (!surfaces.covered[i]) {
            ++background;
            EXPECT_EQ(surfaces.instance[i], -1);
            continue;
        }
        const glm::dvec3 p = surfaces.worldPosition[i] - offset;
        const glm::dvec3& n = surfaces.worldNormal[i];
        if (surfaces.instance[i] == test::kPlaneInstance) {
            ++plane;
            // Only the camera-relative part was a float (|.| < 20 here): ~1e-6 off at most.
            ASSERT_NEAR(p.y, 0.0, 1e-4) << "pixel " << i;
            ASSERT_GT(n.y, 0.9999) << "pixel " << i;
        } else {
            ASSERT_EQ(surfaces.instance[i], test::kBoxInstance);
            ++box;
            // On the box's surface: inside its bounds, on one face, normal along that face.
            const glm::dvec3 local = p - glm::dvec3(0.0, 2.0, 0.0);
            const glm::dvec3 distance = glm::abs(local);
            ASSERT_LE(std::max({distance.x, distance.y, distance.z}), 1.0 + 1e-4);
            ASSERT_NEAR(std::max({distance.x, distance.y, distance.z}), 1.0, 1e-4);
            ASSERT_NEAR(glm::length(n), 1.0, 1e-9);
            ASSERT_NEAR(glm::dot(n, local), std::max({distance.x, distance.y, distance.z}), 1e-4)
                << "the normal points out of the face the pixel shows";
        }
    }
    // The frame shows plane, box and sky; the box from above and the side.
    EXPECT_GT(plane, 20000u);
    EXPECT_GT(box, 1000u);
    EXPECT_GT(background, 1000u);
}

INSTANTIATE_TEST_SUITE_P(Offsets, SurfaceCaptureTest, ::testing::Values(0.0, 1.0e6),
                         [](const auto& info) { return info.param == 0.0 ? "AtOrigin" : "At1e6"; });

class SurfaceCaptureGlTest : public test::TruthGlTest {};

TEST_F(SurfaceCaptureGlTest, DoubleSidedBackFacesFaceTheCamera) {
    // The plane seen from below: culled when single-sided, its flipped face when double-sided.
    engine::Scene scene = test::boxOverPlane(engine::Light::Type::Spot);
    scene.nodes[1].mesh = -1;  // no box
    scene.updateWorldTransforms();
    engine::FrameCamera below = test::sideCamera(64, 48);
    below.eyeToWorld = glm::inverse(glm::lookAt(glm::dvec3(1, -6, 2), glm::dvec3(0.0),
                                                glm::dvec3(0, 1, 0)));
    {
        const engine::SceneGpu gpu(scene);
        const SurfaceBuffer surfaces = SurfaceCapture().capture(scene, gpu, below);
        for (std::uint8_t c : surfaces.covered) ASSERT_EQ(c, 0);
    }
    scene.materials.push_back(engine::Material{});
    scene.materials[0].doubleSided = true;
    scene.meshes[0].primitives[0].material = 0;
    const engine::SceneGpu gpu(scene);
    const SurfaceBuffer surfaces = SurfaceCapture().capture(scene, gpu, below);
    std::size_t covered = 0;
    for (std::size_t i = 0; i < surfaces.pixelCount(); ++i) {
        if (!surfaces.covered[i]) continue;
        ++covered;
        ASSERT_LT(surfaces.worldNormal[i].y, -0.9999) << "pixel " << i;
    }
    EXPECT_GT(covered, 64u * 48u / 2);
}

} // namespace
} // namespace truth
