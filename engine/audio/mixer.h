#pragma once
// The mixer: a fixed pool of voices, each one sound started at a sample of the simulation's clock with a gain and a
// place in 3D, and an ambient bed (a looped sound whose level follows an excitement that events raise and time
// lets fall), rendered to interleaved stereo frames span by span. Nothing here reads a clock: mixer_render renders
// the samples [cursor, cursor + frames) of simulation time, so the same plays give the same samples bit for bit.
//
// Space (at a voice's start; the sounds are short): distance attenuation by OpenAL's inverse-distance-clamped model,
// gain = ref / (ref + rolloff (d - ref)) with d >= ref (OpenAL 1.1 specification, sec. 3.4.2), and equal-power
// panning on the listener's right axis, L = cos(theta), R = sin(theta), theta = (1 + pan) pi / 4 (a centred source
// is 3 dB down in each channel, the same power anywhere across).
// Voices: mixer_play takes a free voice; with none free it steals the least audible (its gain times the share of its
// sound still to play) if the new sound is more audible than that, else the new sound is dropped. No allocation
// after make_mixer.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "engine/audio/sound.h"

namespace eng::audio {

struct Listener {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::UnitX();  // unit: the ear-to-ear axis, toward the right ear
};

struct MixerSettings {
  int voices = 32;               // playing at once; more steal (a match's busiest 50 ms start about a dozen)
  double ref_distance = 6.0;     // m: no attenuation nearer than this (the default camera is 8-10 m from the fight)
  double rolloff = 1.0;          // the inverse-distance model's slope (higher: far sounds quieter)
  double pan_width = 0.8;        // share of the full left-right swing a source at the listener's side gets
  float master = 1.0f;           // the mix's gain before the clamp to [-1, 1]
  int excitation_capacity = 64;  // bed excitations waiting for their sample (more in one render span apply at once)
};

// The ambient bed's level: level = base + span x s / (1 + s), where s follows the excitement e with time constant
// rise_s, and e falls as e^(-t / decay_s) and jumps by each mixer_excite's amount at its sample.
struct BedSettings {
  float base = 0.05f;
  float span = 0.3f;
  double rise_s = 0.4;
  double decay_s = 5.0;
};

struct Voice {
  const SoundBuffer* sound = nullptr;  // nullptr: free
  int64_t start = 0;                   // the sample its sound's first sample plays at
  float gain_l = 0.0f, gain_r = 0.0f;
};

struct MixerStats {
  long started = 0;   // sounds that got a voice
  long stolen = 0;    // voices taken from a playing sound
  long dropped = 0;   // sounds that got none (every voice more audible)
  long late = 0;      // sounds asked for before the cursor: started at the cursor instead
  long clipped = 0;   // output samples clamped to [-1, 1]
  float peak = 0.0f;  // the largest |sample| before the clamp
};

struct Mixer {
  MixerSettings settings;
  Listener listener;
  std::vector<Voice> voices;  // settings.voices, allocated once
  int64_t cursor = 0;         // the next sample mixer_render renders
  // The bed (none while bed is nullptr): its settings, excitement and smoothed excitement, and the excitations not
  // yet reached (sample, amount), in the order they were asked for.
  const SoundBuffer* bed = nullptr;
  BedSettings bed_settings;
  double excitement = 0.0, excitement_smooth = 0.0;
  std::vector<std::pair<int64_t, float>> excitations;  // capacity settings.excitation_capacity
  MixerStats stats;
};

Mixer make_mixer(const MixerSettings& s);

// The (left, right) gains of a source at `at` heard by `l`: distance attenuation times the equal-power pan.
std::array<float, 2> spatial_gains(const MixerSettings& s, const Listener& l, const Eigen::Vector3d& at);

// Starts `sound` (which must outlive its voice) at sample `start` with `gain`, placed at `at` for the current
// listener. False when it was dropped (no voice and none less audible).
bool mixer_play(Mixer& m, const SoundBuffer& sound, int64_t start, float gain, const Eigen::Vector3d& at);

// The ambient bed: `loop` (nullptr: none) played wrapped, the left ear half its length ahead of the right (the two
// channels uncorrelated: a wide bed, no image in the middle).
void mixer_set_bed(Mixer& m, const SoundBuffer* loop, const BedSettings& s);
// Raises the bed's excitement by `amount` at sample `at` (at the cursor if already passed).
void mixer_excite(Mixer& m, int64_t at, float amount);
// The bed's level now (BedSettings).
float mixer_bed_level(const Mixer& m);

// Renders `frames` stereo frames (left, right interleaved into out[2 * frames]) from the cursor and advances it.
void mixer_render(Mixer& m, float* out, int64_t frames);

}  // namespace eng::audio
