#pragma once
// The mouse's hands in the window (MuJoCo simulate's perturbation, the Box2D / Jolt samples' mouse joint): a left
// press picks the body under the cursor (ray cast) and grabs that point; dragging moves the target on the plane
// through the grabbed point facing the camera; the wheel moves that plane nearer or farther; a held Shift grabs
// with the strong spring. Everything it does becomes an InputEvent (interaction.h), applied by the world at the
// next physics step and recorded with --record.
#include <Eigen/Core>
#include <optional>

#include "engine/render/frame.h"
#include "game/interaction/interaction.h"

namespace boxing {

struct World;

// A ray through a pixel of the camera's image (pixels from the top-left; the renderer's projection: frame_data.cpp).
struct CameraRay {
  Eigen::Vector3d origin, dir;  // dir unit
};
CameraRay camera_ray(const eng::render::Camera& c, double px, double py, double width, double height);
// The inverse: the pixel a world point projects to (false when it is behind the camera).
bool world_to_pixel(const eng::render::Camera& c, const Eigen::Vector3d& p, double width, double height, double& px,
                    double& py);

struct MouseHands {
  bool held = false;     // the left button holds a body
  double depth = 0.0;    // m along the camera's forward axis: the drag plane
  Eigen::Vector3d last_target = Eigen::Vector3d::Zero();
};

// Left press over the scene: grabs what is under the cursor (returns whether something was grabbed).
bool hands_press(World& w, MouseHands& h, const CameraRay& ray, const eng::render::Camera& c, bool strong);
// While held: the target where the cursor's ray meets the drag plane, moved by `wheel` notches (0.1 m each, +
// away from the camera). Submits a move event when the target changed.
void hands_drag(World& w, MouseHands& h, const CameraRay& ray, const eng::render::Camera& c, double wheel);
void hands_release(World& w, MouseHands& h);
// A throw from the camera toward the cursor: the launch speed along the ray, plus the vertical speed that cancels the
// drop over the flight to whatever the ray meets (or 5 m).
InputEvent throw_from_camera(const World& w, const CameraRay& ray, ObjectKind kind);

}  // namespace boxing
