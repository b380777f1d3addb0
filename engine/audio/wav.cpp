#include "engine/audio/wav.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <utility>

namespace eng::audio {

namespace {

void put_u32(unsigned char* p, uint32_t v) {
  for (int k = 0; k < 4; ++k) p[k] = static_cast<unsigned char>(v >> (8 * k));
}
void put_u16(unsigned char* p, uint16_t v) {
  p[0] = static_cast<unsigned char>(v), p[1] = static_cast<unsigned char>(v >> 8);
}
uint32_t get_u32(const unsigned char* p) { return p[0] | p[1] << 8 | p[2] << 16 | uint32_t(p[3]) << 24; }
uint16_t get_u16(const unsigned char* p) { return static_cast<uint16_t>(p[0] | p[1] << 8); }

// The 44-byte header of a 16-bit PCM file holding data_bytes of samples.
void header(unsigned char* h, int rate, int channels, uint32_t data_bytes) {
  std::memcpy(h, "RIFF", 4);
  put_u32(h + 4, 36 + data_bytes);
  std::memcpy(h + 8, "WAVEfmt ", 8);
  put_u32(h + 16, 16);                               // fmt chunk size
  put_u16(h + 20, 1);                                // PCM
  put_u16(h + 22, static_cast<uint16_t>(channels));
  put_u32(h + 24, static_cast<uint32_t>(rate));
  put_u32(h + 28, static_cast<uint32_t>(rate * channels * 2));  // bytes per second
  put_u16(h + 32, static_cast<uint16_t>(channels * 2));         // block align
  put_u16(h + 34, 16);                                           // bits per sample
  std::memcpy(h + 36, "data", 4);
  put_u32(h + 40, data_bytes);
}

}  // namespace

int16_t to_pcm16(float x) {
  const float c = std::clamp(x, -1.0f, 1.0f);
  return static_cast<int16_t>(std::lround(c * 32767.0f));
}

Result<WavWriter> WavWriter::open(const std::string& path, int rate, int channels) {
  WavWriter w;
  w.path_ = path;
  w.rate_ = rate;
  w.channels_ = channels;
  w.f_ = std::fopen(path.c_str(), "wb");
  if (!w.f_)
    return make_error("cannot write audio '" + path + "': " + std::strerror(errno) +
                      " (check the folder exists and is writable)");
  unsigned char h[44];
  header(h, rate, channels, 0);
  if (std::fwrite(h, 1, sizeof h, w.f_) != sizeof h) return make_error("cannot write audio '" + path + "': the write failed");
  return w;
}

WavWriter::WavWriter(WavWriter&& o) noexcept { *this = std::move(o); }

WavWriter& WavWriter::operator=(WavWriter&& o) noexcept {
  if (this != &o) {
    if (f_) (void)close();
    f_ = std::exchange(o.f_, nullptr);
    path_ = std::move(o.path_);
    rate_ = o.rate_;
    channels_ = o.channels_;
    frames_ = o.frames_;
    pcm_ = std::move(o.pcm_);
  }
  return *this;
}

WavWriter::~WavWriter() {
  if (f_) (void)close();
}

Result<void> WavWriter::write(const float* interleaved, int64_t frames) {
  if (!f_) return make_error("cannot write audio '" + path_ + "': the file is closed");
  const size_t n = static_cast<size_t>(frames * channels_);
  if (pcm_.size() < n) pcm_.resize(n);
  for (size_t i = 0; i < n; ++i) pcm_[i] = to_pcm16(interleaved[i]);
  // 16-bit little-endian samples: the host's order on every machine we build for (x86-64, arm64).
  if (std::fwrite(pcm_.data(), sizeof(int16_t), n, f_) != n)
    return make_error("cannot write audio '" + path_ + "': the write failed (is the disk full?)");
  frames_ += frames;
  return {};
}

Result<void> WavWriter::close() {
  if (!f_) return {};
  std::FILE* f = std::exchange(f_, nullptr);
  const uint64_t bytes = static_cast<uint64_t>(frames_) * channels_ * 2;
  unsigned char h[44];
  // (A RIFF size is 32 bits: past 4 GiB, over 6 hours of 48 kHz stereo, the sizes saturate.)
  header(h, rate_, channels_, static_cast<uint32_t>(std::min<uint64_t>(bytes, 0xFFFFFFFFu - 36)));
  bool ok = std::fseek(f, 0, SEEK_SET) == 0 && std::fwrite(h, 1, sizeof h, f) == sizeof h;
  ok = (std::fclose(f) == 0) && ok;
  if (!ok) return make_error("cannot write audio '" + path_ + "': finishing the file failed");
  return {};
}

Result<WavData> read_wav(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return make_error("cannot read '" + path + "': " + std::strerror(errno));
  std::vector<unsigned char> bytes;
  unsigned char buf[65536];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) bytes.insert(bytes.end(), buf, buf + n);
  std::fclose(f);
  const std::string bad = "'" + path + "' is not a 16-bit PCM WAV file";
  if (bytes.size() < 12 || std::memcmp(bytes.data(), "RIFF", 4) != 0 || std::memcmp(bytes.data() + 8, "WAVE", 4) != 0)
    return make_error(bad);
  WavData out;
  bool fmt = false;
  for (size_t at = 12; at + 8 <= bytes.size();) {
    const unsigned char* c = bytes.data() + at;
    const uint32_t size = get_u32(c + 4);
    if (at + 8 + size > bytes.size()) return make_error(bad + " (a chunk runs past its end)");
    if (std::memcmp(c, "fmt ", 4) == 0 && size >= 16) {
      if (get_u16(c + 8) != 1 || get_u16(c + 22) != 16) return make_error(bad);
      out.channels = get_u16(c + 10);
      out.rate = static_cast<int>(get_u32(c + 12));
      fmt = true;
    } else if (std::memcmp(c, "data", 4) == 0) {
      if (!fmt) return make_error(bad + " (data before fmt)");
      out.samples.resize(size / 2);
      std::memcpy(out.samples.data(), c + 8, out.samples.size() * 2);
      return out;
    }
    at += 8 + size + (size & 1);
  }
  return make_error(bad + " (no data chunk)");
}

}  // namespace eng::audio
