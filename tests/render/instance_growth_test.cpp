// Regression: growing the per-frame instance SSBO must re-point the descriptor set at the new buffer even when
// the driver hands the new VkBuffer the freed one's handle value (lavapipe does: its handles are heap pointers).
// The old code compared handles, skipped the descriptor update, and lavapipe's shaders then read the destroyed
// buffer: a segfault in JIT code -- but only WITHOUT the validation layer, whose wrapped handles are always
// unique. So this test runs with validation OFF and judges the result by pixels alone.
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include "render/render_fixture.h"
#include "support/ci_env.h"

using namespace eng::render;

namespace {

struct Px {
  int r, g, b;
};
Px px(const eng::Image& img, int x, int y) {
  const uint8_t* p = img.at(x, y);
  return {p[0], p[1], p[2]};
}

}  // namespace

TEST(RendererWithoutValidation, GrowingInstanceCountsDrawEveryFrameFromTheCurrentInstanceBuffer) {
  boxing_test::pin_lavapipe_env();
  RendererConfig cfg;
  cfg.width = 160;
  cfg.height = 120;
  cfg.validation = false;  // the bug hid behind the layer's handle wrapping
  auto rr = Renderer::create_headless(cfg);
  if (!rr && rr.error().rfind("no Vulkan device", 0) == 0) BOXING_SKIP_OR_FAIL(rr.error());
  ASSERT_TRUE(rr.ok()) << rr.error();
  Renderer& r = **rr;
  ASSERT_FALSE(r.validation_active());
  const MeshId box = r.upload_mesh(make_box_mesh({0.5f, 0.5f, 0.5f}));
  const MeshId filler = r.upload_mesh(make_box_mesh({0.02f, 0.02f, 0.02f}));

  // Instance counts cross the initial 64-record buffer and several geometric growths (64 -> 128 -> 300 -> 1000),
  // with frames in between that reuse the buffer, and end with a shrink back to a small scene.
  const int counts[] = {1, 40, 65, 100, 129, 300, 300, 1000, 1001, 5};
  const glm::vec4 colours[3] = {{0.8f, 0.05f, 0.05f, 1.0f}, {0.05f, 0.8f, 0.05f, 1.0f}, {0.05f, 0.05f, 0.8f, 1.0f}};
  int frame_no = 0;
  for (int n : counts) {
    SCOPED_TRACE("frame " + std::to_string(frame_no) + " with " + std::to_string(n) + " instances");
    const glm::vec4 want = colours[frame_no % 3];
    FrameDesc f = render_test::basic_frame();
    f.camera.eye = {0.0f, -5.0f, 1.0f};
    f.camera.target = {0.0f, 0.0f, 1.0f};
    // Fillers come first in the mesh-sorted SSBO; they sit hidden under the ground. The big box in front of the
    // camera is the LAST record of the buffer, so its colour is only right if the shader reads this frame's data.
    for (int i = 0; i + 1 < n; ++i)
      f.opaque.push_back({filler, glm::translate(glm::mat4(1.0f), {0.1f * (i % 30), 0.1f * (i / 30), -3.0f}),
                          Material{{0.5f, 0.5f, 0.5f, 1.0f}}});
    f.opaque.push_back({box, glm::translate(glm::mat4(1.0f), {0, 0, 1}), Material{want}});
    ASSERT_TRUE(r.render(f).ok());
    auto img = r.read_back();
    ASSERT_TRUE(img.ok()) << img.error();
    const Px c = px(*img, 80, 60);
    const int got[3] = {c.r, c.g, c.b};
    const int hi = frame_no % 3;
    for (int k = 0; k < 3; ++k) {
      if (k == hi) continue;
      EXPECT_GT(got[hi], 2 * got[k]) << "centre pixel " << c.r << "," << c.g << "," << c.b
                                     << ": the box was not drawn with this frame's colour";
    }
    EXPECT_GT(got[hi], 60);
    ++frame_no;
  }
}
