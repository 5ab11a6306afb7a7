// The renderer's PNG encoder/decoder and rasterizer (vcg_ext/render).
#include "render/png.h"
#include "render/rasterizer.h"

#include <gtest/gtest.h>

#include <set>

using namespace fcql::render;

namespace {

Image gradient(int w, int h) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = im.pixel(x, y);
      p[0] = std::uint8_t(x * 7 + y), p[1] = std::uint8_t(y * 3), p[2] = std::uint8_t((x * y) % 251);
    }
  return im;
}

std::uint32_t bigEndian(const std::string& s, std::size_t at) {
  return std::uint32_t(std::uint8_t(s[at])) << 24 | std::uint32_t(std::uint8_t(s[at + 1])) << 16 |
         std::uint32_t(std::uint8_t(s[at + 2])) << 8 | std::uint8_t(s[at + 3]);
}

std::string errorOf(const std::string& bytes) {
  try {
    decodePng(bytes);
  } catch (const PngError& e) {
    return e.what();
  }
  return "";
}

CameraSetup frontCamera() {
  CameraSetup cam;  // up y, azimuth 0, elevation 0: looking along -z at the unit sphere
  cam.azimuthDeg = 0, cam.elevationDeg = 0;
  return cam;
}

const Rgb kWhite{255, 255, 255}, kRed{200, 0, 0}, kBlue{0, 0, 200}, kBlack{0, 0, 0};

bool same(const std::uint8_t* p, Rgb c) { return p[0] == c.r && p[1] == c.g && p[2] == c.b; }

}  // namespace

TEST(Png, CrcMatchesTheStandardValue) {
  EXPECT_EQ(pngCrc("IEND", 4), 0xAE426082u);
  EXPECT_EQ(pngCrc("123456789", 9), 0xCBF43926u);
}

TEST(Png, EncodesSignatureHeaderAndChunks) {
  std::string png = encodePng(gradient(37, 21));
  ASSERT_GT(png.size(), 8u + 25 + 12 + 12);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(bigEndian(png, 8), 13u);
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  EXPECT_EQ(bigEndian(png, 16), 37u);
  EXPECT_EQ(bigEndian(png, 20), 21u);
  EXPECT_EQ(png[24], 8);  // bit depth
  EXPECT_EQ(png[25], 2);  // RGB
  EXPECT_EQ(bigEndian(png, 29), pngCrc(png.data() + 12, 17));
  EXPECT_EQ(png.substr(png.size() - 12), std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12));
}

TEST(Png, RoundTripsEveryPixel) {
  for (auto [w, h] : {std::pair{1, 1}, std::pair{37, 21}, std::pair{200, 3}}) {
    Image in = gradient(w, h);
    Image out = decodePng(encodePng(in));
    EXPECT_EQ(out.width, w);
    EXPECT_EQ(out.height, h);
    EXPECT_EQ(out.rgb, in.rgb);
  }
}

TEST(Png, FlatPicturesCompressWell) {
  Image flat(400, 300, 250, 250, 250);
  EXPECT_LT(encodePng(flat).size(), 4000u);
}

TEST(Png, DecoderRejectsDamagedFiles) {
  std::string png = encodePng(gradient(20, 20));
  EXPECT_NE(errorOf("GIF89a"), "");
  EXPECT_NE(errorOf(png.substr(0, png.size() - 20)).find("truncated"), std::string::npos);
  std::string flipped = png;
  flipped[50] ^= 0x10;  // inside IDAT
  EXPECT_NE(errorOf(flipped).find("CRC mismatch in chunk IDAT"), std::string::npos);
  EXPECT_THROW(encodePng(Image()), PngError);
}

TEST(Rasterizer, TriangleFacingTheCameraCoversTheCentreOnly) {
  Rasterizer r(64, 64, frontCamera(), kWhite, 2);
  r.triangle({-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}, kRed);
  Image im = r.finish();
  const std::uint8_t* c = im.pixel(32, 36);
  EXPECT_GT(c[0], 150);  // lit from the camera side: close to the full colour
  EXPECT_EQ(c[1], 0);
  EXPECT_TRUE(same(im.pixel(0, 0), kWhite));
  EXPECT_TRUE(same(im.pixel(63, 63), kWhite));
  EXPECT_TRUE(same(im.pixel(32, 3), kWhite));
}

TEST(Rasterizer, NearerSurfaceWinsInEitherOrder) {
  for (int order = 0; order < 2; ++order) {
    Rasterizer r(32, 32, frontCamera(), kWhite, 1);
    auto nearRed = [&] { r.triangle({-1, -1, 0.5}, {1, -1, 0.5}, {0, 1, 0.5}, kRed); };
    auto farBlue = [&] { r.triangle({-1, -1, -0.5}, {1, -1, -0.5}, {0, 1, -0.5}, kBlue); };
    if (order) nearRed(), farBlue();
    else farBlue(), nearRed();
    Image im = r.finish();
    EXPECT_GT(im.pixel(16, 18)[0], 100) << "order " << order;
    EXPECT_EQ(im.pixel(16, 18)[2], 0) << "order " << order;
  }
}

TEST(Rasterizer, LinesShowOnTheSurfaceNotBehindIt) {
  Rasterizer r(64, 64, frontCamera(), kWhite, 1);
  r.triangle({-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, kRed);
  r.triangle({-1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, kRed);
  r.line({-0.5, 0.3, 0}, {0.5, 0.3, 0}, 3, kBlack);    // on the square
  r.line({-0.5, -0.3, -0.5}, {0.5, -0.3, -0.5}, 3, kBlack);  // behind it
  Image im = r.finish();
  int onTop = 0, behind = 0;
  for (int x = 20; x < 44; ++x)
    for (int y = 0; y < 64; ++y) {
      if (!same(im.pixel(x, y), kBlack)) continue;
      (y < 32 ? onTop : behind)++;
    }
  EXPECT_GT(onTop, 24 * 2);
  EXPECT_EQ(behind, 0);
}

TEST(Rasterizer, DotsHiddenBehindTheSurfaceAreNotDrawn) {
  auto bluePixels = [](bool hiddenToo) {
    Rasterizer r(64, 64, frontCamera(), kWhite, 1);
    r.triangle({-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, kRed);
    r.dot({0, 0, 0}, 3, kBlue, 1, kBlack);                    // on the surface
    if (hiddenToo) r.dot({0, -0.5, -0.5}, 3, kBlue, 1, kBlack);  // behind it
    Image im = r.finish();
    int blue = 0;
    for (std::size_t i = 0; i < im.rgb.size(); i += 3) blue += same(&im.rgb[i], kBlue);
    return blue;
  };
  int one = bluePixels(false);
  EXPECT_GT(one, 15);  // about π·3²
  EXPECT_LT(one, 40);
  EXPECT_EQ(bluePixels(true), one);
}

TEST(Rasterizer, FrameFillsThePicture) {
  Rasterizer r(100, 100, frontCamera(), kWhite, 1);
  std::vector<fcql::render::Vec3> pts = {{2, 2, 0}, {2.2, 2, 0}, {2.1, 2.2, 0}};
  r.frame(pts, 1.0);
  r.triangle(pts[0], pts[1], pts[2], kRed);
  Image im = r.finish();
  int covered = 0;
  for (std::size_t i = 0; i < im.rgb.size(); i += 3) covered += !(im.rgb[i] == 255 && im.rgb[i + 1] == 255);
  EXPECT_GT(covered, 100 * 100 * 0.4);  // a triangle spanning the frame covers about half of it
}
