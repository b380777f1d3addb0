#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include "render/render_fixture.h"
#include "test_paths.h"

using namespace eng::render;

namespace {

glm::mat4 at(glm::vec3 p) { return glm::translate(glm::mat4(1.0f), p); }

struct Px {
  int r, g, b;
};
Px px(const eng::Image& img, int x, int y) {
  const uint8_t* p = img.at(x, y);
  return {p[0], p[1], p[2]};
}

}  // namespace

TEST(Renderer, RedBoxAtCentreAndSkyOnTop) {
  MAKE_RENDERER_OR_RETURN(r, 320, 240);
  const MeshId box = r->upload_mesh(make_box_mesh({0.5f, 0.5f, 0.5f}));
  FrameDesc f = render_test::basic_frame();
  f.camera.eye = {0.0f, -5.0f, 1.0f};
  f.camera.target = {0.0f, 0.0f, 1.0f};
  f.opaque.push_back({box, at({0, 0, 1}), Material{{0.8f, 0.05f, 0.05f, 1.0f}}});
  ASSERT_TRUE(r->render(f).ok());
  auto img = r->read_back();
  ASSERT_TRUE(img.ok()) << img.error();
  ASSERT_EQ(img->width, 320);
  ASSERT_EQ(img->height, 240);
  ASSERT_EQ(img->rgba.size(), 320u * 240u * 4u);
  const Px c = px(*img, 160, 120);
  EXPECT_GT(c.r, 2 * c.g) << c.r << "," << c.g << "," << c.b;
  EXPECT_GT(c.r, 2 * c.b);
  EXPECT_GT(c.r, 60);
  for (int x : {0, 100, 319}) {
    const Px s = px(*img, x, 0);
    EXPECT_GT(s.b, s.r) << "sky at top row should be blue-ish";
    EXPECT_GT(s.b, 120);
  }
  EXPECT_EQ(r->validation_errors(), 0);
  EXPECT_TRUE(r->validation_active());
}

TEST(Renderer, BoxCastsShadowOnGround) {
  MAKE_RENDERER_OR_RETURN(r, 320, 240);
  const MeshId box = r->upload_mesh(make_box_mesh({0.5f, 0.5f, 0.5f}));
  FrameDesc f = render_test::basic_frame();
  // Sun straight down: the shadow sits directly under the raised box. Camera looks down at the ground.
  f.sun.direction = {0.0f, 0.0f, -1.0f};
  f.camera.eye = {0.0f, -6.0f, 6.0f};
  f.camera.target = {0.0f, 0.0f, 0.0f};
  f.opaque.push_back({box, at({0, 0, 1.2f}), Material{{0.8f, 0.8f, 0.8f, 1.0f}}});
  ASSERT_TRUE(r->render(f).ok());
  auto img = r->read_back();
  ASSERT_TRUE(img.ok()) << img.error();
  // Project two ground points: under the box edge (shadowed, visible just in front of the box) and beside it.
  const float aspect = 320.0f / 240.0f;
  glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(f.camera.fov_y_deg), aspect, f.camera.znear, f.camera.zfar);
  const glm::mat4 vp = proj * glm::lookAtRH(f.camera.eye, f.camera.target, f.camera.up);
  auto to_px = [&](glm::vec3 w) {
    glm::vec4 c = vp * glm::vec4(w, 1.0f);
    glm::vec2 n = glm::vec2(c) / c.w;
    return glm::ivec2(int((n.x * 0.5f + 0.5f) * 320.0f), int((0.5f - n.y * 0.5f) * 240.0f));
  };
  const glm::ivec2 shadowed = to_px({0.3f, -0.45f, 0.0f});
  const glm::ivec2 lit = to_px({1.6f, -0.45f, 0.0f});
  const Px s = px(*img, shadowed.x, shadowed.y), l = px(*img, lit.x, lit.y);
  eng::write_png(*img, std::string(BOXING_BINARY_DIR) + "/render_shadow_test.png");
  EXPECT_LT(s.r + s.g + s.b + 60, l.r + l.g + l.b) << "shadow " << s.r << "," << s.g << "," << s.b << " lit " << l.r
                                                   << "," << l.g << "," << l.b;
  EXPECT_EQ(r->validation_errors(), 0);
}

