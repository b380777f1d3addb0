#pragma once
// The game's sound events: what happened in a tick that makes a sound, read from the simulation after each step and
// never written back (the fight is the same with or without sound). A landed punch (the match's record: game/match/
// hits.cpp) sounds on the head or the body once its impulse over the impact window is known, at the tick it landed;
// a glove meeting the other boxer's glove or arm is a slap; a boxer's body (not a foot) hitting a crate, the floor or a
// loose object is a thud; a foot setting down after time in the air is a footstep; the bout's bell rings at each
// round's start and end (three times at the bout's end). Each event carries its time on the simulation's clock, the
// contact point and the contact's impulse: the sound's time, place and loudness (game/audio/game_audio.h).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace boxing {

struct World;

enum class SoundKind : uint8_t { GloveOnHead, GloveOnBody, GloveOnGlove, BodyOnCrate, Footstep, Bell };
inline constexpr int kSoundKinds = 6;
const char* sound_kind_name(SoundKind k);

struct SoundEvent {
  SoundKind kind = SoundKind::Bell;
  double t = 0.0;                                   // s, simulation time
  Eigen::Vector3d at = Eigen::Vector3d::Zero();     // m, world: the contact (the bell: its ring post)
  double impulse = 0.0;                             // N s (the bell: 1 per strike)
};

struct SoundEventTuning {
  double slap_min_speed = 1.0;      // m/s: a glove meeting a glove or arm this fast or faster is a slap
  double thud_min_impulse = 4.0;    // N s: a body part's contact with a crate, the floor or an object from this on
  double footstep_air_s = 0.1;      // s off the ground before a foot's touch-down sounds (no sound as a sole rocks)
  double repeat_s = 0.1;            // s: one body's next slap or thud at the earliest (one bounce's geoms are one sound)
  double bell_gap_s = 0.35;         // s between the strikes of the bout's last bell
};

// What a physics body is to the collector (made once by sound_events_setup).
struct SoundBody {
  int8_t boxer = -1;  // -1: not a boxer's (0: the static arena, else a loose body)
  uint8_t part = 0;   // BodyPart (game/match/body_parts.h)
  bool foot = false;
};

// The events in a ring: collect_sound_events appends, and a reader keeps its own count of what it has read
// (`written` is the total so far), so the world never waits for a reader and nothing needs draining. No allocation
// after sound_events_setup.
struct SoundEventLog {
  static constexpr int kCapacity = 256;  // a 60 Hz frame makes a handful; a reader more than this behind loses some
  std::array<SoundEvent, kCapacity> ring{};
  uint64_t written = 0;
  SoundEventTuning tuning;
  // The collector's state: each body's part, its last slap or thud; per fighter the landed punch waiting for its
  // impulse (match event index, landing time, contact point); per boxer and foot the time it left the ground (< 0: on
  // it); the bout's phase and round last seen.
  std::vector<SoundBody> bodies;
  std::vector<double> last_sound;
  std::array<int, 2> landing{-1, -1};
  std::array<double, 2> landing_t{};
  std::array<Eigen::Vector3d, 2> landing_at{};
  std::vector<std::array<double, 2>> airborne_from;
  int bout_phase = -1, bout_round = 0;

  const SoundEvent& at(uint64_t i) const { return ring[i % kCapacity]; }
};

// The body map and state for w's model (after make_world built the scenario).
void sound_events_setup(const World& w, SoundEventLog& log);
// This tick's events (after the step and the match's rules), appended to the log.
void collect_sound_events(const World& w, SoundEventLog& log);

}  // namespace boxing
