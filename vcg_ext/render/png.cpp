#include "render/png.h"

#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace fcql::render {

namespace {

const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

void putBigEndian(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xff));
}

std::uint32_t getBigEndian(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = (v << 8) | std::uint8_t(s[at + i]);
  return v;
}

void putChunk(std::string& out, const char type[4], const std::string& data) {
  putBigEndian(out, std::uint32_t(data.size()));
  std::string body(type, 4);
  body += data;
  out += body;
  putBigEndian(out, pngCrc(body.data(), body.size()));
}

int paeth(int a, int b, int c) {
  int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

// Filter byte k of a row with filter type `type`: x is the byte, a its left neighbour (3 bytes
// back), b the byte above, c the byte above-left; all 0 outside the picture.
std::uint8_t predictor(int type, int a, int b, int c) {
  switch (type) {
    case 1: return std::uint8_t(a);
    case 2: return std::uint8_t(b);
    case 3: return std::uint8_t((a + b) / 2);
    case 4: return std::uint8_t(paeth(a, b, c));
    default: return 0;
  }
}

}  // namespace

Image::Image(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) : width(w), height(h), rgb(std::size_t(w) * h * 3) {
  for (std::size_t i = 0; i < rgb.size(); i += 3) rgb[i] = r, rgb[i + 1] = g, rgb[i + 2] = b;
}

std::uint32_t pngCrc(const void* data, std::size_t size, std::uint32_t crc) {
  return std::uint32_t(crc32(crc, static_cast<const Bytef*>(data), uInt(size)));
}

std::string encodePng(const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != std::size_t(image.width) * image.height * 3)
    throw PngError("cannot encode an empty or inconsistent image");
  const std::size_t stride = std::size_t(image.width) * 3;
  // Each row gets the filter whose output has the smallest sum of |signed bytes| (the usual
  // heuristic): flat colours compress best unfiltered, shading best with Sub/Up/Paeth.
  std::string raw;
  raw.reserve((stride + 1) * image.height);
  std::vector<std::uint8_t> best(stride), trial(stride);
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* row = &image.rgb[y * stride];
    const std::uint8_t* up = y > 0 ? row - stride : nullptr;
    long bestCost = -1;
    int bestType = 0;
    for (int type = 0; type <= 4; ++type) {
      long cost = 0;
      for (std::size_t k = 0; k < stride; ++k) {
        int a = k >= 3 ? row[k - 3] : 0, b = up ? up[k] : 0, c = (up && k >= 3) ? up[k - 3] : 0;
        trial[k] = std::uint8_t(row[k] - predictor(type, a, b, c));
        cost += std::abs(int(std::int8_t(trial[k])));
      }
      if (bestCost < 0 || cost < bestCost) bestCost = cost, bestType = type, best.swap(trial);
    }
    raw.push_back(char(bestType));
    raw.append(reinterpret_cast<const char*>(best.data()), stride);
  }
  uLongf packedSize = compressBound(uLong(raw.size()));
  std::string packed(packedSize, '\0');
  if (compress2(reinterpret_cast<Bytef*>(&packed[0]), &packedSize, reinterpret_cast<const Bytef*>(raw.data()),
                uLong(raw.size()), 9) != Z_OK)
    throw PngError("zlib could not compress the image");
  packed.resize(packedSize);

  std::string out(reinterpret_cast<const char*>(kSignature), 8);
  std::string header;
  putBigEndian(header, std::uint32_t(image.width));
  putBigEndian(header, std::uint32_t(image.height));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, adaptive filters, no interlace
  putChunk(out, "IHDR", header);
  putChunk(out, "IDAT", packed);
  putChunk(out, "IEND", "");
  return out;
}

Image decodePng(const std::string& bytes) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) throw PngError("not a PNG file (bad signature)");
  std::size_t at = 8;
  int width = 0, height = 0;
  bool seenHeader = false, seenEnd = false;
  std::string packed;
  while (!seenEnd) {
    if (at + 12 > bytes.size()) throw PngError("truncated PNG (chunk header past the end)");
    std::uint32_t length = getBigEndian(bytes, at);
    std::string type = bytes.substr(at + 4, 4);
    if (length > bytes.size() - at - 12) throw PngError("truncated PNG (chunk " + type + " past the end)");
    std::uint32_t crc = getBigEndian(bytes, at + 8 + length);
    if (crc != pngCrc(bytes.data() + at + 4, length + 4)) throw PngError("CRC mismatch in chunk " + type);
    std::string data = bytes.substr(at + 8, length);
    at += 12 + length;
    if (!seenHeader && type != "IHDR") throw PngError("first chunk is " + type + ", not IHDR");
    if (type == "IHDR") {
      if (seenHeader || length != 13) throw PngError("bad IHDR chunk");
      width = int(getBigEndian(data, 0));
      height = int(getBigEndian(data, 4));
      if (width <= 0 || height <= 0 || width > 1 << 15 || height > 1 << 15) throw PngError("bad image size in IHDR");
      if (data[8] != 8 || data[9] != 2 || data[10] != 0 || data[11] != 0 || data[12] != 0)
        throw PngError("unsupported PNG format (only 8-bit RGB, non-interlaced)");
      seenHeader = true;
    } else if (type == "IDAT") {
      packed += data;
    } else if (type == "IEND") {
      seenEnd = true;
    }
  }
  const std::size_t stride = std::size_t(width) * 3;
  uLongf rawSize = uLongf((stride + 1) * height);
  std::string raw(rawSize, '\0');
  uLongf produced = rawSize;
  if (uncompress(reinterpret_cast<Bytef*>(&raw[0]), &produced, reinterpret_cast<const Bytef*>(packed.data()),
                 uLong(packed.size())) != Z_OK ||
      produced != rawSize)
    throw PngError("bad or short compressed image data");
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    int type = std::uint8_t(raw[y * (stride + 1)]);
    if (type > 4) throw PngError("bad row filter type " + std::to_string(type));
    const std::uint8_t* in = reinterpret_cast<const std::uint8_t*>(&raw[y * (stride + 1) + 1]);
    std::uint8_t* row = image.pixel(0, y);
    const std::uint8_t* up = y > 0 ? row - stride : nullptr;
    for (std::size_t k = 0; k < stride; ++k) {
      int a = k >= 3 ? row[k - 3] : 0, b = up ? up[k] : 0, c = (up && k >= 3) ? up[k - 3] : 0;
      row[k] = std::uint8_t(in[k] + predictor(type, a, b, c));
    }
  }
  return image;
}

void savePng(const Image& image, const std::string& path) {
  std::string bytes = encodePng(image);
  std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out.flush()) {
      std::remove(temporary.c_str());
      throw std::runtime_error("cannot write " + path);
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + path);
  }
}

}  // namespace fcql::render
