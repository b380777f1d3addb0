// Windowed path: swapchain, present, resize and minimise/restore. Runs only when a display is reachable (e.g.
// under xvfb-run -s "-screen 0 1280x720x24"); skipped otherwise, since headless CI has no window system.
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include "engine/platform/window.h"
#include "render/render_fixture.h"

using namespace eng::render;

TEST(RendererWindowed, ResizeMinimiseRestoreWithoutValidationErrors) {
  boxing_test::pin_lavapipe_env();
  render_test::enable_sync_validation();
  if (!eng::platform::display_available()) GTEST_SKIP() << "no display (run under xvfb-run to exercise this)";
  eng::platform::WindowConfig wc;
  wc.width = 640;
  wc.height = 360;
  auto window = eng::platform::Window::create(wc);
  ASSERT_TRUE(window.ok()) << window.error();
  RendererConfig cfg;
  cfg.validation = true;
  cfg.vsync = false;
  auto rr = Renderer::create_windowed(cfg, **window);
  if (!rr && rr.error().rfind("no Vulkan device", 0) == 0) GTEST_SKIP() << rr.error();
  ASSERT_TRUE(rr.ok()) << rr.error();
  Renderer& r = **rr;
  eng::platform::Window& w = **window;
  const MeshId box = r.upload_mesh(make_box_mesh({0.5f, 0.5f, 0.5f}));
  FrameDesc f = render_test::basic_frame();
  f.opaque.push_back({box, glm::translate(glm::mat4(1.0f), {0, 0, 0.5f}), Material{{0.8f, 0.1f, 0.1f, 1.0f}}});
  f.overlay = true;
  for (int i = 0; i < 60; ++i) {
    w.poll_events();
    if (i == 20) w.set_size(800, 500);
    if (i == 35) w.iconify();
    if (i == 45) w.restore();
    // the window's input through the UI, as the game does it (the panel takes none; xvfb has no pointer moves)
    render_test::ui_text_panel(r, w.ui_input(1.0f / 60.0f), {"frame " + std::to_string(i)});
    auto res = r.render(f);
    ASSERT_TRUE(res.ok()) << "frame " << i << ": " << res.error();
  }
  auto img = r.read_back();
  ASSERT_TRUE(img.ok()) << img.error();
  EXPECT_EQ(static_cast<size_t>(img->width) * img->height * 4, img->rgba.size());
  // The offscreen target follows the window, so a screenshot after the resize has the new size.
  EXPECT_EQ(img->width, w.framebuffer_size().x);
  EXPECT_EQ(img->height, w.framebuffer_size().y);
  eng::write_png(*img, std::string(BOXING_BINARY_DIR) + "/render_windowed.png");
  EXPECT_EQ(r.validation_errors(), 0);
  for (const auto& m : r.validation_messages()) ADD_FAILURE() << m;
}
