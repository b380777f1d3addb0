#include "engine/audio/mixer.h"

#include <algorithm>
#include <cmath>

namespace eng::audio {

namespace {

// How much of a voice is still to be heard at the cursor: its louder channel's gain times the share of its sound
// not yet played (a voice near its end is nearly free).
float audibility(const Voice& v, int64_t cursor) {
  const int64_t len = static_cast<int64_t>(v.sound->samples.size());
  const int64_t left = std::clamp<int64_t>(v.start + len - cursor, 0, len);
  return std::max(v.gain_l, v.gain_r) * (len > 0 ? float(left) / float(len) : 0.0f);
}

// The voices' samples in [cursor, cursor + frames) added into out; voices whose sound ends in the span are freed.
void render_voices(Mixer& m, float* out, int64_t frames) {
  const int64_t begin = m.cursor, end = begin + frames;
  for (Voice& v : m.voices) {
    if (!v.sound) continue;
    const float* s = v.sound->samples.data();
    const int64_t len = static_cast<int64_t>(v.sound->samples.size());
    const int64_t a = std::max(begin, v.start), b = std::min(end, v.start + len);
    for (int64_t i = a; i < b; ++i) {
      const float x = s[i - v.start];
      out[2 * (i - begin)] += v.gain_l * x;
      out[2 * (i - begin) + 1] += v.gain_r * x;
    }
    if (v.start + len <= end) v.sound = nullptr;
  }
}

// The bed over the span, its excitement stepped sample by sample (the excitations applied at their samples).
void render_bed(Mixer& m, float* out, int64_t frames) {
  if (!m.bed || m.bed->samples.empty()) return;
  const BedSettings& bs = m.bed_settings;
  const double decay = std::exp(-1.0 / (std::max(bs.decay_s, 1e-3) * kSampleRate));
  const double rise = 1.0 - std::exp(-1.0 / (std::max(bs.rise_s, 1e-3) * kSampleRate));
  const float* loop = m.bed->samples.data();
  const int64_t len = static_cast<int64_t>(m.bed->samples.size());
  size_t next = 0;
  for (int64_t i = 0; i < frames; ++i) {
    const int64_t n = m.cursor + i;
    while (next < m.excitations.size() && m.excitations[next].first <= n) m.excitement += m.excitations[next++].second;
    m.excitement *= decay;
    m.excitement_smooth += (m.excitement - m.excitement_smooth) * rise;
    const float level = mixer_bed_level(m);
    out[2 * i] += level * loop[n % len];
    out[2 * i + 1] += level * loop[(n + len / 2) % len];
  }
  m.excitations.erase(m.excitations.begin(), m.excitations.begin() + static_cast<std::ptrdiff_t>(next));
}

}  // namespace

Mixer make_mixer(const MixerSettings& s) {
  Mixer m;
  m.settings = s;
  m.voices.assign(static_cast<size_t>(std::max(1, s.voices)), Voice{});
  m.excitations.reserve(static_cast<size_t>(std::max(1, s.excitation_capacity)));
  return m;
}

std::array<float, 2> spatial_gains(const MixerSettings& s, const Listener& l, const Eigen::Vector3d& at) {
  const Eigen::Vector3d to = at - l.position;
  const double d = to.norm();
  const double ref = std::max(s.ref_distance, 1e-3);
  const double g = ref / (ref + s.rolloff * (std::max(d, ref) - ref));
  const double pan = d > 1e-9 ? std::clamp(to.dot(l.right) / d, -1.0, 1.0) * s.pan_width : 0.0;
  const double theta = (1.0 + pan) * M_PI / 4.0;
  return {float(g * std::cos(theta)), float(g * std::sin(theta))};
}

bool mixer_play(Mixer& m, const SoundBuffer& sound, int64_t start, float gain, const Eigen::Vector3d& at) {
  const std::array<float, 2> g = spatial_gains(m.settings, m.listener, at);
  Voice v{&sound, start, gain * g[0], gain * g[1]};
  if (start < m.cursor) v.start = m.cursor, ++m.stats.late;
  Voice* slot = nullptr;
  for (Voice& u : m.voices)
    if (!u.sound) {
      slot = &u;
      break;
    }
  if (!slot) {
    float least = 0.0f;
    for (Voice& u : m.voices)
      if (const float a = audibility(u, m.cursor); !slot || a < least) slot = &u, least = a;
    if (std::max(v.gain_l, v.gain_r) <= least) {
      ++m.stats.dropped;
      return false;
    }
    ++m.stats.stolen;
  }
  *slot = v;
  ++m.stats.started;
  return true;
}

void mixer_set_bed(Mixer& m, const SoundBuffer* loop, const BedSettings& s) {
  m.bed = loop;
  m.bed_settings = s;
}

void mixer_excite(Mixer& m, int64_t at, float amount) {
  if (m.excitations.size() >= m.excitations.capacity()) {  // full: now rather than never (no allocation)
    m.excitement += amount;
    return;
  }
  at = std::max(at, m.cursor);
  // Kept in sample order (a handful wait at a time: insertion is cheap).
  auto pos = std::upper_bound(m.excitations.begin(), m.excitations.end(), at,
                              [](int64_t a, const std::pair<int64_t, float>& e) { return a < e.first; });
  m.excitations.insert(pos, {at, amount});
}

float mixer_bed_level(const Mixer& m) {
  const double s = std::max(0.0, m.excitement_smooth);
  return float(m.bed_settings.base + m.bed_settings.span * s / (1.0 + s));
}

void mixer_render(Mixer& m, float* out, int64_t frames) {
  if (frames <= 0) return;
  std::fill(out, out + 2 * frames, 0.0f);
  render_voices(m, out, frames);
  render_bed(m, out, frames);
  const float master = m.settings.master;
  for (int64_t i = 0; i < 2 * frames; ++i) {
    const float x = out[i] * master;
    const float a = std::abs(x);
    m.stats.peak = std::max(m.stats.peak, a);
    if (a > 1.0f) ++m.stats.clipped;
    out[i] = std::clamp(x, -1.0f, 1.0f);
  }
  m.cursor += frames;
}

}  // namespace eng::audio
