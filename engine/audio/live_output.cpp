#include "engine/audio/live_output.h"

#include <algorithm>
#include <array>
#include <string>

#include "engine/audio/wav.h"

#ifdef BOXING_HAVE_OPENAL
#include <AL/al.h>
#include <AL/alc.h>
#endif

namespace eng::audio {

#ifdef BOXING_HAVE_OPENAL

namespace {
constexpr int kBuffers = 8;     // queued at most: 8 frames of 60 Hz sound (133 ms) before spans are dropped
constexpr int kStartAfter = 2;  // buffers waiting before (re)starting the source: a frame of slack against jitter
}  // namespace

struct LiveOutput::Impl {
  ALCdevice* device = nullptr;
  ALCcontext* context = nullptr;
  ALuint source = 0;
  std::array<ALuint, kBuffers> buffers{};
  std::vector<ALuint> free;  // buffers not queued (capacity kBuffers)
  std::vector<int16_t> pcm;  // conversion scratch (grows to the largest span once)
  int rate = 0;
  bool started = false;  // the source has played (a stop after that is an underrun)

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
  impl->device = alcOpenDevice(nullptr);
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
  ALint processed = 0;
  alGetSourcei(s.source, AL_BUFFERS_PROCESSED, &processed);
  for (; processed > 0; --processed) {
    ALuint b = 0;
    alSourceUnqueueBuffers(s.source, 1, &b);
    s.free.push_back(b);
  }
  if (s.free.empty()) {
    ++stats_.dropped;
    return;
  }
  const size_t n = static_cast<size_t>(2 * frames);
  if (s.pcm.size() < n) s.pcm.resize(n);
  for (size_t i = 0; i < n; ++i) s.pcm[i] = to_pcm16(stereo[i]);
  const ALuint b = s.free.back();
  s.free.pop_back();
  alBufferData(b, AL_FORMAT_STEREO16, s.pcm.data(), static_cast<ALsizei>(n * sizeof(int16_t)), s.rate);
  alSourceQueueBuffers(s.source, 1, &b);
  ++stats_.buffers_queued;
  ALint state = 0, queued = 0;
  alGetSourcei(s.source, AL_SOURCE_STATE, &state);
  alGetSourcei(s.source, AL_BUFFERS_QUEUED, &queued);
  if (state != AL_PLAYING && queued >= kStartAfter) {
    if (s.started) ++stats_.underruns;
    alSourcePlay(s.source);
    s.started = true;
  }
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
