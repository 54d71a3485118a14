#pragma once
// The lab's point light: D = P * max(rhat . nhat, 0) / (4 pi |r|^2) at a point with facing normal
// nhat, r running from the point to the light, and the shadow ray that decides whether D arrives.

#include "ray.h"
#include "render_settings.h"

#include <glm/vec3.hpp>

namespace raylab {

// The direct light D at a point before the shadow test, and the shadow ray that decides it.
struct LightSample {
    glm::vec3 direct{0.0f};      // D when unshadowed; 0 when facing away or at the light
    bool needsShadowRay = false; // settings.shadows and direct may be non-zero
    Ray shadowRay;               // towards the light, eps < t < |r| - eps (when needed)
};

// The point light of settings.light (its radius is not read).
LightSample lightAt(const RenderSettings& settings, const glm::vec3& point,
                    const glm::vec3& facingNormal);

} // namespace raylab
