// The renderer must refuse to run silently unvalidated, and must explain a missing driver.
#include <gtest/gtest.h>
#include <cstdlib>
#include <string>
#include "render/render_fixture.h"
#include "support/ci_env.h"

using namespace eng::render;

namespace {

// Sets an environment variable for the scope of one test and restores the pinned lavapipe setup afterwards.
struct ScopedEnv {
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (had_) setenv(name_, old_.c_str(), 1);
    else unsetenv(name_);
    boxing_test::pin_lavapipe_env();
  }
  const char* name_;
  std::string old_;
  bool had_ = false;
};

}  // namespace

TEST(RendererErrors, MissingValidationLayerIsAnErrorNamingThePackage) {
  boxing_test::pin_lavapipe_env();
  ScopedEnv env("VK_LAYER_PATH", "/nonexistent-layer-dir");  // hides every explicit layer, validation included
  RendererConfig cfg;
  cfg.width = 64;
  cfg.height = 64;
  auto r = Renderer::create_headless(cfg);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("vulkan-validationlayers"), std::string::npos) << r.error();
}

TEST(RendererErrors, NoDeviceIsAClearError) {
  boxing_test::pin_lavapipe_env();
  ScopedEnv a("VK_ICD_FILENAMES", "/nonexistent_icd.json");
  ScopedEnv b("VK_DRIVER_FILES", "/nonexistent_icd.json");
  RendererConfig cfg;
  cfg.width = 64;
  cfg.height = 64;
  cfg.validation = false;
  auto r = Renderer::create_headless(cfg);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().rfind("no Vulkan device found", 0), 0u) << r.error();
}

TEST(RendererErrors, ValidationOffStillRenders) {
  boxing_test::pin_lavapipe_env();
  RendererConfig cfg;
  cfg.width = 64;
  cfg.height = 64;
  cfg.validation = false;
  auto r = Renderer::create_headless(cfg);
  if (!r && r.error().rfind("no Vulkan device", 0) == 0) BOXING_SKIP_OR_FAIL(r.error());
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_FALSE((*r)->validation_active());
  EXPECT_TRUE((*r)->render(render_test::basic_frame()).ok());
  EXPECT_TRUE((*r)->read_back().ok());
}
