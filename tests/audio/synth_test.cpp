// The synthesizer (engine/audio/synth.h, biquad.h): the same recipe gives the same samples bit for bit, a mode decays
// at its time constant, the filters' gains are the Butterworth response, the onset is normalised, the bed loops
// without a seam.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/audio/biquad.h"
#include "engine/audio/synth.h"

namespace eng::audio {
namespace {

ImpactRecipe thud(uint64_t seed) {
  ImpactRecipe r;
  r.length_s = 0.3;
  r.noise = NoiseBurst{1.0, 0.001, 0.015, 200.0, 3000.0, 2};
  r.modes = {Mode{120.0, 0.8, 0.05, 80.0, 0.03}, Mode{300.0, 0.3, 0.02}};
  r.seed = seed;
  return r;
}

TEST(Synth, TheSameRecipeGivesTheSameSamplesBitForBit) {
  const SoundBuffer a = synth_impact(thud(7)), b = synth_impact(thud(7)), c = synth_impact(thud(8));
  ASSERT_EQ(a.samples.size(), size_t(0.3 * kSampleRate));
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_NE(a.samples, c.samples) << "another seed, other noise";
}

// A lone mode's envelope is e^(-t / decay): the RMS over a window 0.1 s later is e^(-0.1 / decay) of the earlier
// one's (the windows hold whole periods of the 200 Hz sine, so the ratio is the envelope's to within 1%).
TEST(Synth, AModeDecaysAtItsTimeConstant) {
  ImpactRecipe r;
  r.length_s = 0.5;
  r.modes = {Mode{200.0, 1.0, 0.08}};
  const SoundBuffer b = synth_impact(r);
  const size_t w = kSampleRate / 200 * 4;  // 4 periods
  const double early = rms(b.samples, size_t(0.1 * kSampleRate), w), late = rms(b.samples, size_t(0.2 * kSampleRate), w);
  EXPECT_NEAR(late / early, std::exp(-0.1 / 0.08), 0.01 * std::exp(-0.1 / 0.08));
}

// The RBJ low-pass at Q = 1/sqrt(2) is the 2nd-order Butterworth through the bilinear transform: |H(f)| =
// 1 / sqrt(1 + W^4) with W = tan(pi f / fs) / tan(pi fc / fs) (the analog response at the warped frequency); measured
// on a steady sine after 0.1 s (fs = 48 kHz, fc = 1 kHz; 0.05 dB: the RMS of a 0.1 s window of whole and part periods).
TEST(Synth, TheLowPassHasTheButterworthGain) {
  for (const double f : {250.0, 1000.0, 4000.0}) {
    Biquad lp = lowpass(1000.0, M_SQRT1_2, kSampleRate);
    std::vector<float> out;
    for (int i = 0; i < kSampleRate / 5; ++i) out.push_back(float(lp.process(std::sin(2.0 * M_PI * f * i / kSampleRate))));
    const double gain_db = 20.0 * std::log10(rms(out, kSampleRate / 10, kSampleRate / 10) / M_SQRT1_2);
    const double W = std::tan(M_PI * f / kSampleRate) / std::tan(M_PI * 1000.0 / kSampleRate);
    const double want_db = -10.0 * std::log10(1.0 + std::pow(W, 4));
    EXPECT_NEAR(gain_db, want_db, 0.05) << f << " Hz";
  }
}

TEST(Synth, TheOnsetIsScaledToTheAskedRms) {
  ImpactRecipe r = thud(3);
  r.onset_rms = 0.25;
  const SoundBuffer b = synth_impact(r);
  EXPECT_NEAR(rms(b.samples, 0, size_t(r.onset_window_s * kSampleRate)), 0.25, 1e-4);
  EXPECT_EQ(b.samples.back(), 0.0f) << "the tail fades to zero";
}

// Played wrapped, the bed's last sample meets its first as any two neighbours do: the step across the seam is no
// larger than the largest step inside the loop.
TEST(Synth, TheBedLoopsWithoutASeam) {
  NoiseBedRecipe r;
  r.length_s = 2.0;
  r.layers = {{400.0, 1.0, 1.0, 0.5, 0.5}, {1200.0, 1.5, 0.5, 1.3, 0.5}};
  r.rms = 0.2;
  const SoundBuffer b = synth_noise_bed(r);
  ASSERT_EQ(b.samples.size(), size_t(2 * kSampleRate));
  EXPECT_NEAR(rms(b.samples, 0, b.samples.size()), 0.2, 1e-4);
  float largest = 0.0f;
  for (size_t i = 1; i < b.samples.size(); ++i) largest = std::max(largest, std::abs(b.samples[i] - b.samples[i - 1]));
  EXPECT_LE(std::abs(b.samples.front() - b.samples.back()), largest);
}

}  // namespace
}  // namespace eng::audio
