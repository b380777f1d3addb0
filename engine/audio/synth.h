#pragma once
// Sounds made from code at start-up (no sample files): a struck object as modal synthesis plus a noise transient
// (P. R. Cook, "Real Sound Synthesis for Interactive Applications", 2002, ch. 4 and 11: a struck body rings in
// exponentially damped sinusoidal modes; the contact itself is a short burst of band-limited noise), and a loopable
// noise bed (band-limited noise layers with slow swells: a crowd's murmur). Every noise comes from a seeded
// generator (NoiseRng), so a recipe makes the same samples on every run and machine.
#include <cstdint>
#include <vector>

#include "engine/audio/sound.h"

namespace eng::audio {

// White noise, uniform in [-1, 1): splitmix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014) on a counter; the top 53 bits make the double.
struct NoiseRng {
  uint64_t state = 0;
  double next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-52 - 1.0;
  }
};

// The contact's transient: white noise through a high-pass and a low-pass (Butterworth biquads, `stages` of each
// for a steeper band), under a linear attack and an exponential decay.
struct NoiseBurst {
  double gain = 0.0;          // peak amplitude of the envelope (before the recipe's normalisation); 0: no burst
  double attack_s = 0.001;    // s, the linear rise
  double decay_s = 0.02;      // s, the decay's time constant (amplitude e^(-t / decay_s) after the attack)
  double highpass_hz = 0.0;   // Hz, 0: none (lower, a duller thud)
  double lowpass_hz = 0.0;    // Hz, 0: none (higher, a brighter crack)
  int stages = 2;             // biquads per filter
};

// One damped mode of the struck body: a sine whose amplitude decays as e^(-t / decay_s), its frequency gliding from
// freq_hz to glide_to_hz with time constant glide_s (a drum-like pitch drop; glide_to_hz 0: a steady pitch).
struct Mode {
  double freq_hz = 100.0;
  double gain = 1.0;
  double decay_s = 0.1;
  double glide_to_hz = 0.0;
  double glide_s = 0.03;
};

struct ImpactRecipe {
  double length_s = 0.3;        // the buffer's length (the last 5 ms fade out, no click at the cut)
  NoiseBurst noise;
  std::vector<Mode> modes;
  double mode_attack_s = 0.0005;  // s, the modes' linear rise (a click-free start)
  // > 0: the whole sound scaled so that its RMS over its first onset_window_s is onset_rms. Sounds of one kind are
  // then equally loud where a listener (and the tests' onset detector) hears the hit, whatever their spectrum.
  double onset_rms = 0.0;
  double onset_window_s = 0.02;
  uint64_t seed = 1;
};

SoundBuffer synth_impact(const ImpactRecipe& r);

// A layer of the bed: noise through a band-pass at centre_hz (bandwidth centre_hz / q), its amplitude swelling as
// 1 + swell_depth sin(2 pi swell_hz t + phase) (phase drawn from the seed).
struct BedLayer {
  double centre_hz = 500.0;
  double q = 1.0;
  double gain = 1.0;
  double swell_hz = 0.5;
  double swell_depth = 0.3;
};

// A loopable bed: the layers summed over length_s, the last crossfade_s faded into the first (equal power: the
// noise's two ends are uncorrelated), scaled to RMS `rms`. Played from any sample and wrapped, it has no seam.
struct NoiseBedRecipe {
  double length_s = 4.0;
  double crossfade_s = 0.25;
  std::vector<BedLayer> layers;
  double rms = 0.1;
  uint64_t seed = 1;
};

SoundBuffer synth_noise_bed(const NoiseBedRecipe& r);

// RMS of samples [from, from + count) of a buffer (clipped to it; 0 for an empty range).
double rms(const std::vector<float>& s, size_t from, size_t count);

}  // namespace eng::audio
