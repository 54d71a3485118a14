#include "bvh/build/bvh_clip.h"

#include "bvh/build/bvh_build_clip.h"

namespace raylab {

void splitBox(const Triangle& t, const Aabb& box, int axis, float position, float slack, Aabb& left,
              Aabb& right) {
    SseBox b, l, r;
    b.lower = _mm_setr_ps(box.lower.x, box.lower.y, box.lower.z, 0.0f);
    b.upper = _mm_setr_ps(box.upper.x, box.upper.y, box.upper.z, 0.0f);
    splitBoxSse(t, b, axis, position, slack, l, r);
    left = l.toAabb();
    right = r.toAabb();
}

} // namespace raylab
