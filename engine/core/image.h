#pragma once
// Image: 8-bit RGBA pixels in memory, and PNG read/write (stb).
#include <cstdint>
#include <string>
#include <vector>
#include "engine/core/result.h"

namespace eng {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // row-major, top row first, 4 bytes per pixel
  uint8_t* at(int x, int y) { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  const uint8_t* at(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
};

Result<void> write_png(const Image& img, const std::string& path);
Result<Image> read_png(const std::string& path);

}  // namespace eng
