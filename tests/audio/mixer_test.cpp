// The mixer (engine/audio/mixer.h): a voice starts at its sample whatever the render spans, the mix is the same bit
// for bit however it is split, gain scales RMS exactly, distance and pan follow their formulas, voices are bounded
// and stolen from the least audible, the bed follows its excitement.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/audio/mixer.h"

namespace eng::audio {
namespace {

SoundBuffer constant(float value, int n) { return SoundBuffer{std::vector<float>(size_t(n), value)}; }

// The listener at the origin, its right ear along +x; a source straight ahead at `d` m (+y).
Eigen::Vector3d ahead(double d) { return Eigen::Vector3d(0.0, d, 0.0); }

std::vector<float> render(Mixer& m, int64_t frames, int64_t span) {
  std::vector<float> out(size_t(2 * frames));
  for (int64_t at = 0; at < frames; at += span) mixer_render(m, out.data() + 2 * at, std::min(span, frames - at));
  return out;
}

int64_t first_sound(const std::vector<float>& stereo) {
  for (size_t i = 0; i < stereo.size(); ++i)
    if (stereo[i] != 0.0f) return int64_t(i / 2);
  return -1;
}

double channel_rms(const std::vector<float>& stereo, int ch) {
  double s = 0.0;
  for (size_t i = ch; i < stereo.size(); i += 2) s += double(stereo[i]) * stereo[i];
  return std::sqrt(s / double(stereo.size() / 2));
}

TEST(Mixer, AVoiceStartsAtItsSampleWhateverTheSpans) {
  const SoundBuffer s = constant(0.5f, 100);
  for (const int64_t span : {1, 333, 800, 5000}) {
    Mixer m = make_mixer({});
    ASSERT_TRUE(mixer_play(m, s, 1234, 1.0f, ahead(1.0)));
    const std::vector<float> out = render(m, 3000, span);
    EXPECT_EQ(first_sound(out), 1234) << "span " << span;
    EXPECT_NE(out[2 * 1333], 0.0f) << "its 100th sample";
    EXPECT_EQ(out[2 * 1334], 0.0f) << "and nothing after";
  }
}

TEST(Mixer, TheMixIsTheSameBitForBitHoweverItIsRendered) {
  const SoundBuffer a = constant(0.3f, 4000), b = constant(-0.2f, 2500);
  SoundBuffer loop = constant(0.0f, 4800);
  for (size_t i = 0; i < loop.samples.size(); ++i) loop.samples[i] = float(std::sin(0.01 * double(i)));
  auto run = [&](int64_t span) {
    Mixer m = make_mixer({});
    mixer_set_bed(m, &loop, BedSettings{});
    mixer_play(m, a, 100, 0.7f, Eigen::Vector3d(3.0, 4.0, 0.0));
    mixer_play(m, b, 2100, 0.9f, Eigen::Vector3d(-8.0, 2.0, 1.0));
    mixer_excite(m, 3000, 2.0f);
    return render(m, 20000, span);
  };
  const std::vector<float> whole = run(20000);
  EXPECT_EQ(run(800), whole);
  EXPECT_EQ(run(7), whole);
}

TEST(Mixer, TwiceTheGainIsTwiceTheRms) {
  const SoundBuffer s = constant(0.25f, 4800);
  Mixer quiet = make_mixer({}), loud = make_mixer({});
  mixer_play(quiet, s, 0, 0.5f, ahead(2.0));
  mixer_play(loud, s, 0, 1.0f, ahead(2.0));
  const std::vector<float> q = render(quiet, 4800, 4800), l = render(loud, 4800, 4800);
  EXPECT_NEAR(channel_rms(l, 0) / channel_rms(q, 0), 2.0, 1e-6);
}

// OpenAL's inverse-distance-clamped model: no change inside ref_distance, ref / (ref + rolloff (d - ref)) beyond.
TEST(Mixer, DistanceFollowsTheInverseClampedModel) {
  MixerSettings s;
  s.ref_distance = 6.0, s.rolloff = 1.0;
  const Listener l;
  const double centre = std::cos(M_PI / 4.0);  // the equal-power pan's gain for a source straight ahead
  EXPECT_NEAR(spatial_gains(s, l, ahead(3.0))[0], centre, 1e-6);
  EXPECT_NEAR(spatial_gains(s, l, ahead(12.0))[0], 0.5 * centre, 1e-6);
  EXPECT_NEAR(spatial_gains(s, l, ahead(24.0))[1], 0.25 * centre, 1e-6);
}

TEST(Mixer, PanningKeepsThePowerAndFollowsTheSide) {
  MixerSettings s;
  const Listener l;
  for (const double x : {-5.0, -1.0, 0.0, 2.0, 5.0}) {
    const auto g = spatial_gains(s, l, Eigen::Vector3d(x, 4.0, 0.0));
    const double d = std::hypot(x, 4.0), att = s.ref_distance / (s.ref_distance + s.rolloff * (std::max(d, s.ref_distance) - s.ref_distance));
    EXPECT_NEAR(g[0] * g[0] + g[1] * g[1], att * att, 1e-6) << x;
    if (x > 0) {
      EXPECT_GT(g[1], g[0]) << "a source on the right is louder on the right";
    } else if (x < 0) {
      EXPECT_GT(g[0], g[1]);
    }
  }
}

// Four voices: a fifth quieter sound is dropped, a fifth louder one steals the least audible voice; never more than
// four sound at once.
TEST(Mixer, VoicesAreBoundedAndTheLeastAudibleIsStolen) {
  MixerSettings s;
  s.voices = 4;
  Mixer m = make_mixer(s);
  const SoundBuffer tone = constant(0.1f, 48000);
  const float gains[4] = {0.4f, 0.2f, 0.6f, 0.8f};
  for (const float g : gains) ASSERT_TRUE(mixer_play(m, tone, 0, g, ahead(1.0)));
  EXPECT_FALSE(mixer_play(m, tone, 0, 0.1f, ahead(1.0))) << "quieter than every playing voice";
  EXPECT_EQ(m.stats.dropped, 1);
  EXPECT_TRUE(mixer_play(m, tone, 0, 0.5f, ahead(1.0)));
  EXPECT_EQ(m.stats.stolen, 1);
  int playing = 0;
  bool quietest_left = false;
  for (const Voice& v : m.voices) {
    playing += v.sound != nullptr;
    quietest_left |= std::abs(v.gain_l - 0.2f * float(std::cos(M_PI / 4.0))) < 1e-6f;
  }
  EXPECT_EQ(playing, 4);
  EXPECT_FALSE(quietest_left) << "the 0.2 voice was the one stolen";
  EXPECT_EQ(m.stats.started, 5);
}

TEST(Mixer, ASoundAskedForBeforeTheCursorStartsAtTheCursor) {
  Mixer m = make_mixer({});
  const SoundBuffer s = constant(0.5f, 100);
  std::vector<float> out(2000);
  mixer_render(m, out.data(), 1000);
  mixer_play(m, s, 400, 1.0f, ahead(1.0));
  EXPECT_EQ(m.stats.late, 1);
  mixer_render(m, out.data(), 1000);
  EXPECT_EQ(first_sound(out), 0);
}

// The bed sits at `base` until excited; an excitation at sample S raises it after S (not before), and it falls back
// toward base as the excitement decays (after 4 decay times, within 10% of the rise).
TEST(Mixer, TheBedFollowsItsExcitement) {
  SoundBuffer loop = constant(1.0f, 4800);
  Mixer m = make_mixer({});
  BedSettings bs;
  bs.base = 0.1f, bs.span = 0.5f, bs.rise_s = 0.1, bs.decay_s = 1.0;
  mixer_set_bed(m, &loop, bs);
  mixer_excite(m, kSampleRate, 4.0f);
  const std::vector<float> out = render(m, 6 * kSampleRate, 800);
  auto level = [&](double t) { return out[2 * size_t(t * kSampleRate)]; };
  EXPECT_FLOAT_EQ(level(0.99), 0.1f);
  const float peak = *std::max_element(out.begin(), out.end());
  EXPECT_GT(peak, 0.1f + 0.5f * 0.6f) << "4 units of excitement: s / (1 + s) near 0.7 at the rise's top";
  EXPECT_GT(level(1.3), 0.2f);
  EXPECT_LT(level(5.5) - 0.1f, 0.1f * (peak - 0.1f));
}

}  // namespace
}  // namespace eng::audio
