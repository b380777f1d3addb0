// The shared-memory surface (engine/platform/shm_surface): what is written into it is what the X server shows.
// Needs a display (xvfb-run); skipped without one, failed without one under CI=true (support/window_test_env.h).
#include "engine/platform/shm_surface.h"

#include <gtest/gtest.h>
#include <chrono>
#include <thread>
#include "engine/platform/window.h"
#include "support/window_test_env.h"
#include "support/x11_window_pixels.h"

using eng::platform::ShmSurface;

namespace {
std::unique_ptr<eng::platform::Window> open_window(int w, int h) {
  eng::platform::WindowConfig wc;
  wc.width = w;
  wc.height = h;
  wc.title = "shm surface test";
  auto win = eng::platform::Window::create(wc);
  return win ? std::move(*win) : nullptr;
}
}  // namespace

TEST(ShmSurface, TheWindowShowsExactlyThePixelsWritten) {
  BOXING_REQUIRE_DISPLAY();
  auto win = open_window(320, 200);
  ASSERT_TRUE(win);
  const glm::ivec2 fb = win->framebuffer_size();
  auto s = ShmSurface::create(*win, fb.x, fb.y);
  ASSERT_TRUE(s.ok()) << s.error();
  ShmSurface& surf = **s;
  ASSERT_GE(surf.stride(), fb.x * 4);
  // A pattern in every channel: B, G, R, X bytes in memory.
  for (int frame = 0; frame < 2; ++frame) {  // twice: the segment is rewritten after a present
    for (int y = 0; y < fb.y; ++y)
      for (int x = 0; x < fb.x; ++x) {
        uint8_t* p = surf.pixels() + y * surf.stride() + x * 4;
        p[0] = uint8_t(x + frame * 7), p[1] = uint8_t(y * 3), p[2] = uint8_t((x ^ y) + frame), p[3] = 0;
      }
    // Presented until shown (at most 2 s): the window's first map may clear it to its background after a present.
    int wrong = 0;
    for (int attempt = 0; attempt < 80; ++attempt) {
      surf.present();
      win->poll_events();
      const eng::Image shown = boxing_test::x11_window_pixels(*win);
      ASSERT_EQ(shown.width, fb.x);
      ASSERT_EQ(shown.height, fb.y);
      wrong = 0;
      for (int y = 0; y < fb.y; ++y)
        for (int x = 0; x < fb.x; ++x) {
          const uint8_t* o = &shown.rgba[size_t(y * fb.x + x) * 4];
          wrong += o[0] != uint8_t((x ^ y) + frame) || o[1] != uint8_t(y * 3) || o[2] != uint8_t(x + frame * 7);
        }
      if (wrong == 0) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(25));
    }
    EXPECT_EQ(wrong, 0) << "frame " << frame;
  }
}

TEST(ShmSurface, RefusesANonPositiveSizeWithAReason) {
  BOXING_REQUIRE_DISPLAY();
  auto win = open_window(64, 64);
  ASSERT_TRUE(win);
  auto s = ShmSurface::create(*win, 0, 10);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("size must be positive"), std::string::npos) << s.error();
}
