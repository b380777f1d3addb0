// Same seed, same frames: two headless runs of the same scenario give identical pixels and identical physics
// results; another seed gives another arena.
#include <gtest/gtest.h>

#include "game/app.h"
#include "game/cli.h"
#include "support/vulkan_test_env.h"

namespace {

boxing::HeadlessRun run(const std::vector<std::string>& args) {
  boxing_test::pin_lavapipe_env();
  auto o = boxing::parse_cli(args);
  EXPECT_TRUE(o.ok());
  auto r = boxing::run_headless(*o);
  EXPECT_TRUE(r.ok()) << r.error();
  return std::move(*r);
}

}  // namespace

TEST(Determinism, SameSeedGivesTheSameFramesBitForBit) {
  const std::vector<std::string> args = {"--headless", "--scenario", "ragdolls", "--seed", "5", "--seconds", "0.5",
                                         "--width", "320", "--height", "180"};
  const boxing::HeadlessRun a = run(args), b = run(args);
  ASSERT_EQ(a.image.rgba.size(), b.image.rgba.size());
  EXPECT_TRUE(a.image.rgba == b.image.rgba) << "frames differ between two runs of the same seed";
  EXPECT_EQ(a.report["boxers"].dump(), b.report["boxers"].dump());
  EXPECT_EQ(a.validation_errors, 0);
}

TEST(Determinism, AnotherSeedGivesAnotherScene) {
  const boxing::HeadlessRun a = run({"--headless", "--seed", "1", "--seconds", "0.05", "--width", "320", "--height",
                                     "180"});
  const boxing::HeadlessRun b = run({"--headless", "--seed", "2", "--seconds", "0.05", "--width", "320", "--height",
                                     "180"});
  EXPECT_FALSE(a.image.rgba == b.image.rgba);
}
