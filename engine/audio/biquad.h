#pragma once
// Second-order IIR filters (biquads) from Robert Bristow-Johnson's "Cookbook formulae for audio EQ biquad filter
// coefficients" (the W3C Audio EQ Cookbook): low-pass, high-pass and band-pass (constant 0 dB peak gain), each
// H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2) with the coefficients divided by a0. The synthesizer
// shapes its noise with them at start-up (double precision: the sounds are made once, not per frame).
namespace eng::audio {

struct Biquad {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0, a1 = 0.0, a2 = 0.0;
  double z1 = 0.0, z2 = 0.0;  // transposed direct form II state
  double process(double x) {
    const double y = b0 * x + z1;
    z1 = b1 * x - a1 * y + z2;
    z2 = b2 * x - a2 * y;
    return y;
  }
};

// Cut-off / centre frequency f_hz (0 < f_hz < rate / 2), quality q (0.7071: Butterworth for low / high pass; for the
// band-pass the bandwidth is f_hz / q).
Biquad lowpass(double f_hz, double q, double rate);
Biquad highpass(double f_hz, double q, double rate);
Biquad bandpass(double f_hz, double q, double rate);

}  // namespace eng::audio
