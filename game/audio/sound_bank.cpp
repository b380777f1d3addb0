#include "game/audio/sound_bank.h"

#include "engine/audio/synth.h"

namespace boxing {

namespace {

using eng::audio::ImpactRecipe;
using eng::audio::Mode;
using eng::audio::NoiseBurst;

// Every impact is scaled to this RMS over its first 20 ms (ImpactRecipe::onset_rms): the kinds' loudness is then set
// by the gain mapping alone (SoundTuning), not by how each recipe happens to sum.
constexpr double kOnsetRms = 0.25;

// A glove on the head: a sharp, bright pop. A short burst of wide-band noise (the leather's slap, up to 5 kHz) over
// a low knock whose pitch drops (the skull and neck, 150 -> 95 Hz).
ImpactRecipe glove_on_head() {
  ImpactRecipe r;
  r.length_s = 0.25;
  r.noise = NoiseBurst{1.0, 0.0005, 0.012, 350.0, 5000.0, 2};
  r.modes = {Mode{150.0, 0.9, 0.045, 95.0, 0.03}, Mode{330.0, 0.3, 0.02}};
  return r;
}

// A glove on the body: duller and deeper. The noise darker (to 1.2 kHz) and longer, the knock lower (the trunk's
// mass, 80 -> 55 Hz) and longer.
ImpactRecipe glove_on_body() {
  ImpactRecipe r;
  r.length_s = 0.35;
  r.noise = NoiseBurst{1.0, 0.001, 0.02, 80.0, 1200.0, 2};
  r.modes = {Mode{80.0, 1.0, 0.08, 55.0, 0.04}, Mode{170.0, 0.35, 0.035}};
  return r;
}

// A glove on a glove or an arm: a short slap of leather on leather, bright noise with almost no body.
ImpactRecipe glove_on_glove() {
  ImpactRecipe r;
  r.length_s = 0.12;
  r.noise = NoiseBurst{1.0, 0.0003, 0.006, 1000.0, 6500.0, 2};
  r.modes = {Mode{240.0, 0.15, 0.015}};
  return r;
}

// A body on a crate: a low wooden knock, the crate's first modes (inharmonic, as a struck box's panels ring; Cook
// 2002 ch. 11) under a short click of the contact.
ImpactRecipe body_on_crate() {
  ImpactRecipe r;
  r.length_s = 0.4;
  r.noise = NoiseBurst{0.5, 0.0005, 0.004, 500.0, 3000.0, 2};
  r.modes = {Mode{95.0, 0.8, 0.09, 70.0, 0.05}, Mode{190.0, 1.0, 0.07}, Mode{440.0, 0.6, 0.05}, Mode{780.0, 0.4, 0.03},
             Mode{1250.0, 0.25, 0.018}};
  return r;
}

// A footstep: a soft, short scuff of a sole on wood, mid-band noise with a slower rise and a faint knock.
ImpactRecipe footstep() {
  ImpactRecipe r;
  r.length_s = 0.15;
  r.noise = NoiseBurst{1.0, 0.004, 0.025, 200.0, 1800.0, 2};
  r.modes = {Mode{110.0, 0.3, 0.02}};
  return r;
}

// The bell: Risset's additive bell (J.-C. Risset, "An Introductory Catalogue of Computer Synthesized Sounds", 1969,
// #430; as tabled in Dodge and Jerse, "Computer Music", 2nd ed., 1997, sec. 4.11): eleven inharmonic partials (ratios
// to the nominal pitch, two pairs 1 and 1.7 Hz apart, which beat), each fading to -60 dB in its own share of the
// ring's length (amplitude time constant = share x length / ln 1000). Nominal 900 Hz and a 5 s ring, a small brass
// bell's; a hammer's click (bright noise) on the strike.
ImpactRecipe bell() {
  struct Partial {
    double ratio, plus_hz, amp, share;
  };
  constexpr Partial kRisset[] = {{0.56, 0.0, 1.0, 1.0},   {0.56, 1.0, 0.67, 0.9},  {0.92, 0.0, 1.0, 0.65},
                                 {0.92, 1.7, 1.8, 0.55},  {1.19, 0.0, 2.67, 0.325}, {1.7, 0.0, 1.67, 0.35},
                                 {2.0, 0.0, 1.46, 0.25},  {2.74, 0.0, 1.33, 0.2},   {3.0, 0.0, 1.33, 0.15},
                                 {3.76, 0.0, 1.0, 0.1},   {4.07, 0.0, 1.33, 0.075}};
  constexpr double kNominal = 900.0, kRing = 5.0, kLn1000 = 6.907755;
  ImpactRecipe r;
  r.length_s = 3.0;
  r.noise = NoiseBurst{0.6, 0.0002, 0.003, 2500.0, 9000.0, 2};
  for (const Partial& p : kRisset) r.modes.push_back(Mode{p.ratio * kNominal + p.plus_hz, p.amp / 4.0, p.share * kRing / kLn1000});
  r.onset_window_s = 0.1;
  return r;
}

// The crowd: a murmur of band-limited noise layers (voices' formant regions, 300 Hz to 2 kHz), each swelling slowly
// at its own rate, looped over 6 s.
eng::audio::SoundBuffer crowd() {
  eng::audio::NoiseBedRecipe r;
  r.length_s = 6.0;
  r.crossfade_s = 0.5;
  r.layers = {{300.0, 1.0, 1.0, 0.31, 0.5}, {600.0, 1.2, 0.8, 0.67, 0.5}, {1100.0, 1.5, 0.5, 1.27, 0.5},
              {2000.0, 2.0, 0.25, 2.11, 0.5}};
  r.rms = 0.25;
  r.seed = 0xC20Du;
  return eng::audio::synth_noise_bed(r);
}

}  // namespace

SoundBank make_sound_bank() {
  SoundBank bank;
  ImpactRecipe (*const recipes[kSoundKinds])() = {glove_on_head, glove_on_body, glove_on_glove, body_on_crate, footstep,
                                                  bell};
  for (int k = 0; k < kSoundKinds; ++k)
    for (int v = 0; v < SoundBank::kVariants; ++v) {
      ImpactRecipe r = recipes[k]();
      // The variants: +-4.5% of pitch and their own noise (the bell is one bell: its own noise only).
      const double pitch = k == static_cast<int>(SoundKind::Bell) ? 1.0 : 1.0 + 0.03 * (v - 1.5);
      for (Mode& m : r.modes) m.freq_hz *= pitch, m.glide_to_hz *= pitch;
      r.seed = 0xB0C5000ull + 16u * static_cast<uint64_t>(k) + static_cast<uint64_t>(v);
      r.onset_rms = kOnsetRms;
      bank.sounds[k][v] = eng::audio::synth_impact(r);
    }
  bank.crowd = crowd();
  return bank;
}

}  // namespace boxing
