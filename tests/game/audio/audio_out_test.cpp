// --audio-out as a user runs it: build/boxing headless writes a WAV as long as the simulated time, the report says
// what was played; a path that cannot be written is one clear error and a non-zero exit; the window with no audio
// device says so once, runs, and records the same.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/audio/sound.h"
#include "engine/audio/wav.h"
#include "support/run_boxing.h"
#include "support/vulkan_test_env.h"
#include "support/window_test_env.h"
#include "test_paths.h"

namespace {

using boxing_test::ExeRun;
using boxing_test::run_boxing;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// 3 s of the match: the WAV holds 3 s of 48 kHz stereo frames (the simulated time, 720 ticks), the opening bell is in
// it, and the report's audio block counts what played (the bell once; nothing dropped, nothing late).
TEST(AudioOut, HeadlessWritesTheSimulatedTimesSoundAndReportsIt) {
  const std::string wav = std::string(BOXING_BINARY_DIR) + "/audio_out/match.wav";  // the folder is made
  const std::string report = std::string(BOXING_BINARY_DIR) + "/audio_out/match.json";
  std::remove(wav.c_str());
  const ExeRun r = run_boxing("--headless --scenario match --seconds 3 --seed 2 --no-validation --audio-out " + wav +
                              " --report " + report);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(count(r.output, "audio device"), 0) << "headless never opens a device: " << r.output;
  auto w = eng::audio::read_wav(wav);
  ASSERT_TRUE(w) << w.error();
  EXPECT_EQ(w->rate, 48000);
  EXPECT_EQ(w->channels, 2);
  EXPECT_EQ(w->frames(), 3 * 48000);
  int peak = 0;
  for (size_t i = 0; i < size_t(48000); ++i) peak = std::max(peak, std::abs(int(w->samples[i])));
  EXPECT_GT(peak, 1000) << "the opening bell in the first second";
  std::ifstream in(report);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["audio"]["events"]["bell"], 1);
  EXPECT_EQ(j["audio"]["late"], 0);
  EXPECT_EQ(j["audio"]["dropped"], 0);
  EXPECT_DOUBLE_EQ(j["audio"]["seconds"].get<double>(), 3.0);
}

TEST(AudioOut, APathThatCannotBeWrittenIsOneErrorAndExitCode1) {
  const ExeRun r = run_boxing("--headless --seconds 0.1 --no-validation --audio-out /proc/no/sound.wav");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("boxing: --audio-out: cannot write audio '/proc/no/sound.wav'"), std::string::npos) << r.output;
  EXPECT_EQ(count(r.output, "\n"), 1) << "one line: " << r.output;
  const ExeRun bad = run_boxing("--headless --audio-out sound.mp3");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.output.find("--audio-out needs a .wav file name"), std::string::npos) << bad.output;
}

// The window (Xvfb, no sound card: OpenAL finds no device): the game says so in one line and runs silent, and
// --audio-out records the same sound as headless would (the length of the simulated time).
TEST(AudioOut, TheWindowWithoutADeviceSaysSoOnceAndStillRecords) {
  BOXING_REQUIRE_DISPLAY();
  const std::string wav = std::string(BOXING_BINARY_DIR) + "/audio_out/window.wav";
  const std::string report = std::string(BOXING_BINARY_DIR) + "/audio_out/window.json";
  const ExeRun r = run_boxing("--scenario match --seconds 1 --seed 2 --no-validation --no-vsync --width 320 --height 180 "
                              "--audio-out " + wav + " --report " + report);
  ASSERT_EQ(r.code, 0) << r.output;
  const int said = count(r.output, "running silent");
  if (said == 0) GTEST_SKIP() << "this machine has an audio device (the silent path is not taken): " << r.output;
  EXPECT_EQ(said, 1) << r.output;
  EXPECT_NE(r.output.find("no audio device"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--audio-out FILE.wav"), std::string::npos) << "says how to record instead: " << r.output;
  std::ifstream in(report);
  const nlohmann::json j = nlohmann::json::parse(in);
  auto w = eng::audio::read_wav(wav);
  ASSERT_TRUE(w) << w.error();
  EXPECT_EQ(w->frames(), eng::audio::sample_at(j["seconds"].get<double>()));
}

}  // namespace
