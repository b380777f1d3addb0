#pragma once
// WAV files: 16-bit PCM (the canonical RIFF/WAVE layout: "RIFF" size "WAVE", a 16-byte "fmt " chunk with format 1,
// then one "data" chunk). WavWriter streams frames to the file and writes the sizes into the header when it is
// closed; read_wav reads back what it writes (and any 16-bit PCM WAV with those two chunks), for the tests.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/core/result.h"

namespace eng::audio {

class WavWriter {
 public:
  // Creates (truncates) `path` and writes a header with empty sizes. The error names the path and the fix.
  static Result<WavWriter> open(const std::string& path, int rate, int channels);
  WavWriter(WavWriter&& o) noexcept;
  WavWriter& operator=(WavWriter&& o) noexcept;
  WavWriter(const WavWriter&) = delete;
  WavWriter& operator=(const WavWriter&) = delete;
  ~WavWriter();  // closes (sizes written) if close() was not called; errors are then lost

  // Appends `frames` frames of interleaved float samples, each clamped to [-1, 1] and rounded to 16 bits.
  Result<void> write(const float* interleaved, int64_t frames);
  // Writes the header's sizes and closes the file.
  Result<void> close();
  int64_t frames() const { return frames_; }
  const std::string& path() const { return path_; }

 private:
  WavWriter() = default;
  std::FILE* f_ = nullptr;
  std::string path_;
  int rate_ = 0, channels_ = 2;
  int64_t frames_ = 0;
  std::vector<int16_t> pcm_;  // conversion scratch (grows to the largest write once)
};

struct WavData {
  int rate = 0, channels = 0;
  std::vector<int16_t> samples;  // interleaved
  int64_t frames() const { return channels ? static_cast<int64_t>(samples.size()) / channels : 0; }
};

Result<WavData> read_wav(const std::string& path);

// A float in [-1, 1] as a 16-bit sample (x 32767, rounded to nearest, clamped).
int16_t to_pcm16(float x);

}  // namespace eng::audio
