#include "engine/audio/synth.h"

#include <algorithm>
#include <cmath>

#include "engine/audio/biquad.h"

namespace eng::audio {

namespace {

constexpr double kTailFade = 0.005;  // s: the last samples of an impact fade to zero (no click where it is cut)

// The recipe's noise burst added into out. The decay is a per-sample factor (e^(-1 / (decay_s rate)), exact for the
// exponential) rather than an exp() a sample: the bank is made at every start.
void add_noise_burst(const NoiseBurst& nb, uint64_t seed, std::vector<double>& out) {
  if (nb.gain <= 0.0) return;
  NoiseRng rng{seed};
  std::vector<Biquad> filters;
  for (int k = 0; k < nb.stages; ++k) {
    if (nb.highpass_hz > 0.0) filters.push_back(highpass(nb.highpass_hz, M_SQRT1_2, kSampleRate));
    if (nb.lowpass_hz > 0.0) filters.push_back(lowpass(nb.lowpass_hz, M_SQRT1_2, kSampleRate));
  }
  const size_t attack = static_cast<size_t>(std::max(nb.attack_s, 1e-6) * kSampleRate);
  const double fall = std::exp(-1.0 / (nb.decay_s * kSampleRate));
  double env = 1.0;
  for (size_t i = 0; i < out.size() && env > 1e-6; ++i) {  // to -120 dB: below the 16-bit floor
    double x = rng.next();
    for (Biquad& f : filters) x = f.process(x);
    const double rise = i < attack ? double(i) / double(attack) : 1.0;
    out[i] += nb.gain * rise * env * x;
    if (i >= attack) env *= fall;
  }
}

// The damped modes added into out. A steady mode is a rotating phasor (z <- z e^(i w) each sample) under a decaying
// envelope (a per-sample factor): no sin() or exp() a sample. A gliding mode integrates its phase sample by sample.
void add_modes(const ImpactRecipe& r, std::vector<double>& out) {
  const double attack = std::max(r.mode_attack_s, 1e-6) * kSampleRate;
  for (const Mode& m : r.modes) {
    const double fall = std::exp(-1.0 / (m.decay_s * kSampleRate));
    double env = m.gain;
    if (m.glide_to_hz <= 0.0) {
      const double w = 2.0 * M_PI * m.freq_hz / kSampleRate, cw = std::cos(w), sw = std::sin(w);
      double re = 1.0, im = 0.0;  // e^(i phase), phase 0 at the start (sin starts at 0: no click)
      for (size_t i = 0; i < out.size(); ++i) {
        out[i] += std::min(1.0, double(i) / attack) * env * im;
        const double nre = re * cw - im * sw;
        im = re * sw + im * cw, re = nre;
        env *= fall;
      }
      continue;
    }
    const double glide = std::exp(-1.0 / (m.glide_s * kSampleRate));
    double phase = 0.0, excess = m.freq_hz - m.glide_to_hz;  // the frequency above where it glides to, Hz
    for (size_t i = 0; i < out.size(); ++i) {
      out[i] += std::min(1.0, double(i) / attack) * env * std::sin(phase);
      phase += 2.0 * M_PI * (m.glide_to_hz + excess) / kSampleRate;
      excess *= glide;
      env *= fall;
    }
  }
}

}  // namespace

double rms(const std::vector<float>& s, size_t from, size_t count) {
  const size_t end = std::min(s.size(), from + count);
  if (from >= end) return 0.0;
  double sum = 0.0;
  for (size_t i = from; i < end; ++i) sum += double(s[i]) * s[i];
  return std::sqrt(sum / double(end - from));
}

SoundBuffer synth_impact(const ImpactRecipe& r) {
  const size_t n = static_cast<size_t>(std::max(0.0, r.length_s) * kSampleRate);
  std::vector<double> acc(n, 0.0);
  add_noise_burst(r.noise, r.seed, acc);
  add_modes(r, acc);
  const size_t fade = std::min(n, static_cast<size_t>(kTailFade * kSampleRate));
  for (size_t i = 0; i < fade; ++i) acc[n - 1 - i] *= double(i) / double(fade);
  SoundBuffer b;
  b.samples.assign(acc.begin(), acc.end());
  if (r.onset_rms > 0.0) {
    const double now = rms(b.samples, 0, static_cast<size_t>(r.onset_window_s * kSampleRate));
    if (now > 0.0)
      for (float& x : b.samples) x = float(x * (r.onset_rms / now));
  }
  return b;
}

SoundBuffer synth_noise_bed(const NoiseBedRecipe& r) {
  const size_t n = static_cast<size_t>(std::max(0.0, r.length_s) * kSampleRate);
  const size_t xf = std::min(n, static_cast<size_t>(std::max(0.0, r.crossfade_s) * kSampleRate));
  std::vector<double> acc(n + xf, 0.0);  // the loop and the stretch after it that is faded into its start
  NoiseRng phases{r.seed ^ 0x5EEDu};
  for (size_t l = 0; l < r.layers.size(); ++l) {
    const BedLayer& layer = r.layers[l];
    NoiseRng rng{r.seed + 0x1000u * (l + 1)};
    Biquad bp = bandpass(layer.centre_hz, layer.q, kSampleRate), bp2 = bp;  // two stages: a clearer band
    const double phase = M_PI * (phases.next() + 1.0), w = 2.0 * M_PI * layer.swell_hz / kSampleRate;
    double re = std::cos(phase), im = std::sin(phase);  // the swell's phasor (rotated each sample, no sin() a sample)
    const double cw = std::cos(w), sw = std::sin(w);
    for (size_t i = 0; i < acc.size(); ++i) {
      acc[i] += layer.gain * (1.0 + layer.swell_depth * im) * bp2.process(bp.process(rng.next()));
      const double nre = re * cw - im * sw;
      im = re * sw + im * cw, re = nre;
    }
  }
  // Equal-power crossfade of the tail [n, n + xf) into the head [0, xf): the loop's end meets its start.
  for (size_t i = 0; i < xf; ++i) {
    const double a = (double(i) + 0.5) / double(xf);
    acc[i] = std::sqrt(a) * acc[i] + std::sqrt(1.0 - a) * acc[n + i];
  }
  SoundBuffer b;
  b.samples.assign(acc.begin(), acc.begin() + static_cast<std::ptrdiff_t>(n));
  const double now = rms(b.samples, 0, n);
  if (now > 0.0)
    for (float& x : b.samples) x = float(x * (r.rms / now));
  return b;
}

}  // namespace eng::audio
