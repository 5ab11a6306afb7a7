// PNG files for the renderer: 8-bit RGB, non-interlaced, compressed with zlib. The decoder
// reads back what the encoder writes (8-bit RGB, any of the five row filters) and checks every
// chunk CRC; it exists for tests and for tools that inspect pictures, not for general PNGs.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace fcql::render {

/// An RGB picture, rows top to bottom, 3 bytes per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;

  Image() = default;
  Image(int w, int h, std::uint8_t r = 0, std::uint8_t g = 0, std::uint8_t b = 0);
  std::uint8_t* pixel(int x, int y) { return &rgb[3 * (std::size_t(y) * width + x)]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgb[3 * (std::size_t(y) * width + x)]; }
};

struct PngError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The bytes of a PNG file holding `image` (rows filtered adaptively, then deflated).
std::string encodePng(const Image& image);

/// Decodes an 8-bit RGB non-interlaced PNG; throws PngError naming the problem (bad signature,
/// truncated chunk, CRC mismatch, unsupported format, bad compressed data, wrong size).
Image decodePng(const std::string& bytes);

/// Writes encodePng(image) to `path` (through a temporary file renamed into place); throws
/// std::runtime_error if the file cannot be written.
void savePng(const Image& image, const std::string& path);

/// The CRC-32 of PNG chunks (ISO 3309), over `size` bytes.
std::uint32_t pngCrc(const void* data, std::size_t size, std::uint32_t crc = 0);

}  // namespace fcql::render
