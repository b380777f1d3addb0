#include "engine/core/image_compare.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

eng::Image checker(int w, int h, int shift_x = 0) {
  eng::Image img;
  img.width = w;
  img.height = h;
  img.rgba.resize(size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool on = (((x + shift_x) / 8) + (y / 8)) % 2 == 0;
      uint8_t* p = img.at(x, y);
      p[0] = on ? 220 : 30;
      p[1] = on ? 200 : 60;
      p[2] = uint8_t((x * 255) / w);
      p[3] = 255;
    }
  return img;
}

TEST(ImageCompare, IdenticalImagesMatchExactly) {
  auto a = checker(64, 48);
  auto r = eng::compare_images(a, a);
  EXPECT_TRUE(r.exact);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.failing_pixels, 0);
}

TEST(ImageCompare, ShiftedImageFails) {
  auto r = eng::compare_images(checker(64, 48, 1), checker(64, 48));
  EXPECT_FALSE(r.passed);
  EXPECT_GT(r.failing_fraction, 0.05);
}

TEST(ImageCompare, RecolouredImageFails) {
  auto a = checker(64, 48), b = a;
  for (size_t i = 0; i < b.rgba.size(); i += 4) b.rgba[i] = uint8_t(255 - b.rgba[i]);  // red channel inverted
  EXPECT_FALSE(eng::compare_images(b, a).passed);
}

TEST(ImageCompare, SlightRecolourOfOneRegionFailsWhenOverThreshold) {
  auto a = checker(100, 100), b = a;
  for (int y = 0; y < 10; ++y)  // 100 pixels = 1% with a +6/255 shift: over a 4/255 threshold
    for (int x = 0; x < 10; ++x) b.at(x, y)[1] = uint8_t(b.at(x, y)[1] + 6);
  auto r = eng::compare_images(b, a);
  EXPECT_EQ(r.failing_pixels, 100);
  EXPECT_FALSE(r.passed);
}

TEST(ImageCompare, NoiseUnderThresholdOrOnFewPixelsPasses) {
  auto a = checker(100, 100), b = a;
  for (size_t i = 0; i < b.rgba.size(); i += 4) b.rgba[i + 1] = uint8_t(b.rgba[i + 1] + ((i / 4) % 3));  // <= 2/255
  uint8_t& r0 = b.at(50, 50)[0];
  r0 = uint8_t(r0 > 128 ? r0 - 100 : r0 + 100);  // a single pixel (0.01%) far off
  auto r = eng::compare_images(b, a);
  EXPECT_FALSE(r.exact);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.failing_pixels, 1);
  EXPECT_EQ(r.max_channel_diff, 100);
}

TEST(ImageCompare, DifferentSizesFail) {
  auto r = eng::compare_images(checker(64, 48), checker(64, 40));
  EXPECT_FALSE(r.same_size);
  EXPECT_FALSE(r.passed);
}

TEST(ImageCompare, DiffImageMarksFailingPixelsRedAndMagnifies) {
  auto a = checker(32, 32), b = a;
  b.at(5, 7)[2] = uint8_t(b.at(5, 7)[2] ^ 0x80);
  auto d = eng::make_diff_image(b, a, {}, 4);
  ASSERT_EQ(d.width, 128);
  ASSERT_EQ(d.height, 128);
  const uint8_t* p = d.at(5 * 4 + 2, 7 * 4 + 1);
  EXPECT_EQ(p[0], 255);
  EXPECT_LT(p[1], 100);
  const uint8_t* q = d.at(0, 0);
  EXPECT_EQ(q[0], q[1]);  // unchanged pixels are grey
}

TEST(ImageIo, PngRoundTripIsLossless) {
  auto a = checker(33, 17);
  auto path = (std::filesystem::temp_directory_path() / "boxing_png_roundtrip.png").string();
  ASSERT_TRUE(eng::write_png(a, path).ok());
  auto b = eng::read_png(path);
  ASSERT_TRUE(b.ok()) << b.error();
  EXPECT_TRUE(eng::compare_images(*b, a).exact);
}

TEST(ImageIo, MissingPngGivesClearError) {
  auto b = eng::read_png("/nonexistent/golden.png");
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().find("missing image"), std::string::npos);
}

}  // namespace
