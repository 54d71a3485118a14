#pragma once
// isValidTriangle (scene.h) on SSE2 registers, for loops over every triangle of a scene (the
// build's records): one rule, the same decision bit for bit.

#include "scene.h"
#include "sse_xyz.h"

#include <cmath>
#include <cstddef>
#include <emmintrin.h>
#include <limits>

namespace raylab {

// The triangle's vertices in lanes x, y, z, lane 3 zero: loaded, it holds the next member, and
// v2's is the material index, whose bits are a denormal float (arithmetic on denormals can
// cost a hundred cycles).
struct TriangleLanes {
    __m128 v0, v1, v2;
    explicit TriangleLanes(const Triangle& t)
        : v0(xyzOf(_mm_loadu_ps(&t.v0.x))), v1(xyzOf(_mm_loadu_ps(&t.v1.x))),
          v2(xyzOf(_mm_loadu_ps(&t.v2.x))) {
        static_assert(offsetof(Triangle, v1) == 12 && offsetof(Triangle, v2) == 24 &&
                      sizeof(Triangle) >= 40);
    }
};

// Every coordinate finite, and the squared length of cross(v1 - v0, v2 - v0) positive and
// finite: the cross product and its square computed as glm::cross and glm::dot do, in the same
// order, so the same floats.
inline bool isValidTriangle(const TriangleLanes& t) {
    const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
    const __m128 infinity = _mm_set1_ps(std::numeric_limits<float>::infinity());
    const auto finite = [&](__m128 v) { // lanes below infinity; NaN is not
        return _mm_movemask_ps(_mm_cmplt_ps(_mm_and_ps(v, magnitude), infinity)) & 7;
    };
    if ((finite(t.v0) & finite(t.v1) & finite(t.v2)) != 7) {
        return false;
    }
    const __m128 a = _mm_sub_ps(t.v1, t.v0), b = _mm_sub_ps(t.v2, t.v0);
    const auto yzx = [](__m128 v) { return _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 0, 2, 1)); };
    const auto zxy = [](__m128 v) { return _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 1, 0, 2)); };
    // cross(a, b) = (a.y b.z - b.y a.z, a.z b.x - b.z a.x, a.x b.y - b.x a.y)
    const __m128 n = _mm_sub_ps(_mm_mul_ps(yzx(a), zxy(b)), _mm_mul_ps(yzx(b), zxy(a)));
    const __m128 squares = _mm_mul_ps(n, n);
    const float area2 =
        (_mm_cvtss_f32(squares) + _mm_cvtss_f32(yzx(squares))) + _mm_cvtss_f32(zxy(squares));
    return area2 > 0.0f && std::isfinite(area2);
}

} // namespace raylab
