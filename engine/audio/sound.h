#pragma once
// The audio module's one sample format: mono float buffers at kSampleRate for the sounds, interleaved stereo float
// frames (left, right) for the mix. Everything here runs in SIMULATION time: a sample index n is the time n / kSampleRate
// s on the simulation's clock, never the wall clock, so the same events give the same samples bit for bit.
#include <cmath>
#include <cstdint>
#include <vector>

namespace eng::audio {

inline constexpr int kSampleRate = 48000;  // Hz: the mixer's, the WAV's and the live output's rate

// One synthesized sound, mono, at kSampleRate; amplitude 1 is full scale.
struct SoundBuffer {
  std::vector<float> samples;
  double seconds() const { return double(samples.size()) / kSampleRate; }
};

// The sample on or after time t (s): the mixer's and the outputs' one rounding from time to samples.
inline int64_t sample_at(double t) { return static_cast<int64_t>(std::floor(t * kSampleRate + 0.5)); }

}  // namespace eng::audio
