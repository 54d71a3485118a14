#include "ray_overlay_geometry.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace raylab::viewer {

std::vector<WorldSegment> inspectionSegments(const PixelInspection& inspection,
                                             const glm::vec3& rayOrigin) {
    std::vector<WorldSegment> segments;
    if (!inspection.hit) {
        return segments;
    }
    segments.push_back({rayOrigin, inspection.point, OverlayRay::Camera});
    if (inspection.shadowTested && inspection.distance > 0.0f) {
        const glm::vec3 light = inspection.point + inspection.toLight;
        if (inspection.blocker) {
            const glm::vec3 towards = inspection.toLight / inspection.distance;
            segments.push_back({inspection.point,
                                inspection.point + inspection.blocker->t * towards,
                                OverlayRay::ShadowBlocked});
        } else {
            segments.push_back({inspection.point, light, OverlayRay::ShadowClear});
        }
    }
    for (std::size_t i = 1; i < inspection.path.size(); ++i) {
        segments.push_back(
            {inspection.path[i - 1].point, inspection.path[i].point, OverlayRay::Path});
    }
    return segments;
}

namespace {

// Liang-Barsky: narrows [t0, t1] to where p + t * d satisfies the bound (q - t * r >= 0 in the
// form r * t <= q). False when nothing is left.
bool clipBound(float r, float q, float& t0, float& t1) {
    if (r == 0.0f) {
        return q >= 0.0f;
    }
    const float t = q / r;
    if (r < 0.0f) {
        t0 = std::max(t0, t);
    } else {
        t1 = std::min(t1, t);
    }
    return t0 <= t1;
}

} // namespace

bool projectSegment(const PrimaryRays& rays, int width, int height, float nearDepth,
                    const WorldSegment& segment, ImageSegment& out) {
    glm::vec3 a = rays.cameraFrom(segment.from);
    glm::vec3 b = rays.cameraFrom(segment.to);
    if (a.z < nearDepth && b.z < nearDepth) {
        return false;
    }
    // The part in front of the near plane.
    if (a.z < nearDepth) {
        a += (b - a) * ((nearDepth - a.z) / (b.z - a.z));
        a.z = nearDepth;
    } else if (b.z < nearDepth) {
        b += (a - b) * ((nearDepth - b.z) / (a.z - b.z));
        b.z = nearDepth;
    }
    const glm::vec2 p = rays.imageFrom(a);
    const glm::vec2 d = rays.imageFrom(b) - p;
    // The part inside the picture: 0 <= x <= width, 0 <= y <= height.
    float t0 = 0.0f, t1 = 1.0f;
    if (!clipBound(-d.x, p.x, t0, t1) || !clipBound(d.x, static_cast<float>(width) - p.x, t0, t1) ||
        !clipBound(-d.y, p.y, t0, t1) ||
        !clipBound(d.y, static_cast<float>(height) - p.y, t0, t1)) {
        return false;
    }
    out.from = p + t0 * d;
    out.to = p + t1 * d;
    out.kind = segment.kind;
    return true;
}

std::vector<ImageSegment> projectSegments(const PrimaryRays& rays, int width, int height,
                                          float nearDepth,
                                          const std::vector<WorldSegment>& segments) {
    std::vector<ImageSegment> out;
    for (const WorldSegment& segment : segments) {
        ImageSegment projected;
        if (projectSegment(rays, width, height, nearDepth, segment, projected)) {
            out.push_back(projected);
        }
    }
    return out;
}

glm::vec3 overlayColour(OverlayRay kind) {
    switch (kind) {
    case OverlayRay::Camera: return {0.0f, 1.0f, 0.0f};
    case OverlayRay::ShadowClear: return {1.0f, 1.0f, 0.0f};
    case OverlayRay::ShadowBlocked: return {1.0f, 0.0f, 0.0f};
    case OverlayRay::Path: return {1.0f, 0.0f, 1.0f};
    case OverlayRay::LabCamera: return {1.0f, 1.0f, 1.0f};
    case OverlayRay::Light: return {0.0f, 1.0f, 1.0f};
    }
    return {1.0f, 1.0f, 1.0f};
}

void appendLineQuad(const glm::vec2& a, const glm::vec2& b, float width,
                    std::vector<glm::vec2>& vertices) {
    const glm::vec2 d = b - a;
    const float length = glm::length(d);
    if (!(length >= 1e-3f)) {
        return;
    }
    const glm::vec2 side = glm::vec2(-d.y, d.x) * (0.5f * width / length);
    const glm::vec2 corners[4] = {a - side, b - side, b + side, a + side};
    for (const int i : {0, 1, 2, 0, 2, 3}) {
        vertices.push_back(corners[i]);
    }
}

} // namespace raylab::viewer
