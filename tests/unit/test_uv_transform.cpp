// UvTransform::matrix (KHR_texture_transform) against the extension's own example.
#include "engine/scene/Scene.h"

#include <gtest/gtest.h>

#include <numbers>

namespace {

void expectMaps(const engine::UvTransform& transform, glm::vec2 from, glm::vec2 to) {
    const glm::vec2 got = transform.apply(from);
    EXPECT_NEAR(got.x, to.x, 1e-6f) << "u of (" << from.x << ", " << from.y << ")";
    EXPECT_NEAR(got.y, to.y, 1e-6f) << "v of (" << from.x << ", " << from.y << ")";
}

// The README of KHR_texture_transform: offset [0, 1], rotation pi/2, scale [0.5, 0.5]
// shows the lower-left quadrant of the image, turned.
TEST(UvTransform, MatchesTheExtensionsExample) {
    engine::UvTransform transform;
    transform.offset = {0.0f, 1.0f};
    transform.rotation = static_cast<float>(std::numbers::pi / 2);
    transform.scale = {0.5f, 0.5f};
    expectMaps(transform, {0, 0}, {0, 1});
    expectMaps(transform, {1, 0}, {0, 0.5f});
    expectMaps(transform, {1, 1}, {0.5f, 0.5f});
    expectMaps(transform, {0, 1}, {0.5f, 1});
}

TEST(UvTransform, DefaultIsTheIdentity) {
    const engine::UvTransform identity;
    EXPECT_EQ(identity.matrix(), glm::mat3(1.0f));
    expectMaps(identity, {0.25f, 0.75f}, {0.25f, 0.75f});
}

// T * R * S: scale first, then rotate, then offset (not the other way round).
TEST(UvTransform, ScalesThenRotatesThenOffsets) {
    engine::UvTransform transform;
    transform.offset = {10.0f, 20.0f};
    transform.scale = {2.0f, 3.0f};
    expectMaps(transform, {1, 1}, {12, 23});
    transform.rotation = static_cast<float>(std::numbers::pi);
    expectMaps(transform, {1, 1}, {8, 17});
}

} // namespace
