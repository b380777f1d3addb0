#include "game/interaction/mouse_hands.h"

#include <algorithm>
#include <cmath>

#include "engine/physics/raycast.h"
#include "game/world.h"

namespace boxing {

namespace {
Eigen::Vector3d v3(const glm::vec3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }
Eigen::Vector3d forward_of(const eng::render::Camera& c) { return (v3(c.target) - v3(c.eye)).normalized(); }
}  // namespace

CameraRay camera_ray(const eng::render::Camera& c, double px, double py, double width, double height) {
  const Eigen::Vector3d f = forward_of(c);
  const Eigen::Vector3d r = f.cross(v3(c.up)).normalized();
  const Eigen::Vector3d u = r.cross(f);
  const double t = std::tan(0.5 * c.fov_y_deg * M_PI / 180.0), aspect = width / std::max(1.0, height);
  const double nx = 2.0 * (px + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (py + 0.5) / height;
  return {v3(c.eye), (f + nx * t * aspect * r + ny * t * u).normalized()};
}

bool world_to_pixel(const eng::render::Camera& c, const Eigen::Vector3d& p, double width, double height, double& px,
                    double& py) {
  const Eigen::Vector3d f = forward_of(c);
  const Eigen::Vector3d r = f.cross(v3(c.up)).normalized();
  const Eigen::Vector3d u = r.cross(f);
  const Eigen::Vector3d d = p - v3(c.eye);
  const double z = d.dot(f);
  if (z <= 1e-9) return false;
  const double t = std::tan(0.5 * c.fov_y_deg * M_PI / 180.0), aspect = width / std::max(1.0, height);
  const double nx = d.dot(r) / (z * t * aspect), ny = d.dot(u) / (z * t);
  px = 0.5 * (nx + 1.0) * width - 0.5;
  py = 0.5 * (1.0 - ny) * height - 0.5;
  return true;
}

bool hands_press(World& w, MouseHands& h, const CameraRay& ray, const eng::render::Camera& c, bool strong) {
  const Pick p = interaction_pick(w, ray.origin, ray.dir);
  if (p.body < 0) return false;
  h.held = true;
  h.depth = (p.point - ray.origin).dot(forward_of(c));
  h.last_target = p.point;
  interaction_submit(w, grab_event(w, p, strong));
  return true;
}

void hands_drag(World& w, MouseHands& h, const CameraRay& ray, const eng::render::Camera& c, double wheel) {
  if (!h.held) return;
  const Eigen::Vector3d f = forward_of(c);
  h.depth = std::clamp(h.depth + 0.1 * wheel, 0.3, 30.0);
  const double along = ray.dir.dot(f);
  if (along < 1e-3) return;
  const Eigen::Vector3d target = ray.origin + ray.dir * (h.depth / along);
  if ((target - h.last_target).norm() < 1e-6) return;
  h.last_target = target;
  InputEvent e;
  e.kind = InputKind::Move;
  e.vec = target;
  interaction_submit(w, e);
}

void hands_release(World& w, MouseHands& h) {
  if (!h.held) return;
  h.held = false;
  InputEvent e;
  e.kind = InputKind::Release;
  interaction_submit(w, e);
}

InputEvent throw_from_camera(const World& w, const CameraRay& ray, ObjectKind kind) {
  const double speed = kind == ObjectKind::Ball ? 10.0 : 8.0;
  const eng::physics::RayHit hit = eng::physics::raycast(w.model, w.data, ray.origin, ray.dir, 30.0);
  const double distance = hit.hit ? hit.distance : 5.0;
  // Start a little in front of the eye (so the object is seen leaving), aimed along the ray with the drop cancelled.
  const double start = std::min(0.6, 0.5 * distance);
  const double T = std::max(0.05, (distance - start) / speed);
  InputEvent e;
  e.kind = InputKind::Throw;
  e.object_kind = kind;
  e.from = ray.origin + start * ray.dir;
  e.velocity = speed * ray.dir + Eigen::Vector3d(0.0, 0.0, 0.5 * 9.81 * T);
  return e;
}

}  // namespace boxing
