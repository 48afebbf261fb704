// 8-bit RGB PNG output through libpng.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rc {

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // row-major, 3 bytes per pixel, top row first
};

// Throws std::runtime_error naming the path when the file cannot be written.
void write_png(const std::string& path, const RgbImage& image);

}  // namespace rc
