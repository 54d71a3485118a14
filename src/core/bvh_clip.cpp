#include "bvh_clip.h"

#include <algorithm>

namespace raylab {

void splitBox(const Triangle& t, const Aabb& box, int axis, float position, float slack, Aabb& left,
              Aabb& right) {
    const glm::vec3 v[3] = {t.v0, t.v1, t.v2};
    left = Aabb{};
    right = Aabb{};
    for (int i = 0; i < 3; ++i) {
        const glm::vec3& p = v[i];
        const glm::vec3& q = v[(i + 1) % 3];
        if (p[axis] <= position) {
            left.extend(p);
        }
        if (p[axis] >= position) {
            right.extend(p);
        }
        if ((p[axis] < position && q[axis] > position) ||
            (p[axis] > position && q[axis] < position)) {
            glm::vec3 x = p + (position - p[axis]) / (q[axis] - p[axis]) * (q - p);
            x[axis] = position;
            left.extend(x);
            right.extend(x);
        }
    }
    for (Aabb* b : {&left, &right}) {
        if (b->empty()) {
            continue;
        }
        b->lower = glm::max(b->lower - glm::vec3(slack), box.lower);
        b->upper = glm::min(b->upper + glm::vec3(slack), box.upper);
    }
    left.upper[axis] = std::min(left.upper[axis], position);
    right.lower[axis] = std::max(right.lower[axis], position);
}

} // namespace raylab
