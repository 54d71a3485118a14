#pragma once
// The pinhole camera: a position and an orientation (yaw about world y, then pitch about the
// camera's right axis) and a vertical field of view. With yaw = pitch = 0 it looks along +z with
// +y up; world space is right-handed, so the image's right is -x.

#include "ray.h"
#include "ray_packet.h"

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace raylab {

// The lab's camera: focal length f = image height in pixels, i.e. 2*atan(1/2) = 53.13 degrees.
inline constexpr float kLabVerticalFovDegrees = 53.130102354155978f;

struct Camera {
    glm::vec3 position{0.0f, 0.0f, -3.0f};
    float yawDegrees = 0.0f;   // positive turns the view to the left (counter-clockwise from above)
    float pitchDegrees = 0.0f; // positive looks up; kept within (-90, 90)
    float verticalFovDegrees = kLabVerticalFovDegrees; // in (0, 180)

    bool operator==(const Camera&) const = default;
};

// Columns: the camera's right, up and forward axes in world space (orthonormal).
glm::mat3 worldFromCamera(const Camera& camera);

// The unit vector the camera looks along.
glm::vec3 forwardOf(const Camera& camera);

// Yaw and pitch that make the camera at its position look at target (unchanged when they coincide).
void lookAt(Camera& camera, const glm::vec3& target);

// Moves the camera on the sphere about `pivot` through its position (the orbit of a viewer's
// right drag): its direction to the pivot turns by yawDegrees about world y and pitchDegrees
// up, the distance is kept, and the camera looks at the pivot. The pitch stays within +-85
// degrees. A camera at the pivot is left as it is.
void orbitCamera(Camera& camera, const glm::vec3& pivot, float yawDegrees, float pitchDegrees);

// A turntable of `frames` cameras (frames >= 1): frame k is `start` turned rigidly by 360 k /
// frames degrees about the vertical line through `centre` (position and yaw together; pitch and
// field of view kept), so the scene seems to spin in front of a still camera.
std::vector<Camera> turntableCameras(const Camera& start, const glm::vec3& centre, int frames);

// Moves the camera along its own right and up axes (world units): a pan.
void panCamera(Camera& camera, float right, float up);

// Focal length in pixels for an image of the given height, and its inverse.
float focalLengthPixels(float verticalFovDegrees, int imageHeight);
float verticalFovFromFocal(float focalPixels, int imageHeight);

// Precomputed per-frame data to turn pixel coordinates into primary rays.
struct PrimaryRays {
    glm::vec3 origin{0.0f};
    glm::vec3 right{0.0f}, up{0.0f}, forward{0.0f};
    float halfWidth = 0.0f, halfHeight = 0.0f, focal = 1.0f;

    PrimaryRays(const Camera& camera, int width, int height);

    // The ray through image point (px, py) in pixel units, y counting down from the top; the
    // pixel (x, y)'s centre is (x + 0.5, y + 0.5). The direction is unit length.
    Ray through(float px, float py) const;

    // Lane i of rays = through(px[i], py[i]) bit for bit, for i < count <= 8, and rays.lanes =
    // those lanes (8 lanes at once where the CPU has AVX2). px and py are read for i < count only.
    void through8(const float* px, const float* py, int count, RayPacket& rays) const;

    // The inverse of through(), for drawing world points over the picture. cameraFrom: a world
    // point in the camera's frame (x along right, y along up, z along forward: z is the depth in
    // world units, > 0 in front of the camera). imageFrom: where a camera-frame point with z > 0
    // is seen, in pixel units, y counting down: through(imageFrom(c)) points at c.
    glm::vec3 cameraFrom(const glm::vec3& world) const;
    glm::vec2 imageFrom(const glm::vec3& cameraPoint) const;
};

} // namespace raylab