TEST(Renderer, SameFrameSameBytes) {
  MAKE_RENDERER_OR_RETURN(r, 256, 160);
  const MeshId box = r->upload_mesh(make_box_mesh({0.4f, 0.4f, 0.4f}));
  const MeshId cap = r->upload_mesh(make_capsule_mesh(0.25f, 0.5f, 24));
  FrameDesc f = render_test::basic_frame();
  f.opaque.push_back({box, at({0, 0, 0.4f}), Material{{0.6f, 0.4f, 0.2f, 1.0f}}});
  f.opaque.push_back({cap, at({1, 0.5f, 0.75f}), Material{{0.1f, 0.2f, 0.8f, 1.0f}, 0.3f}});
  f.ghosts.push_back({box, at({-1, 0, 0.4f}), Material{{0.2f, 0.9f, 0.3f, 0.4f}}});
  f.lines.push_back({{0, 0, 0}, {0, 0, 2}, {1, 1, 0, 1}});
  f.points.push_back({{1, 0, 1}, 8.0f, {1, 0, 1, 1}});
  f.overlay = true;
  render_test::ui_text_panel(*r, render_test::ui_display(256, 160), {"determinism"});
  ASSERT_TRUE(r->render(f).ok());
  auto a = r->read_back();
  ASSERT_TRUE(r->render(f).ok());
  auto b = r->read_back();
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(a->rgba == b->rgba);
  EXPECT_EQ(r->validation_errors(), 0);
  // A fresh renderer (new device, new allocations) must produce the same bytes too: golden images rely on it.
  std::string skip;
  auto r2 = render_test::make_renderer(256, 160, &skip);
  ASSERT_TRUE(r2);
  r2->upload_mesh(make_box_mesh({0.4f, 0.4f, 0.4f}));
  r2->upload_mesh(make_capsule_mesh(0.25f, 0.5f, 24));
  render_test::ui_text_panel(*r2, render_test::ui_display(256, 160), {"determinism"});
  ASSERT_TRUE(r2->render(f).ok());
  auto c = r2->read_back();
  ASSERT_TRUE(c.ok());
  EXPECT_TRUE(a->rgba == c->rgba);
  EXPECT_EQ(r2->validation_errors(), 0);
}

TEST(Renderer, DebugLineAndPointColours) {
  MAKE_RENDERER_OR_RETURN(r, 200, 200);
  FrameDesc f = render_test::basic_frame();
  f.ground = false;
  f.camera.eye = {0.0f, -5.0f, 1.0f};
  f.camera.target = {0.0f, 0.0f, 1.0f};
  // A vertical green line through the image centre, and a big magenta point left of it.
  f.lines.push_back({{0, 0, -1}, {0, 0, 3}, {0, 1, 0, 1}});
  f.points.push_back({{-1.0f, 0.0f, 1.0f}, 16.0f, {1, 0, 1, 1}});
  ASSERT_TRUE(r->render(f).ok());
  auto img = r->read_back();
  ASSERT_TRUE(img.ok());
  int green = 0;
  for (int x = 95; x <= 105; ++x) {
    const Px p = px(*img, x, 60);
    if (p.g > p.r + 60 && p.g > p.b + 60 && p.g > 150) ++green;  // MSAA blends thin lines a little
  }
  EXPECT_GE(green, 1) << "no green line pixels near the centre column";
  eng::write_png(*img, std::string(BOXING_BINARY_DIR) + "/render_debug_test.png");
  // Point at x = -1 m, 5 m away: about 200/2 - (1/5)/tan(22.5deg)*100 = ~52 px.
  bool magenta = false;
  for (int x = 40; x < 65; ++x) {
    const Px p = px(*img, x, 100);
    magenta |= p.r > 200 && p.b > 200 && p.g < 60;
  }
  EXPECT_TRUE(magenta);
  EXPECT_EQ(r->validation_errors(), 0);
}

TEST(Renderer, ReportsDevice) {
  MAKE_RENDERER_OR_RETURN(r, 64, 64);
  EXPECT_FALSE(r->device_name().empty());
  EXPECT_FALSE(r->driver_info().empty());
  EXPECT_FALSE(r->read_back().ok()) << "nothing rendered yet";
  EXPECT_EQ(r->validation_errors(), 0);
}

