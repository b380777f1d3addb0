#pragma once
// Golden-image comparison, after Filament's renderdiff: exact match first; else a pixel "fails" when any colour
// channel differs by more than `channel_threshold` (in 1/255 units), and the images match while at most
// `max_failing_fraction` of pixels fail. Alpha is ignored (the renderer writes opaque frames).
#include <string>
#include "engine/core/image.h"

namespace eng {

struct CompareTolerance {
  int channel_threshold = 4;            // per-channel |a-b| allowed, in 1/255
  double max_failing_fraction = 0.001;  // 0.1% of pixels may exceed the threshold
};

struct CompareResult {
  bool same_size = false;
  bool exact = false;              // every RGB byte equal
  bool passed = false;             // within tolerance
  long failing_pixels = 0;         // pixels with a channel over the threshold
  double failing_fraction = 0.0;
  int max_channel_diff = 0;        // largest |a-b| of any channel
  double mean_abs_diff = 0.0;      // mean over all RGB channels, in 1/255
  std::string summary() const;
};

CompareResult compare_images(const Image& actual, const Image& golden, const CompareTolerance& tol = {});

// A diff picture a person can read: the golden in grey, failing pixels in red scaled by their difference, and the
// whole thing magnified `scale` times (nearest neighbour) so single-pixel differences are visible.
Image make_diff_image(const Image& actual, const Image& golden, const CompareTolerance& tol = {}, int scale = 2);

}  // namespace eng
