// build/boxing as a user runs it: exit codes and one-line messages for bad input, the report's contents.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_boxing.h"
#include "support/vulkan_test_env.h"
#include "test_paths.h"

using boxing_test::ExeRun;
using boxing_test::run_boxing;

TEST(Executable, BadFlagIsOneLineAndExitCode2) {
  const ExeRun r = run_boxing("--frobnicate");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("unknown flag '--frobnicate'"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "exactly one line: " << r.output;
}

TEST(Executable, MissingContentNamesTheFileAndExitsNonZero) {
  const ExeRun r = run_boxing("--headless --seconds 0.1 --content /nonexistent/content");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("/nonexistent/content/boxer/boxer.gltf"), std::string::npos) << r.output;
}

TEST(Executable, BrokenContentFileIsAClearErrorNotACrash) {
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/broken_content";
  std::system(("mkdir -p " + dir + "/boxer " + dir + "/clips").c_str());
  std::ofstream(dir + "/boxer/boxer.gltf") << "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ {";
  const ExeRun r = run_boxing("--headless --seconds 0.1 --content " + dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("broken glTF"), std::string::npos) << r.output;
}

TEST(Executable, NoDisplayFallsBackToHeadlessAndSaysSo) {
  const std::string shot = std::string(BOXING_BINARY_DIR) + "/nodisplay.png";
  std::remove(shot.c_str());
  const std::string saved = std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "";
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  const ExeRun r = run_boxing("--seconds 0.05 --width 320 --height 180 --screenshot " + shot);
  if (!saved.empty()) setenv("DISPLAY", saved.c_str(), 1);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("no display found"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("running headless"), std::string::npos) << r.output;
  std::FILE* f = std::fopen(shot.c_str(), "rb");
  EXPECT_NE(f, nullptr) << "the headless fallback wrote the screenshot";
  if (f) std::fclose(f);
}

TEST(Executable, HeadlessRunWritesAScreenshotOfTheAskedSizeAndAReport) {
  const std::string shot = std::string(BOXING_BINARY_DIR) + "/exe_test.png";
  const std::string report = std::string(BOXING_BINARY_DIR) + "/exe_test.json";
  const ExeRun r = run_boxing("--headless --seconds 0.25 --seed 3 --width 400 --height 240 --screenshot " + shot +
                           " --report " + report);
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream f(report);
  const nlohmann::json j = nlohmann::json::parse(f);
  EXPECT_EQ(j["seed"], 3);
  EXPECT_EQ(j["frames"], 15);  // 0.25 s of 60 Hz frames
  EXPECT_NEAR(j["seconds"].get<double>(), 0.25, 1e-9);
  EXPECT_EQ(j["validation"]["errors"], 0);
  EXPECT_TRUE(j["validation"]["active"].get<bool>());
  EXPECT_FALSE(j["device"].get<std::string>().empty());
  EXPECT_GT(j["frame_times"]["simulate"]["count"].get<int>(), 0);
  FILE* png = std::fopen(shot.c_str(), "rb");
  ASSERT_NE(png, nullptr);
  unsigned char hdr[24];
  ASSERT_EQ(std::fread(hdr, 1, 24, png), 24u);
  std::fclose(png);
  const int w = (hdr[16] << 24) | (hdr[17] << 16) | (hdr[18] << 8) | hdr[19];
  const int h = (hdr[20] << 24) | (hdr[21] << 16) | (hdr[22] << 8) | hdr[23];
  EXPECT_EQ(w, 400);
  EXPECT_EQ(h, 240);
}
