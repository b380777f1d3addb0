#include "engine/audio/biquad.h"

#include <algorithm>
#include <cmath>

namespace eng::audio {

namespace {

struct Omega {
  double cos_w, alpha;
};

// w0 = 2 pi f / Fs, alpha = sin(w0) / (2 Q) (the cookbook's intermediate values); f kept inside (0, Fs / 2).
Omega omega(double f_hz, double q, double rate) {
  const double f = std::clamp(f_hz, 1.0, 0.49 * rate);
  const double w0 = 2.0 * M_PI * f / rate;
  return {std::cos(w0), std::sin(w0) / (2.0 * std::max(q, 1e-3))};
}

Biquad normalized(double b0, double b1, double b2, double a0, double a1, double a2) {
  Biquad f;
  f.b0 = b0 / a0, f.b1 = b1 / a0, f.b2 = b2 / a0, f.a1 = a1 / a0, f.a2 = a2 / a0;
  return f;
}

}  // namespace

Biquad lowpass(double f_hz, double q, double rate) {
  const auto [c, alpha] = omega(f_hz, q, rate);
  return normalized((1.0 - c) / 2.0, 1.0 - c, (1.0 - c) / 2.0, 1.0 + alpha, -2.0 * c, 1.0 - alpha);
}

Biquad highpass(double f_hz, double q, double rate) {
  const auto [c, alpha] = omega(f_hz, q, rate);
  return normalized((1.0 + c) / 2.0, -(1.0 + c), (1.0 + c) / 2.0, 1.0 + alpha, -2.0 * c, 1.0 - alpha);
}

Biquad bandpass(double f_hz, double q, double rate) {
  const auto [c, alpha] = omega(f_hz, q, rate);
  return normalized(alpha, 0.0, -alpha, 1.0 + alpha, -2.0 * c, 1.0 - alpha);
}

}  // namespace eng::audio
