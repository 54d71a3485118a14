#pragma once
// What the lab's keys, the mouse drag and the scroll wheel do to the camera and the light.
// Distances are in world units: `step` is core's navigationStep(scene bounds), 0.1 for the box.

#include "core/render_settings.h"

namespace raylab::viewer {

enum class NavAction {
    CameraForward, // Up: along the view direction
    CameraBack,    // Down
    TurnLeft,      // Left: yaw up by kTurnStepDegrees per step
    TurnRight,     // Right
    LightForward,  // W: along the view direction projected on the ground (xz) plane
    LightBack,     // S
    LightLeft,     // A: along the camera's horizontal left
    LightRight,    // D
    LightDown,     // Q: along world -y
    LightUp,       // E
};

inline constexpr float kTurnStepDegrees = 5.0f;
inline constexpr float kMaxPitchDegrees = 89.0f;

// Moves what `action` moves by `steps` steps (fractional while a key is held, held_keys.h): by
// steps * step world units, or, turning, by steps * kTurnStepDegrees. One key press is one step.
void applyNavAction(NavAction action, float step, RenderSettings& settings, float steps = 1.0f);

// Turns the camera: yaw (positive = left) wrapped to (-180, 180], pitch (positive = up) clamped to
// +-kMaxPitchDegrees.
void turnCamera(float yawDegrees, float pitchDegrees, RenderSettings& settings);

// Moves the camera along its view direction (negative = back).
void moveCamera(float distance, RenderSettings& settings);

} // namespace raylab::viewer
