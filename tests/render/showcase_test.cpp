// Renders a representative game scene to <build>/render_showcase.png for people to look at (and checks it is
// sane). Crates of different heights, two capsule "people", a ghost, debug lines and the overlay.
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include "render/render_fixture.h"
#include "test_paths.h"

using namespace eng::render;

namespace {

FrameDesc showcase(MeshId box, MeshId capsule, MeshId sphere) {
  FrameDesc f = render_test::basic_frame();
  auto crate = [&](glm::vec3 p, glm::vec3 half, float yaw, glm::vec3 color) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), p + glm::vec3(0, 0, half.z));
    m = glm::rotate(m, yaw, glm::vec3(0, 0, 1));
    m = glm::scale(m, half / 0.5f);
    f.opaque.push_back({box, m, Material{{color, 1.0f}, 0.7f, 0.0f}});
  };
  crate({-1.6f, 1.2f, 0.0f}, {0.5f, 0.5f, 0.5f}, 0.2f, {0.55f, 0.36f, 0.18f});
  crate({-1.6f, 1.2f, 1.0f}, {0.4f, 0.4f, 0.4f}, 0.6f, {0.60f, 0.42f, 0.22f});
  crate({-0.5f, 1.8f, 0.0f}, {0.35f, 0.35f, 0.35f}, -0.3f, {0.50f, 0.33f, 0.16f});
  crate({1.7f, 1.5f, 0.0f}, {0.45f, 0.45f, 0.9f}, 0.1f, {0.45f, 0.45f, 0.48f});
  auto person = [&](glm::vec3 p, glm::vec3 color) {
    // Torso capsule upright, head sphere, two arm capsules reaching forward.
    glm::mat4 torso = glm::translate(glm::mat4(1.0f), p + glm::vec3(0, 0, 1.15f));
    f.opaque.push_back({capsule, glm::scale(torso, glm::vec3(1.0f, 1.0f, 1.0f)), Material{{color, 1.0f}, 0.45f}});
    f.opaque.push_back({sphere, glm::translate(glm::mat4(1.0f), p + glm::vec3(0, 0, 1.78f)),
                        Material{{0.85f, 0.65f, 0.5f, 1.0f}, 0.6f}});
    for (float side : {-1.0f, 1.0f}) {
      glm::mat4 leg = glm::translate(glm::mat4(1.0f), p + glm::vec3(0.12f * side, 0, 0.45f));
      leg = glm::scale(leg, glm::vec3(0.55f, 0.55f, 0.75f));
      f.opaque.push_back({capsule, leg, Material{{color * 0.6f, 1.0f}, 0.6f}});
    }
  };
  person({-0.3f, -0.2f, 0.0f}, {0.75f, 0.08f, 0.06f});
  person({0.9f, 0.3f, 0.0f}, {0.06f, 0.16f, 0.75f});
  f.ghosts.push_back({sphere, glm::scale(glm::translate(glm::mat4(1.0f), {0.3f, -1.2f, 0.6f}), glm::vec3(1.6f)),
                      Material{{0.3f, 0.9f, 0.4f, 0.35f}, 0.3f}});
  f.lines.push_back({{-0.3f, -0.2f, 1.15f}, {0.9f, 0.3f, 1.15f}, {1.0f, 0.9f, 0.1f, 1.0f}});
  f.points.push_back({{0.3f, 0.05f, 1.15f}, 10.0f, {1.0f, 0.2f, 0.9f, 1.0f}});
  f.overlay = true;
  return f;
}

}  // namespace

TEST(Renderer, ShowcaseScenePng) {
  MAKE_RENDERER_OR_RETURN(r, 1280, 720);
  const MeshId box = r->upload_mesh(make_box_mesh({0.5f, 0.5f, 0.5f}));
  const MeshId capsule = r->upload_mesh(make_capsule_mesh(0.22f, 0.3f, 32));
  const MeshId sphere = r->upload_mesh(make_sphere_mesh(0.15f, 32));
  const FrameDesc f = showcase(box, capsule, sphere);
  render_test::ui_text_panel(*r, render_test::ui_display(1280, 720), {"16.60 ms  (60 fps)", "showcase scene", "F12: screenshot"});
  ASSERT_TRUE(r->render(f).ok());
  auto img = r->read_back();
  ASSERT_TRUE(img.ok()) << img.error();
  const std::string path = std::string(BOXING_BINARY_DIR) + "/render_showcase.png";
  ASSERT_TRUE(eng::write_png(*img, path).ok()) << path;
  // Sanity: the frame is not flat (something drew), and there are no validation errors.
  long sum = 0, sum2 = 0;
  for (size_t i = 0; i < img->rgba.size(); i += 4) {
    sum += img->rgba[i + 1];
    sum2 += long(img->rgba[i + 1]) * img->rgba[i + 1];
  }
  const double n = double(img->width) * img->height, mean = sum / n;
  EXPECT_GT(sum2 / n - mean * mean, 100.0);

  // Low evening sun, closer camera: long shadows are where acne and peter-panning would show.
  FrameDesc low = f;
  low.sun.direction = {-0.8f, 0.45f, -0.33f};
  low.sun.color = {1.0f, 0.85f, 0.7f};
  low.camera.eye = {2.2f, -3.4f, 1.6f};
  low.camera.target = {0.2f, 0.4f, 0.8f};
  low.overlay = false;
  ASSERT_TRUE(r->render(low).ok());
  auto img2 = r->read_back();
  ASSERT_TRUE(img2.ok());
  ASSERT_TRUE(eng::write_png(*img2, std::string(BOXING_BINARY_DIR) + "/render_showcase_low_sun.png").ok());
  EXPECT_EQ(r->validation_errors(), 0);
}
