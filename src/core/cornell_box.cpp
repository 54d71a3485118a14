#include "cornell_box.h"

#include <array>

namespace raylab {

glm::vec3 labColor(LabColor color) {
    switch (color) {
    case LabColor::Red: return {0.75f, 0.15f, 0.15f};
    case LabColor::Yellow: return {0.75f, 0.75f, 0.15f};
    case LabColor::Green: return {0.15f, 0.75f, 0.15f};
    case LabColor::Cyan: return {0.15f, 0.75f, 0.75f};
    case LabColor::Blue: return {0.15f, 0.15f, 0.75f};
    case LabColor::Purple: return {0.75f, 0.15f, 0.75f};
    case LabColor::White: return {0.75f, 0.75f, 0.75f};
    }
    return glm::vec3(0.75f);
}

namespace {

constexpr float kL = 555.0f; // the lab's box side, in the lab's units

// The eight corners A..H of an axis-aligned box or block in the lab's units, scaled into
// [-1, 1]^3 with v * 2/L - 1.
struct Corners {
    glm::vec3 a, b, c, d, e, f, g, h;
};

glm::vec3 scaled(glm::vec3 v) { return v * (2.0f / kL) - glm::vec3(1.0f); }

Corners scaledCorners(const std::array<glm::vec3, 8>& lab) {
    return {scaled(lab[0]), scaled(lab[1]), scaled(lab[2]), scaled(lab[3]),
            scaled(lab[4]), scaled(lab[5]), scaled(lab[6]), scaled(lab[7])};
}

// The lab's ten triangles of a block (front, front, back, left, top; two each).
void addBlock(Scene& scene, const Corners& k, uint32_t material) {
    const std::array<std::array<glm::vec3, 3>, 10> faces{{
        {k.e, k.b, k.a},
        {k.e, k.f, k.b},
        {k.f, k.d, k.b},
        {k.f, k.h, k.d},
        {k.h, k.c, k.d},
        {k.h, k.g, k.c},
        {k.g, k.e, k.c},
        {k.e, k.a, k.c},
        {k.g, k.f, k.e},
        {k.g, k.h, k.f},
    }};
    for (const auto& f : faces) {
        scene.triangles.push_back({f[0], f[1], f[2], material});
    }
}

} // namespace

Scene makeCornellBox() {
    Scene scene;
    scene.name = std::string(kLabBoxName);
    const std::array<std::pair<const char*, LabColor>, 7> materials{{
        {"red", LabColor::Red},
        {"yellow", LabColor::Yellow},
        {"green", LabColor::Green},
        {"cyan", LabColor::Cyan},
        {"blue", LabColor::Blue},
        {"purple", LabColor::Purple},
        {"white", LabColor::White},
    }};
    for (const auto& [name, color] : materials) {
        scene.materials.push_back({name, labColor(color)});
    }
    auto id = [](LabColor c) { return static_cast<uint32_t>(c); };

    const Corners room = scaledCorners({{{kL, 0, 0},
                                         {0, 0, 0},
                                         {kL, 0, kL},
                                         {0, 0, kL},
                                         {kL, kL, 0},
                                         {0, kL, 0},
                                         {kL, kL, kL},
                                         {0, kL, kL}}});
    const auto add = [&](glm::vec3 p, glm::vec3 q, glm::vec3 r, LabColor c) {
        scene.triangles.push_back({p, q, r, id(c)});
    };
    add(room.c, room.b, room.a, LabColor::Green); // floor
    add(room.c, room.d, room.b, LabColor::Green);
    add(room.a, room.e, room.c, LabColor::Purple); // left wall
    add(room.c, room.e, room.g, LabColor::Purple);
    add(room.f, room.b, room.d, LabColor::Yellow); // right wall
    add(room.h, room.f, room.d, LabColor::Yellow);
    add(room.e, room.f, room.g, LabColor::Cyan); // ceiling
    add(room.f, room.h, room.g, LabColor::Cyan);
    add(room.g, room.d, room.c, LabColor::White); // back wall
    add(room.g, room.h, room.d, LabColor::White);

    addBlock(scene,
             scaledCorners({{{290, 0, 114},
                             {130, 0, 65},
                             {240, 0, 272},
                             {82, 0, 225},
                             {290, 165, 114},
                             {130, 165, 65},
                             {240, 165, 272},
                             {82, 165, 225}}}),
             id(LabColor::Red)); // short block
    addBlock(scene,
             scaledCorners({{{423, 0, 247},
                             {265, 0, 296},
                             {472, 0, 406},
                             {314, 0, 456},
                             {423, 330, 247},
                             {265, 330, 296},
                             {472, 330, 406},
                             {314, 330, 456}}}),
             id(LabColor::Blue)); // tall block
    return scene;
}

} // namespace raylab
