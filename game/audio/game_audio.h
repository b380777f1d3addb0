#pragma once
// The game's sound: the sound bank (synthesized at start-up), the mixer, and where the mix goes: a WAV file
// (--audio-out, headless or in the window) and the live device (the window only; none found: the game runs silent
// and says so once). Each frame game_audio_update reads the world's new sound events (sound_events.h), starts a voice
// for each at its simulation time, placed at its contact and scaled by its impulse (SoundTuning), and renders the mix
// up to the world's time less SoundTuning::lag_s. The lag is what lets a landed punch sound at the tick it landed
// although its impulse is known only at the end of the match's impact window; the mix is rendered in simulation
// time only, so the same run gives the same WAV bit for bit.
#include <array>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/audio/live_output.h"
#include "engine/audio/mixer.h"
#include "engine/audio/wav.h"
#include "engine/core/result.h"
#include "engine/render/frame.h"
#include "game/audio/sound_bank.h"
#include "game/audio/sound_events.h"

namespace boxing {

struct World;

// An event's gain from its impulse: gain = level x (floor + (1 - floor) x u / (1 + u / saturation)), u = impulse /
// ref_impulse. Linear in the impulse below the reference (a sound's pressure grows with the impact's momentum),
// bending smoothly toward level x saturation above it so the hardest hits stay under full scale, strictly rising
// everywhere (a bigger impulse is always louder); `floor`: the share of the level an event of no impulse still gets
// (a landed punch met the head at 2 m/s or more: it is heard, whatever the solver's impulse over the window).
struct SoundLevel {
  double ref_impulse = 1.0;  // N s: u = 1 (plays at level x (floor + (1 - floor) / (1 + 1 / saturation)))
  float level = 0.5f;
  double saturation = 4.0;
  double floor = 0.0;
};
float sound_gain(const SoundLevel& s, double impulse);

struct SoundTuning {
  // Per SoundKind (GloveOnHead, GloveOnBody, GloveOnGlove, BodyOnCrate, Footstep, Bell). Each reference is a typical
  // impulse of its kind, so a typical event plays near its level (how they were chosen: docs/guide/audio.md).
  std::array<SoundLevel, kSoundKinds> levels{{{8.0, 0.8f, 4.0, 0.1},  // glove on head: landed punch, N s over 50 ms
                                              {8.0, 0.8f, 4.0, 0.1},  // glove on body
                                              {1.5, 0.35f, 3.0},   // glove on glove: the hit's first-step impulse
                                              {15.0, 0.6f, 3.0},   // body on crate
                                              {9.0, 0.12f, 2.0},   // footstep: the foot's contacts in its touch-down step
                                              {1.0, 0.45f, 1e9}}}; // bell: one strike
  // s behind the world's clock the mix is rendered: the match's impact window (50 ms, MatchTuning::impact_window)
  // plus two ticks. A landed punch's sound is pushed when its impulse is summed, 50 ms after the tick it landed on.
  double lag_s = 0.05 + 2.0 / 240.0;
  bool crowd = true;
  // The crowd's bed (mixer.h BedSettings) and what excites it: a landed punch adds (impulse / crowd_ref)^2 (a big hit
  // raises it far more than a jab), a body's thud on the crates (a knockdown) adds crowd_thud.
  eng::audio::BedSettings crowd_bed{0.03f, 0.12f, 0.4, 5.0};
  double crowd_ref = 12.0;   // N s
  float crowd_thud = 0.5f;
  eng::audio::MixerSettings mixer;
};

struct GameAudioConfig {
  std::string wav_path;  // --audio-out ("" none)
  bool live = false;     // open the audio device (the window)
  SoundTuning tuning;
};

struct GameAudio {
  SoundTuning tuning;
  SoundBank bank;
  eng::audio::Mixer mixer;
  std::optional<eng::audio::WavWriter> wav;
  std::unique_ptr<eng::audio::LiveOutput> live;
  std::vector<float> span;  // one render chunk's stereo frames (kChunkFrames), allocated once
  // The world being heard: its events read so far, and its clock's offset on the mixer's (0 for the first world: the
  // WAV's sample n is the simulation's time n / 48000 s; a restarted world continues where the mix is).
  const World* world = nullptr;
  uint64_t read = 0;
  double offset_s = 0.0, last_t = 0.0;
  std::array<long, kSoundKinds> played{};  // events per kind
  long events_lost = 0;                    // events the ring overwrote before they were read
};

// The bank synthesized, the WAV opened (its error fails: a path that cannot be written), the device opened when
// asked (its failure does not: the game runs silent and prints one line saying so and how to record instead).
eng::Result<std::unique_ptr<GameAudio>> make_game_audio(const GameAudioConfig& c);
// The listener at the camera's eye, its right ear along the view's right.
void game_audio_listen(GameAudio& a, const eng::render::Camera& c);
// The world's new events played and the mix rendered to the world's time less the lag (to the WAV, to the device).
eng::Result<void> game_audio_update(GameAudio& a, const World& w);
// The rest rendered (to the world's time) and the WAV closed.
eng::Result<void> game_audio_finish(GameAudio& a, const World& w);
// The live output's playback speed (the window's slow motion).
void game_audio_speed(GameAudio& a, double time_scale);
// The report's "audio" block: events per kind, voices stolen and dropped, late starts, the peak and clipped samples.
nlohmann::json game_audio_report(const GameAudio& a);

}  // namespace boxing
