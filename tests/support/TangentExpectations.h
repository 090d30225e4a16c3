#pragma once
// A tangent as Primitive::tangents holds it, checked against the expected direction (to
// 1e-6: the float rounding of a unit vector computed in double) and exact sign.
#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace engine::test {

inline void expectTangent(const glm::vec4& actual, const glm::vec3& xyz, float w, const char* where = "") {
    EXPECT_NEAR(actual.x, xyz.x, 1e-6f) << where;
    EXPECT_NEAR(actual.y, xyz.y, 1e-6f) << where;
    EXPECT_NEAR(actual.z, xyz.z, 1e-6f) << where;
    EXPECT_EQ(actual.w, w) << where;
}

} // namespace engine::test
