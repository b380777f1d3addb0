#include "engine/core/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <filesystem>

namespace eng {

Result<void> write_png(const Image& img, const std::string& path) {
  if (img.width <= 0 || img.height <= 0 || img.rgba.size() != size_t(img.width) * img.height * 4)
    return make_error("write_png: image is empty or malformed (" + path + ")");
  std::error_code ec;
  auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (!stbi_write_png(path.c_str(), img.width, img.height, 4, img.rgba.data(), img.width * 4))
    return make_error("cannot write PNG '" + path + "': check that the folder exists and is writable");
  return {};
}

Result<Image> read_png(const std::string& path) {
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!data) {
    if (!std::filesystem::exists(path)) return make_error("missing image '" + path + "'");
    return make_error("cannot decode PNG '" + path + "': " + stbi_failure_reason());
  }
  Image img;
  img.width = w;
  img.height = h;
  img.rgba.assign(data, data + size_t(w) * h * 4);
  stbi_image_free(data);
  return img;
}

}  // namespace eng
