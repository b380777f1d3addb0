#include "engine/audio/live_output.h"

#include <algorithm>
#include <array>
#include <string>

#include "engine/audio/wav.h"

#ifdef BOXING_HAVE_OPENAL
#include <AL/al.h>
#include <AL/alc.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#endif

namespace eng::audio {

#ifdef BOXING_HAVE_OPENAL

namespace {
constexpr int kBuffers = 16;    // enough that the queue's length in time, not its count, is what bounds it
constexpr int kStartAfter = 2;  // buffers waiting before (re)starting the source: a frame of slack against jitter
// s of sound queued at most: past it a span's oldest frames are dropped (the game ran ahead of the device, as in the
// catch-up after a slow frame, and the latency would stay that high). The trade: the sound's latency is the mixer's
// lag (62 ms) plus what is queued; a frame slower than what is queued empties the queue, a gap (both measured in the
// window under lavapipe: docs/guide/audio.md).
constexpr double kMaxQueued = 0.15;

// The default device, opened with stderr quiet: OpenAL Soft's backends and the ALSA library below them print their
// own lines while probing a machine with no sound card ("ALSA lib ... Unknown PCM default", "AL lib: (EE) ..."); the
// game says what happened in one line of its own (the caller's). OpenAL Soft's log level is read once, from
// ALSOFT_LOGLEVEL, at its first call (kept if the user set it).
ALCdevice* open_default_device_quietly() {
  setenv("ALSOFT_LOGLEVEL", "0", 0);
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO), null = ::open("/dev/null", O_WRONLY);
  if (saved >= 0 && null >= 0) dup2(null, STDERR_FILENO);
  ALCdevice* d = alcOpenDevice(nullptr);
  if (saved >= 0) dup2(saved, STDERR_FILENO), close(saved);
  if (null >= 0) close(null);
  return d;
}
}  // namespace

struct LiveOutput::Impl {
  ALCdevice* device = nullptr;
  ALCcontext* context = nullptr;
  ALuint source = 0;
  std::array<ALuint, kBuffers> buffers{};
  std::array<int64_t, kBuffers> frames_in{};  // frames each buffer holds (by index into buffers)
  int64_t queued_frames = 0;                  // in the buffers still queued
  std::vector<ALuint> free;  // buffers not queued (capacity kBuffers)
  std::vector<int16_t> pcm;  // conversion scratch (grows to the largest span once)
  int rate = 0;

  size_t index_of(ALuint b) const { return size_t(std::find(buffers.begin(), buffers.end(), b) - buffers.begin()) % kBuffers; }

  ~Impl() {
    if (context) {
      alSourceStop(source);
      alDeleteSources(1, &source);
      alDeleteBuffers(kBuffers, buffers.data());
      alcMakeContextCurrent(nullptr);
      alcDestroyContext(context);
    }
    if (device) alcCloseDevice(device);
  }
};

Result<std::unique_ptr<LiveOutput>> LiveOutput::open(int rate) {
  auto impl = std::make_unique<Impl>();
  impl->rate = rate;
  impl->device = open_default_device_quietly();
  if (!impl->device) return make_error("no audio device (OpenAL: alcOpenDevice found no output device)");
  const ALCint attrs[] = {ALC_FREQUENCY, rate, 0};
  impl->context = alcCreateContext(impl->device, attrs);
  if (!impl->context || !alcMakeContextCurrent(impl->context)) {
    const std::string why = alcGetString(impl->device, alcGetError(impl->device));
    return make_error("no audio device (OpenAL: creating a context failed: " + why + ")");
  }
  alGetError();
  alGenSources(1, &impl->source);
  alGenBuffers(kBuffers, impl->buffers.data());
  if (const ALenum e = alGetError(); e != AL_NO_ERROR)
    return make_error(std::string("no audio device (OpenAL: ") + alGetString(e) + ")");
  alSourcei(impl->source, AL_SOURCE_RELATIVE, AL_TRUE);  // the mix is already placed: a plain stereo stream
  impl->free.assign(impl->buffers.begin(), impl->buffers.end());
  return std::unique_ptr<LiveOutput>(new LiveOutput(std::move(impl)));
}

void LiveOutput::queue(const float* stereo, int64_t frames) {
  Impl& s = *impl_;
  if (frames <= 0) return;
  // Played buffers back to the free list. A source that ran dry has stopped, and a stopped source counts every queued
  // buffer as processed (OpenAL 1.1, sec. 4.3.5): all are taken back and the source rewound to its initial state,
  // where what is queued next waits, unplayed, until kStartAfter buffers restart it.
  ALint state = 0, processed = 0;
  alGetSourcei(s.source, AL_SOURCE_STATE, &state);
  alGetSourcei(s.source, AL_BUFFERS_PROCESSED, &processed);
  for (; processed > 0; --processed) {
    ALuint b = 0;
    alSourceUnqueueBuffers(s.source, 1, &b);
    s.free.push_back(b);
    s.queued_frames -= s.frames_in[s.index_of(b)];
  }
  if (state == AL_STOPPED) {
    alSourceRewind(s.source);
    ++stats_.underruns;
  }
  // Past kMaxQueued only the span's newest frames are queued (the oldest are dropped): the latency is cut back to the
  // bound at one seam instead of growing.
  const int64_t room = static_cast<int64_t>(kMaxQueued * s.rate) - s.queued_frames;
  if (s.free.empty() || room <= 0) {
    ++stats_.dropped;
    return;
  }
  if (frames > room) {
    ++stats_.dropped;
    stereo += 2 * (frames - room);
    frames = room;
  }
  const size_t n = static_cast<size_t>(2 * frames);
  if (s.pcm.size() < n) s.pcm.resize(n);
  for (size_t i = 0; i < n; ++i) s.pcm[i] = to_pcm16(stereo[i]);
  const ALuint b = s.free.back();
  s.free.pop_back();
  s.frames_in[s.index_of(b)] = frames;
  s.queued_frames += frames;
  alBufferData(b, AL_FORMAT_STEREO16, s.pcm.data(), static_cast<ALsizei>(n * sizeof(int16_t)), s.rate);
  alSourceQueueBuffers(s.source, 1, &b);
  ++stats_.buffers_queued;
  ALint queued = 0;
  alGetSourcei(s.source, AL_SOURCE_STATE, &state);
  alGetSourcei(s.source, AL_BUFFERS_QUEUED, &queued);
  if (state != AL_PLAYING && queued >= kStartAfter) alSourcePlay(s.source);
}

void LiveOutput::set_pitch(float pitch) { alSourcef(impl_->source, AL_PITCH, std::clamp(pitch, 0.05f, 4.0f)); }

#else  // built without OpenAL

struct LiveOutput::Impl {};

Result<std::unique_ptr<LiveOutput>> LiveOutput::open(int) {
  return make_error("no audio device (this build has no OpenAL: install libopenal-dev, scripts/deps, and rebuild)");
}
void LiveOutput::queue(const float*, int64_t) {}
void LiveOutput::set_pitch(float) {}

#endif

LiveOutput::LiveOutput(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LiveOutput::~LiveOutput() = default;

}  // namespace eng::audio