TEST(Renderer, WithoutMsaaStillRendersCleanly) {
  RendererConfig cfg;
  cfg.width = 160;
  cfg.height = 120;
  cfg.msaa_samples = 1;  // the single-sample path renders straight into the resolved image
  MAKE_RENDERER_WITH_OR_RETURN(rr, cfg);
  Renderer& r = *rr;
  const MeshId box = r.upload_mesh(make_box_mesh({0.5f, 0.5f, 0.5f}));
  FrameDesc f = render_test::basic_frame();
  f.camera.eye = {0.0f, -5.0f, 1.0f};
  f.opaque.push_back({box, at({0, 0, 1}), Material{{0.8f, 0.05f, 0.05f, 1.0f}}});
  f.overlay = true;
  render_test::ui_text_panel(r, render_test::ui_display(160, 120), {"msaa 1"});
  ASSERT_TRUE(r.render(f).ok());
  auto img = r.read_back();
  ASSERT_TRUE(img.ok());
  const Px c = px(*img, 80, 60);
  EXPECT_GT(c.r, 2 * c.g);
  EXPECT_EQ(r.validation_errors(), 0);
}

// render_scale: the scene drawn at a lower resolution and stretched over the target (bilinear) looks like the native
// frame (same size, the same picture within a blur), the HUD on top stays pixel-sharp, and the validation layer
// (synchronization checks on) sees no error in the extra blit.
TEST(Renderer, ScaledSceneMatchesTheNativeFrameAndKeepsTheHudSharp) {
  eng::Image img[2];
  for (int k = 0; k < 2; ++k) {
    RendererConfig cfg;
    cfg.width = 320;
    cfg.height = 240;
    cfg.render_scale = k == 0 ? 1.0 : 0.5;
    MAKE_RENDERER_WITH_OR_RETURN(rr, cfg);
    Renderer& r = *rr;
    const MeshId box = r.upload_mesh(make_box_mesh({0.5f, 0.5f, 0.5f}));
    FrameDesc f = render_test::basic_frame();
    f.opaque.push_back({box, at({0, 0, 0.5f}), Material{{0.8f, 0.05f, 0.05f, 1.0f}}});
    f.overlay = true;
    render_test::ui_text_panel(r, render_test::ui_display(320, 240), {"scale"});
    ASSERT_TRUE(r.render(f).ok());
    auto got = r.read_back();
    ASSERT_TRUE(got.ok());
    img[k] = std::move(*got);
    EXPECT_EQ(r.validation_errors(), 0);
  }
  ASSERT_EQ(img[1].width, 320);
  ASSERT_EQ(img[1].height, 240);
  // The scene: mean difference small (edges blur, flat areas agree); the box's centre the same red.
  double sum = 0.0;
  for (int y = 60; y < 240; ++y)
    for (int x = 0; x < 320; ++x)
      for (int c = 0; c < 3; ++c) sum += std::abs(int(img[0].at(x, y)[c]) - int(img[1].at(x, y)[c]));
  EXPECT_LT(sum / (180.0 * 320.0 * 3.0), 3.0);
  const Px a = px(img[0], 160, 150), b = px(img[1], 160, 150);
  EXPECT_NEAR(a.r, b.r, 4);
  EXPECT_NEAR(a.g, b.g, 4);
  // The HUD panel (text at the top left, over the smooth sky) is drawn at full resolution after the upscale: its
  // glyphs' edges agree to the panel's translucency over a slightly different sky, where an upscaled HUD would
  // smear them by tens of levels.
  int hud_max = 0;
  for (int y = 10; y < 40; ++y)
    for (int x = 10; x < 120; ++x)
      for (int c = 0; c < 3; ++c) hud_max = std::max(hud_max, std::abs(int(img[0].at(x, y)[c]) - int(img[1].at(x, y)[c])));
  eng::write_png(img[1], std::string(BOXING_BINARY_DIR) + "/render_scaled_test.png");
  EXPECT_LE(hud_max, 8) << "the HUD went through the upscale";
  // But the scaled frame is not the native one (the path was taken).
  EXPECT_FALSE(img[0].rgba == img[1].rgba);
}
