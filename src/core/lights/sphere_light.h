#pragma once
// The lab's light with a size: a sphere of radius r and total power P, emitting uniformly from
// its surface (radiance Le = P / (4 pi^2 r^2) per channel). Seen from a point outside it, it lights
// a surface facing it fully exactly as a point light of power P at its centre would; a finite
// radius softens shadows and the terminator.

#include "lights/point_light.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raylab {

// One sample of D at `point` (facing normal nhat) from settings.light: a direction drawn
// uniformly from the cone of directions that see the sphere (u in [0, 1)^2), the estimate
// Le * max(w . nhat, 0) / pdf(w), and the shadow ray to the sphere's surface along w
// (eps < t < distance to the surface - eps). Its mean over u is the irradiance from the sphere.
// Radius 0 is lightAt(settings, point, nhat) exactly, whatever u; a point inside the sphere gets
// no light.
LightSample sampleSphereLight(const RenderSettings& settings, const glm::vec3& point,
                              const glm::vec3& facingNormal, glm::vec2 u);

} // namespace raylab
