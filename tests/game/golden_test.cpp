// Screenshot regression: fixed scenes rendered headless on lavapipe (pinned ICD, thread count, poisoned memory,
// fixed simulated time and seed) and compared with golden PNGs in tests/golden/.
//
// Metric (after Filament's renderdiff): exact match first; else a pixel fails when any RGB channel differs by more
// than 4/255, and the test passes while at most 0.1% of pixels fail. On failure the actual image and a magnified
// diff (failing pixels in red) are written to <build>/golden_out/ and named in the message.
// Regenerate the goldens (after an intended visual change, looking at them first): scripts/update-goldens
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/core/image.h"
#include "engine/core/image_compare.h"
#include "game/app.h"
#include "game/cli.h"
#include "support/vulkan_test_env.h"
#include "test_paths.h"

namespace fs = std::filesystem;

namespace {

const fs::path kGoldenDir = fs::path(BOXING_SOURCE_DIR) / "tests" / "golden";
const fs::path kOutDir = fs::path(BOXING_BINARY_DIR) / "golden_out";

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  std::string t = s.str();
  while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
  return t;
}

void check_golden(const std::string& name, std::vector<std::string> args) {
  boxing_test::pin_lavapipe_env();
  args.insert(args.end(), {"--headless", "--width", "640", "--height", "360"});
  auto options = boxing::parse_cli(args);
  ASSERT_TRUE(options.ok()) << options.error();
  auto run = boxing::run_headless(*options);
  ASSERT_TRUE(run.ok()) << run.error();
  EXPECT_TRUE(run->validation_active) << "the Khronos validation layer must be active in every Vulkan test";
  EXPECT_EQ(run->validation_errors, 0) << "Vulkan validation errors while rendering " << name;

  const fs::path golden_path = kGoldenDir / (name + ".png");
  const fs::path driver_path = kGoldenDir / "DRIVER.txt";
  if (std::getenv("BOXING_UPDATE_GOLDENS")) {
    ASSERT_TRUE(eng::write_png(run->image, golden_path.string()).ok());
    std::ofstream(driver_path) << run->driver << "\n";
    GTEST_SKIP() << "golden regenerated: " << golden_path;
  }
  ASSERT_TRUE(fs::exists(golden_path)) << "missing golden image " << golden_path
                                       << " (make it with scripts/update-goldens and look at it before committing)";
  auto golden = eng::read_png(golden_path.string());
  ASSERT_TRUE(golden.ok()) << golden.error();

  const std::string golden_driver = fs::exists(driver_path) ? read_text(driver_path) : "(unknown)";
  const std::string driver_note =
      golden_driver == run->driver
          ? std::string()
          : "\nNOTE: the goldens were made with driver '" + golden_driver + "' but this run used '" + run->driver +
                "'; a driver change can explain small differences.";

  const eng::CompareResult r = eng::compare_images(run->image, *golden);
  if (!r.passed) {
    fs::create_directories(kOutDir);
    const fs::path actual = kOutDir / (name + ".actual.png");
    const fs::path diff = kOutDir / (name + ".diff.png");
    (void)eng::write_png(run->image, actual.string());
    if (r.same_size) (void)eng::write_png(eng::make_diff_image(run->image, *golden), diff.string());
    FAIL() << name << ": " << r.summary() << "\n  actual: " << actual << "\n  diff:   " << diff
           << "\n  golden: " << golden_path << driver_note;
  }
  if (!driver_note.empty()) std::printf("%s\n", driver_note.c_str());
}

}  // namespace

TEST(Golden, ArenaFromTheDefaultCameraMatchesGolden) {
  check_golden("arena_default", {"--scenario", "arena", "--seed", "1", "--seconds", "0.05", "--camera", "default"});
}

TEST(Golden, BoxerCloseUpMatchesGolden) {
  check_golden("boxer_closeup", {"--scenario", "arena", "--seed", "1", "--seconds", "0.05", "--camera", "closeup"});
}
