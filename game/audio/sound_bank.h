#pragma once
// The game's sounds, synthesized at start-up from the recipes in sound_bank.cpp (engine/audio/synth.h: damped modes
// plus a noise burst; the crowd a looped noise bed). A few variants of each kind (other noise, a few per cent of
// pitch apart) so repeated hits do not sound like one sample replayed. Deterministic: fixed seeds, no files.
#include <array>

#include "engine/audio/sound.h"
#include "game/audio/sound_events.h"

namespace boxing {

struct SoundBank {
  static constexpr int kVariants = 4;
  std::array<std::array<eng::audio::SoundBuffer, kVariants>, kSoundKinds> sounds;
  eng::audio::SoundBuffer crowd;  // the crowd's loop (its level: the mixer's bed, game_audio.h)
  const eng::audio::SoundBuffer& get(SoundKind k, int variant) const {
    return sounds[static_cast<int>(k)][static_cast<size_t>(variant) % kVariants];
  }
};

// About 50 ms of one core at start-up, 4.4 MB of buffers (the bell's 3 s and the crowd's 6 s are most of it).
SoundBank make_sound_bank();

}  // namespace boxing
