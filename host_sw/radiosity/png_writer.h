// 8-bit RGB PNG output through libpng: encoded in memory, then written atomically (io/output_file.h),
// so a failed or interrupted write never leaves half a picture.
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

// The PNG file's bytes. Throws std::runtime_error if libpng fails or the image's pixels do not
// match its size.
std::string encode_png(const RgbImage& image);

// encode_png, then io::write_file_atomically. Throws io::OutputFileError naming the path when the
// file cannot be written (and std::runtime_error as encode_png).
void write_png(const std::string& path, const RgbImage& image);

}  // namespace rc
