#pragma once
// splitBox (bvh_clip.h) on SSE registers, for the build's inner loops (internal to core).

#include "bvh/build/bvh_binning.h"
#include "scene.h"

namespace raylab {

// True when the box is empty on x, y or z (lane 3 is ignored).
inline bool isEmpty(const SseBox& b) {
    return (_mm_movemask_ps(_mm_cmpgt_ps(b.lower, b.upper)) & 7) != 0;
}

// splitBox on SSE registers, for the build's inner loops: the same operations in the same order,
// so the same boxes. The vertices' and the box's lane 3 are ignored (and undefined in the
// results); `box` must not be empty.
inline void splitBoxSse(const Triangle& t, const SseBox& box, int axis, float position, float slack,
                        SseBox& left, SseBox& right) {
    const __m128 v[3] = {_mm_loadu_ps(&t.v0.x), _mm_loadu_ps(&t.v1.x), _mm_loadu_ps(&t.v2.x)};
    const float c[3] = {t.v0[axis], t.v1[axis], t.v2[axis]};
    const __m128 plane = _mm_set1_ps(position);
    const __m128 onAxis = axisLane(axis);
    // min(b, a) / max(b, a) as glm::min(a, b) / glm::max(a, b) choose, zeros and NaN included.
    auto extend = [](SseBox& b, __m128 p) {
        b.lower = _mm_min_ps(p, b.lower);
        b.upper = _mm_max_ps(p, b.upper);
    };
    left = SseBox{};
    right = SseBox{};
    for (int i = 0; i < 3; ++i) {
        const int j = i == 2 ? 0 : i + 1;
        if (c[i] <= position) {
            extend(left, v[i]);
        }
        if (c[i] >= position) {
            extend(right, v[i]);
        }
        if ((c[i] < position && c[j] > position) || (c[i] > position && c[j] < position)) {
            const float s = (position - c[i]) / (c[j] - c[i]);
            __m128 x = _mm_add_ps(v[i], _mm_mul_ps(_mm_set1_ps(s), _mm_sub_ps(v[j], v[i])));
            x = withLane(onAxis, plane, x);
            extend(left, x);
            extend(right, x);
        }
    }
    const __m128 widen = _mm_set1_ps(slack);
    for (SseBox* b : {&left, &right}) {
        if (isEmpty(*b)) {
            continue;
        }
        b->lower = _mm_max_ps(box.lower, _mm_sub_ps(b->lower, widen));
        b->upper = _mm_min_ps(box.upper, _mm_add_ps(b->upper, widen));
    }
    // left.upper[axis] = min(left.upper[axis], position), right.lower[axis] likewise with max.
    left.upper = withLane(onAxis, _mm_min_ps(plane, left.upper), left.upper);
    right.lower = withLane(onAxis, _mm_max_ps(plane, right.lower), right.lower);
}

} // namespace raylab
