#pragma once
// The live sound: the mixer's stereo frames streamed to the default audio device through OpenAL Soft, as a few
// small buffers queued on one source and refilled as they play (OpenAL 1.1 specification, sec. 4.3.5: buffer
// queueing). The game renders the mixer in simulation time and queues what each frame added; the device plays it
// at its own clock, so the queue's depth is the latency (a frame or two) and an empty queue is a gap, not a stall.
// Built without OpenAL (libopenal-dev missing at build time), open() says so and the game runs silent.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/result.h"

namespace eng::audio {

class LiveOutput {
 public:
  struct Stats {
    long buffers_queued = 0;
    long dropped = 0;    // spans dropped because every buffer was still queued (the game ran ahead of the device)
    long underruns = 0;  // times the source ran dry and was restarted (the game fell behind, or paused)
  };
  // Opens the default device at `rate` Hz, stereo 16-bit. The error says why (no device, no OpenAL in this build).
  static Result<std::unique_ptr<LiveOutput>> open(int rate);
  ~LiveOutput();
  LiveOutput(const LiveOutput&) = delete;
  LiveOutput& operator=(const LiveOutput&) = delete;

  // Queues `frames` interleaved stereo frames (float, [-1, 1]); playback starts once `start_after` buffers wait.
  void queue(const float* stereo, int64_t frames);
  // The playback rate's factor (the window's slow motion: 0.5 plays the half-speed simulation's sound at half speed).
  void set_pitch(float pitch);
  const Stats& stats() const { return stats_; }

  struct Impl;

 private:
  explicit LiveOutput(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
  Stats stats_;
};

}  // namespace eng::audio
