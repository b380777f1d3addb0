// The mouse's hands without a window (game/interaction/mouse_hands.h): the camera ray through a pixel and its inverse
// agree with the renderer's projection; a press on a boxer's head grabs that bone, the drag plane faces the camera,
// the release lets go; a throw from the camera reaches what the cursor points at.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "game/cli.h"
#include "game/interaction/mouse_hands.h"
#include "game/scene_view.h"
#include "game/world.h"

namespace {
std::unique_ptr<boxing::World> stand(int seed) {
  auto o = boxing::parse_cli({"--scenario", "stand", "--seed", std::to_string(seed)});
  auto w = boxing::make_world(*o);
  EXPECT_TRUE(w.ok());
  return std::move(*w);
}
}  // namespace

// The renderer's view-projection (frame_data.cpp: lookAtRH, perspectiveRH_ZO, Vulkan's y flip) maps the point
// world_to_pixel names to that pixel, and the ray through the pixel passes through the point.
TEST(MouseHands, CameraRayAndWorldToPixelAgreeWithTheRenderersProjection) {
  eng::render::Camera c;
  c.eye = {2.6f, -4.4f, 2.3f};
  c.target = {0.0f, 0.0f, 0.85f};
  const double W = 1280, H = 720;
  const glm::mat4 view = glm::lookAtRH(c.eye, c.target, c.up);
  glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(c.fov_y_deg), float(W / H), c.znear, c.zfar);
  proj[1][1] *= -1.0f;
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.5, 0.3, 1.6), Eigen::Vector3d(-1, 1, 0.2)}) {
    double px, py;
    ASSERT_TRUE(boxing::world_to_pixel(c, p, W, H, px, py));
    const glm::vec4 clip = proj * view * glm::vec4(float(p.x()), float(p.y()), float(p.z()), 1.0f);
    // NDC -> pixel centres: x = (ndc + 1) W / 2 - 0.5 (Vulkan's viewport, y down after the flip)
    EXPECT_NEAR(px, (clip.x / clip.w + 1.0) * 0.5 * W - 0.5, 0.05);
    EXPECT_NEAR(py, (clip.y / clip.w + 1.0) * 0.5 * H - 0.5, 0.05);
    const boxing::CameraRay ray = boxing::camera_ray(c, px, py, W, H);
    const Eigen::Vector3d to_p = p - ray.origin;
    EXPECT_NEAR((to_p - ray.dir * to_p.dot(ray.dir)).norm(), 0.0, 1e-9);
  }
}

TEST(MouseHands, APressOnTheHeadGrabsItTheDragPullsItAndTheReleaseLetsGo) {
  auto w = stand(1);
  for (int s = 0; s < 240; ++s) boxing::step_world(*w);  // a second to settle in guard
  const eng::render::Camera cam = boxing::camera_preset("side", *w);
  const int head = w->boxers[0].bodies.body[w->boxer_desc.skeleton.find("head")];
  const Eigen::Vector3d p0 = w->data.com_world[head];
  double px, py;
  ASSERT_TRUE(boxing::world_to_pixel(cam, p0, 1280, 720, px, py));
  boxing::MouseHands hands;
  ASSERT_TRUE(boxing::hands_press(*w, hands, boxing::camera_ray(cam, px, py, 1280, 720), cam, false));
  for (int s = 0; s < 4; ++s) boxing::step_world(*w);
  ASSERT_TRUE(w->interaction->drags[0].active);
  ASSERT_EQ(w->interaction->drag_log.size(), 1u);
  EXPECT_EQ(w->interaction->drag_log[0].boxer, 0);
  EXPECT_EQ(w->boxer_desc.skeleton.name[w->interaction->drag_log[0].bone], "head");
  // The cursor 70 px (0.34 m at the head) to the right (the side camera looks along +y: screen right is +x) for a
  // second.
  for (int f = 0; f < 60; ++f) {
    boxing::hands_drag(*w, hands, boxing::camera_ray(cam, px + 70, py, 1280, 720), cam, 0.0);
    for (int s = 0; s < 4; ++s) boxing::step_world(*w);
  }
  const Eigen::Vector3d moved = w->data.com_world[head] - p0;
  EXPECT_GT(moved.x(), 0.2) << moved.transpose();
  // The target stayed on the plane through the grabbed point facing the camera (the side camera's forward is +y).
  EXPECT_NEAR(w->interaction->drags[0].goal.y(), w->interaction->drags[0].start.y(), 0.05);
  boxing::hands_release(*w, hands);
  for (int s = 0; s < 4 * 60 * 4; ++s) boxing::step_world(*w);
  EXPECT_FALSE(w->interaction->drags[0].active);
  EXPECT_FALSE(w->boxers[0].metrics.fell);
  EXPECT_LT((w->data.com_world[head] - p0).norm(), 0.1);  // and back near where it was
}

TEST(MouseHands, ABallThrownFromTheCameraHitsTheBoxerUnderTheCursor) {
  auto w = stand(2);
  const eng::render::Camera cam = boxing::camera_preset("default", *w);
  const int chest = w->boxers[1].bodies.body[w->boxer_desc.skeleton.find("chest")];
  double px, py;
  ASSERT_TRUE(boxing::world_to_pixel(cam, w->data.com_world[chest], 1280, 720, px, py));
  boxing::interaction_submit(
      *w, boxing::throw_from_camera(*w, boxing::camera_ray(cam, px, py, 1280, 720), boxing::ObjectKind::Ball));
  for (int s = 0; s < 240; ++s) boxing::step_world(*w);
  ASSERT_FALSE(w->interaction->object_hits.empty());
  EXPECT_EQ(w->interaction->object_hits[0].boxer, 1);
  EXPECT_EQ(w->interaction->object_hits[0].kind, boxing::ObjectKind::Ball);
}
