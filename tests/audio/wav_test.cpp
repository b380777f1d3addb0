// The WAV writer (engine/audio/wav.h): the header's sizes and the file's length match the frames written, samples come
// back as written, and a path that cannot be written is an error naming it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <vector>

#include "engine/audio/wav.h"
#include "test_paths.h"

namespace eng::audio {
namespace {

TEST(Wav, TheHeaderAndTheLengthMatchTheFramesWritten) {
  const std::string path = std::string(BOXING_BINARY_DIR) + "/wav_test.wav";
  std::vector<float> frames;
  for (int i = 0; i < 2 * 12345; ++i) frames.push_back(float(i % 200 - 100) / 100.0f);
  {
    auto w = WavWriter::open(path, 48000, 2);
    ASSERT_TRUE(w) << w.error();
    ASSERT_TRUE(w->write(frames.data(), 10000));
    ASSERT_TRUE(w->write(frames.data() + 20000, 2345));
    ASSERT_TRUE(w->close());
  }
  EXPECT_EQ(std::filesystem::file_size(path), 44u + 12345u * 4u);
  auto r = read_wav(path);
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->rate, 48000);
  EXPECT_EQ(r->channels, 2);
  ASSERT_EQ(r->frames(), 12345);
  for (int i = 0; i < 2 * 12345; ++i) ASSERT_EQ(r->samples[i], to_pcm16(frames[i])) << i;
  EXPECT_EQ(to_pcm16(1.0f), 32767);
  EXPECT_EQ(to_pcm16(-2.0f), -32767) << "clamped";
}

TEST(Wav, APathThatCannotBeWrittenIsAnErrorNamingIt) {
  auto w = WavWriter::open("/proc/no/sound.wav", 48000, 2);
  ASSERT_FALSE(w);
  EXPECT_NE(w.error().find("/proc/no/sound.wav"), std::string::npos) << w.error();
  EXPECT_NE(w.error().find("writable"), std::string::npos) << w.error();
}

TEST(Wav, ReadingSomethingElseIsAnError) {
  const std::string path = std::string(BOXING_BINARY_DIR) + "/not_a_wav.wav";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  std::fputs("RIFF....WAVEjunk", f);
  std::fclose(f);
  EXPECT_FALSE(read_wav(path));
  EXPECT_FALSE(read_wav(path + ".missing"));
}

}  // namespace
}  // namespace eng::audio
