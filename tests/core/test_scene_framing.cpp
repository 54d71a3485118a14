// Framing a mesh: the whole bounding box in view, the light above and in front, scaled epsilon.

#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/scene_framing.h"
#include "test_meshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace raylab {
namespace {

// Projects p with the camera; true when it lands inside the image.
bool inView(const RenderSettings& s, const glm::vec3& p) {
    const glm::mat3 basis = worldFromCamera(s.camera);
    const glm::vec3 d = p - s.camera.position;
    const float z = glm::dot(d, basis[2]);
    if (z <= 0.0f) {
        return false;
    }
    const float f = focalLengthPixels(s.camera.verticalFovDegrees, s.height);
    const float px = glm::dot(d, basis[0]) / z * f;
    const float py = glm::dot(d, basis[1]) / z * f;
    return std::abs(px) <= 0.5f * static_cast<float>(s.width) &&
           std::abs(py) <= 0.5f * static_cast<float>(s.height);
}

TEST(SceneFraming, EveryCornerOfTheBoundsIsInViewForAnyAspect) {
    Scene scene = test::makePerturbedSphere(8, 16, 0.1f, 0.0f, 1);
    for (Triangle& t : scene.triangles) { // a small, off-centre, stretched mesh like the bunny
        for (glm::vec3* v : {&t.v0, &t.v1, &t.v2}) {
            *v = *v * glm::vec3(1.0f, 0.5f, 2.0f) + glm::vec3(-0.02f, 0.11f, 0.0f);
        }
    }
    const Aabb b = scene.bounds();
    for (const auto& [w, h] : {std::pair{500, 500}, {1280, 720}, {200, 800}}) {
        RenderSettings s;
        s.width = w;
        s.height = h;
        frameScene(scene, s);
        EXPECT_EQ(validate(s), "");
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner{(i & 1) ? b.upper.x : b.lower.x, (i & 2) ? b.upper.y : b.lower.y,
                                   (i & 4) ? b.upper.z : b.lower.z};
            EXPECT_TRUE(inView(s, corner)) << w << "x" << h << " corner " << i;
        }
        EXPECT_LT(s.camera.position.z, b.lower.z); // in front, looking along +z
        EXPECT_EQ(forwardOf(s.camera), glm::vec3(0.0f, 0.0f, 1.0f));
        EXPECT_GT(s.light.position.y, b.center().y); // above
        EXPECT_LT(s.light.position.z, b.lower.z);    // in front
        EXPECT_GT(s.light.intensity, 0.0f);
    }
}

TEST(SceneFraming, EpsilonAndStepsScaleWithTheScene) {
    const Aabb lab = makeCornellBox().bounds();
    EXPECT_NEAR(scaledShadowEpsilon(lab), 1e-3f, 1e-9f);
    EXPECT_NEAR(navigationStep(lab), 0.1f, 1e-7f);
    Aabb tenTimes;
    tenTimes.extend(glm::vec3(-10.0f));
    tenTimes.extend(glm::vec3(10.0f));
    EXPECT_NEAR(scaledShadowEpsilon(tenTimes), 1e-2f, 1e-8f);
    EXPECT_NEAR(scaledShadowEpsilon(Aabb{}), 1e-3f, 1e-9f) << "empty: the lab's value";
}

TEST(SceneFraming, AnEmptySceneLeavesTheSettingsAlone) {
    RenderSettings s;
    const RenderSettings before = s;
    frameScene(Scene{}, s);
    EXPECT_EQ(s.camera.position, before.camera.position);
    EXPECT_EQ(s.light.position, before.light.position);
}

} // namespace
} // namespace raylab
