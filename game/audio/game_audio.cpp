#include "game/audio/game_audio.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "game/world.h"

namespace boxing {

namespace {

using eng::audio::kSampleRate;
using eng::audio::sample_at;

constexpr int64_t kChunkFrames = kSampleRate / 10;  // rendered 0.1 s at a time (a frame's span is 800 frames)

// The variant of a sound: a hash of its start sample and kind (the same run picks the same; neighbours differ).
int variant_of(SoundKind k, int64_t start) {
  const uint64_t h = static_cast<uint64_t>(start) * 0x9E3779B97F4A7C15ull + static_cast<uint64_t>(k) * 0xBF58476D1CE4E5B9ull;
  return static_cast<int>((h >> 33) % SoundBank::kVariants);
}

// The mix rendered from the cursor to sample `until`, chunk by chunk, to the WAV and the device.
eng::Result<void> render_to(GameAudio& a, int64_t until) {
  while (a.mixer.cursor < until) {
    const int64_t n = std::min(kChunkFrames, until - a.mixer.cursor);
    eng::audio::mixer_render(a.mixer, a.span.data(), n);
    if (a.wav)
      if (auto ok = a.wav->write(a.span.data(), n); !ok) return eng::make_error("boxing: " + ok.error());
    if (a.live) a.live->queue(a.span.data(), n);
  }
  return {};
}

// The world heard from now on. A new one (the window panel's restart: its clock starts again at 0) continues the mix
// where it is: its time t maps to the mixer's sample (t + offset) x rate, its events are read from its log's start.
void attach(GameAudio& a, const World& w) {
  if (a.world == &w && w.data.time >= a.last_t) return;
  if (a.world) a.offset_s = double(a.mixer.cursor) / kSampleRate + a.tuning.lag_s - w.data.time;
  a.world = &w;
  a.read = 0;
}

// One event: its voice (the kind's sound, a variant, at its time and place, its gain from its impulse) and the
// crowd's excitement (landed punches by the square of their impulse; thuds on the crates).
void play(GameAudio& a, const SoundEvent& e) {
  const int kind = static_cast<int>(e.kind);
  const int64_t start = sample_at(e.t + a.offset_s);
  const float gain = sound_gain(a.tuning.levels[kind], e.impulse);
  eng::audio::mixer_play(a.mixer, a.bank.get(e.kind, variant_of(e.kind, start)), start, gain, e.at);
  ++a.played[kind];
  if (!a.tuning.crowd) return;
  if (e.kind == SoundKind::GloveOnHead || e.kind == SoundKind::GloveOnBody) {
    const double u = e.impulse / a.tuning.crowd_ref;
    eng::audio::mixer_excite(a.mixer, start, static_cast<float>(u * u));
  } else if (e.kind == SoundKind::BodyOnCrate) {
    const double u = std::min(1.0, e.impulse / a.tuning.levels[kind].ref_impulse);
    eng::audio::mixer_excite(a.mixer, start, a.tuning.crowd_thud * static_cast<float>(u));
  }
}

}  // namespace

float sound_gain(const SoundLevel& s, double impulse) {
  const double u = std::max(0.0, impulse) / s.ref_impulse;
  return static_cast<float>(s.level * (s.floor + (1.0 - s.floor) * u / (1.0 + u / s.saturation)));
}

eng::Result<std::unique_ptr<GameAudio>> make_game_audio(const GameAudioConfig& c) {
  auto a = std::make_unique<GameAudio>();
  a->tuning = c.tuning;
  if (!c.wav_path.empty()) {
    std::error_code ec;  // the folders are made, as for --report; what cannot be written is the open's error
    if (auto parent = std::filesystem::path(c.wav_path).parent_path(); !parent.empty())
      std::filesystem::create_directories(parent, ec);
    auto wav = eng::audio::WavWriter::open(c.wav_path, kSampleRate, 2);
    if (!wav) return eng::make_error("boxing: --audio-out: " + wav.error());
    a->wav = std::move(*wav);
  }
  a->bank = make_sound_bank();
  a->mixer = eng::audio::make_mixer(a->tuning.mixer);
  if (a->tuning.crowd) eng::audio::mixer_set_bed(a->mixer, &a->bank.crowd, a->tuning.crowd_bed);
  a->span.assign(static_cast<size_t>(2 * kChunkFrames), 0.0f);
  if (c.live) {
    auto live = eng::audio::LiveOutput::open(kSampleRate);
    if (live) a->live = std::move(*live);
    else
      std::fprintf(stderr, "boxing: %s; running silent. Use --audio-out FILE.wav to record the sound\n",
                   live.error().c_str());
  }
  return a;
}

void game_audio_listen(GameAudio& a, const eng::render::Camera& c) {
  const Eigen::Vector3d eye(c.eye.x, c.eye.y, c.eye.z), target(c.target.x, c.target.y, c.target.z);
  const Eigen::Vector3d up(c.up.x, c.up.y, c.up.z);
  const Eigen::Vector3d right = (target - eye).cross(up);
  a.mixer.listener.position = eye;
  if (right.norm() > 1e-9) a.mixer.listener.right = right.normalized();
}

eng::Result<void> game_audio_update(GameAudio& a, const World& w) {
  attach(a, w);
  if (w.sounds) {
    const SoundEventLog& log = *w.sounds;
    if (log.written - a.read > SoundEventLog::kCapacity) {
      a.events_lost += static_cast<long>(log.written - a.read - SoundEventLog::kCapacity);
      a.read = log.written - SoundEventLog::kCapacity;
    }
    for (; a.read < log.written; ++a.read) play(a, log.at(a.read));
  }
  a.last_t = w.data.time;
  return render_to(a, sample_at(w.data.time + a.offset_s - a.tuning.lag_s));
}

eng::Result<void> game_audio_finish(GameAudio& a, const World& w) {
  if (auto ok = game_audio_update(a, w); !ok) return ok;
  if (auto ok = render_to(a, sample_at(w.data.time + a.offset_s)); !ok) return ok;
  if (a.wav)
    if (auto ok = a.wav->close(); !ok) return eng::make_error("boxing: --audio-out: " + ok.error());
  return {};
}

void game_audio_speed(GameAudio& a, double time_scale) {
  if (a.live) a.live->set_pitch(static_cast<float>(time_scale));
}

nlohmann::json game_audio_report(const GameAudio& a) {
  nlohmann::json events = nlohmann::json::object();
  for (int k = 0; k < kSoundKinds; ++k) events[sound_kind_name(static_cast<SoundKind>(k))] = a.played[k];
  const eng::audio::MixerStats& s = a.mixer.stats;
  nlohmann::json j = {{"events", events},         {"events_lost", a.events_lost}, {"voices_started", s.started},
                      {"voices_stolen", s.stolen}, {"dropped", s.dropped},         {"late", s.late},
                      {"clipped_samples", s.clipped}, {"peak", s.peak},
                      {"seconds", double(a.mixer.cursor) / kSampleRate},
                      {"wav", a.wav ? nlohmann::json(a.wav->path()) : nlohmann::json(nullptr)},
                      {"live", a.live != nullptr}};
  if (a.live)
    j["live_stats"] = {{"buffers_queued", a.live->stats().buffers_queued},
                       {"dropped", a.live->stats().dropped},
                       {"underruns", a.live->stats().underruns}};
  return j;
}

}  // namespace boxing
