// Framing a mesh: the whole bounding box in view, the light above and in front, scaled epsilon.

#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/scene_framing.h"
#include "core/scene_view_side.h"
#include "test_meshes.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <utility>

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

// The lab's box turned by `quarterTurns` x 90 degrees about y (yaw, camera.h): its opening,
// towards -z in the lab, then faces away from the direction (sin yaw, 0, cos yaw).
Scene turnedLabBox(int quarterTurns, bool flipWinding) {
    Scene scene = makeCornellBox();
    const auto turn = [quarterTurns](glm::vec3 p) {
        for (int k = 0; k < quarterTurns; ++k) {
            p = glm::vec3(p.z, p.y, -p.x); // exactly 90 degrees: x' = z, z' = -x
        }
        return p;
    };
    for (Triangle& t : scene.triangles) {
        t.v0 = turn(t.v0);
        t.v1 = turn(t.v1);
        t.v2 = turn(t.v2);
        if (flipWinding) {
            std::swap(t.v1, t.v2);
        }
    }
    return scene;
}

TEST(SceneFraming, AnOpenBoxIsSeenThroughItsOpening) {
    const ViewDepths lab = viewDepths(makeCornellBox());
    EXPECT_GT(lab.value[static_cast<int>(ViewSide::AlongPlusZ)], 0.5f);   // into the box
    EXPECT_LT(lab.value[static_cast<int>(ViewSide::AlongMinusZ)], 0.05f); // its back wall
    EXPECT_LT(lab.value[static_cast<int>(ViewSide::AlongPlusX)], 0.05f);  // a side wall
    for (int turns = 0; turns < 4; ++turns) {
        for (bool flip : {false, true}) { // the test does not depend on the winding
            const Scene scene = turnedLabBox(turns, flip);
            const float yaw = 90.0f * static_cast<float>(turns);
            const glm::vec3 inward{std::sin(glm::radians(yaw)), 0.0f, std::cos(glm::radians(yaw))};
            RenderSettings s;
            frameScene(scene, s);
            EXPECT_EQ(validate(s), "");
            EXPECT_NEAR(glm::dot(forwardOf(s.camera), inward), 1.0f, 1e-6f)
                << turns << " quarter turns, flipped " << flip;
            const Aabb b = scene.bounds();
            // Outside the box on the open side, the light above and in front.
            EXPECT_LT(glm::dot(s.camera.position - b.center(), inward), -1.0f) << turns;
            EXPECT_LT(glm::dot(s.light.position - b.center(), inward), -0.5f) << turns;
            EXPECT_GT(s.light.position.y, b.center().y);
            for (int i = 0; i < 8; ++i) {
                const glm::vec3 corner{(i & 1) ? b.upper.x : b.lower.x,
                                       (i & 2) ? b.upper.y : b.lower.y,
                                       (i & 4) ? b.upper.z : b.lower.z};
                EXPECT_TRUE(inView(s, corner)) << turns << " quarter turns, corner " << i;
            }
        }
    }
}

TEST(SceneFraming, ClosedAndFlatScenesKeepTheViewAlongPlusZ) {
    // A closed sphere sees about as deep from every side; a flat triangle facing the view, and
    // one edge-on, see nothing deep. Non-finite triangles are left out.
    Scene flat;
    flat.materials.push_back(Material{});
    flat.triangles.push_back(Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0});
    Scene edgeOn = flat;
    edgeOn.triangles[0] = Triangle{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0};
    Scene broken = turnedLabBox(2, false); // open towards +z: seen along -z
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    broken.triangles.push_back(Triangle{{nan, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, 0});
    // Over half the box's face: counted, its infinite depth would hide the opening.
    broken.triangles.push_back(Triangle{{-1, -1, inf}, {1, -1, 0}, {0, 1, 0}, 0});
    for (const Scene* scene : {&flat, &edgeOn}) {
        EXPECT_EQ(framingSide(*scene), ViewSide::AlongPlusZ);
    }
    EXPECT_EQ(framingSide(test::makePerturbedSphere(8, 16, 0.1f, 0.0f, 1)), ViewSide::AlongPlusZ);
    EXPECT_EQ(framingSide(broken), ViewSide::AlongMinusZ);
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

TEST(PlaceForScene, TheLabsPlacesForTheBoxFramingForAMeshAndGivenFieldsKept) {
    const Scene box = makeCornellBox();
    RenderSettings s;
    s.camera.position = {1.0f, 2.0f, 3.0f};
    s.light.intensity = 3.0f;
    s.shadowEpsilon = 0.5f;
    s.samplesPerPixel = 7;
    RenderSettings placed = s;
    placeForScene(box, true, GivenSettings{}, placed);
    EXPECT_EQ(placed.camera, Camera());
    EXPECT_EQ(placed.light, PointLight());
    EXPECT_EQ(placed.shadowEpsilon, RenderSettings().shadowEpsilon);
    EXPECT_EQ(placed.samplesPerPixel, 7); // other settings kept

    GivenSettings given;
    given.lightIntensity = true;
    given.shadowEpsilon = true;
    Scene mesh = box;
    for (Triangle& t : mesh.triangles) {
        t.v0 *= 10.0f;
        t.v1 *= 10.0f;
        t.v2 *= 10.0f;
    }
    placed = s;
    placeForScene(mesh, false, given, placed);
    RenderSettings framed = s;
    frameScene(mesh, framed);
    EXPECT_EQ(placed.camera, framed.camera);
    EXPECT_EQ(placed.light.position, framed.light.position);
    EXPECT_EQ(placed.light.intensity, 3.0f); // given: kept, not the framed power
    EXPECT_EQ(placed.shadowEpsilon, 0.5f);
    EXPECT_NE(framed.light.intensity, 3.0f);
}

} // namespace
} // namespace raylab
