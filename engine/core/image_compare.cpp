#include "engine/core/image_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace eng {

std::string CompareResult::summary() const {
  if (!same_size) return "image sizes differ";
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s: %ld pixels (%.4f%%) over threshold, max channel diff %d/255, mean %.3f/255",
                exact ? "exact match" : (passed ? "within tolerance" : "MISMATCH"), failing_pixels,
                failing_fraction * 100.0, max_channel_diff, mean_abs_diff);
  return buf;
}

CompareResult compare_images(const Image& actual, const Image& golden, const CompareTolerance& tol) {
  CompareResult r;
  r.same_size = actual.width == golden.width && actual.height == golden.height && actual.width > 0 &&
                actual.rgba.size() == golden.rgba.size();
  if (!r.same_size) return r;
  const long n = long(actual.width) * actual.height;
  double sum = 0.0;
  for (long i = 0; i < n; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      int d = std::abs(int(actual.rgba[i * 4 + c]) - int(golden.rgba[i * 4 + c]));
      worst = std::max(worst, d);
      sum += d;
    }
    r.max_channel_diff = std::max(r.max_channel_diff, worst);
    if (worst > tol.channel_threshold) ++r.failing_pixels;
  }
  r.exact = r.max_channel_diff == 0;
  r.failing_fraction = double(r.failing_pixels) / double(n);
  r.mean_abs_diff = sum / double(n * 3);
  r.passed = r.exact || r.failing_fraction <= tol.max_failing_fraction;
  return r;
}

Image make_diff_image(const Image& actual, const Image& golden, const CompareTolerance& tol, int scale) {
  const int w = std::min(actual.width, golden.width), h = std::min(actual.height, golden.height);
  scale = std::max(1, scale);
  Image out;
  out.width = w * scale;
  out.height = h * scale;
  out.rgba.assign(size_t(out.width) * out.height * 4, 255);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* a = actual.at(x, y);
      const uint8_t* g = golden.at(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a[c]) - int(g[c])));
      uint8_t px[4];
      if (worst > tol.channel_threshold) {
        px[0] = 255;
        px[1] = px[2] = uint8_t(std::max(0, 160 - worst * 4));
      } else if (worst > 0) {
        px[0] = 255; px[1] = 200; px[2] = 0;  // small, tolerated differences in amber
      } else {
        uint8_t grey = uint8_t((int(g[0]) + g[1] + g[2]) / 9 + 150);  // faint golden for orientation
        px[0] = px[1] = px[2] = grey;
      }
      px[3] = 255;
      for (int sy = 0; sy < scale; ++sy)
        for (int sx = 0; sx < scale; ++sx) std::copy(px, px + 4, out.at(x * scale + sx, y * scale + sy));
    }
  return out;
}

}  // namespace eng
