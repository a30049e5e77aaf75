#include "framework/host/render.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>

#include "framework/core/error.h"
#include "framework/host/render_annotations.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

uint32_t read32(const std::vector<uint8_t>& b, size_t at) {
  return (uint32_t(b[at]) << 24) | (uint32_t(b[at + 1]) << 16) | (uint32_t(b[at + 2]) << 8) |
         b[at + 3];
}

// Decodes what encode_png writes (one IDAT, filter 0), checking every chunk's CRC.
Image decode_png(const std::vector<uint8_t>& png) {
  const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  EXPECT_TRUE(std::equal(signature, signature + 8, png.begin()));
  Image image;
  std::vector<uint8_t> idat;
  size_t at = 8;
  bool ended = false;
  while (at + 12 <= png.size()) {
    const uint32_t length = read32(png, at);
    const std::string tag(png.begin() + at + 4, png.begin() + at + 8);
    const uint32_t crc = read32(png, at + 8 + length);
    EXPECT_EQ(crc, crc32(0L, &png[at + 4], length + 4)) << tag;
    if (tag == "IHDR") {
      image.width = static_cast<int>(read32(png, at + 8));
      image.height = static_cast<int>(read32(png, at + 12));
      EXPECT_EQ(png[at + 16], 8);  // bit depth
      EXPECT_EQ(png[at + 17], 2);  // truecolour
    } else if (tag == "IDAT") {
      idat.insert(idat.end(), png.begin() + at + 8, png.begin() + at + 8 + length);
    } else if (tag == "IEND") {
      ended = true;
    }
    at += 12 + length;
  }
  EXPECT_TRUE(ended);
  EXPECT_EQ(at, png.size());
  std::vector<uint8_t> raw((3 * size_t(image.width) + 1) * image.height);
  uLongf size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &size, idat.data(), idat.size()), Z_OK);
  EXPECT_EQ(size, raw.size());
  image.rgb.clear();
  for (int y = 0; y < image.height; ++y) {
    const size_t row = y * (3 * size_t(image.width) + 1);
    EXPECT_EQ(raw[row], 0);
    image.rgb.insert(image.rgb.end(), raw.begin() + row + 1,
                     raw.begin() + row + 1 + 3 * image.width);
  }
  return image;
}

TEST(Png, RoundTripsThePixels) {
  Image image;
  image.width = 37;
  image.height = 11;
  for (int i = 0; i < 3 * 37 * 11; ++i) image.rgb.push_back(static_cast<uint8_t>((i * 7919) % 251));
  const Image back = decode_png(encode_png(image));
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 11);
  EXPECT_EQ(back.rgb, image.rgb);
}

TEST(Png, RejectsAnImageWhosePixelsDoNotMatchItsSize) {
  Image image;
  image.width = 4;
  image.height = 4;
  image.rgb.resize(10);
  EXPECT_THROW(encode_png(image), ParameterError);
}

// Pixels whose colour is a shade (0.3..1 times) of the base colour of part `part`.
long pixels_of_part(const Image& image, int part) {
  const auto base = surface_colour(part);
  long count = 0;
  for (size_t p = 0; p < image.rgb.size(); p += 3) {
    const int m = base[0] >= base[1] && base[0] >= base[2] ? 0 : base[1] >= base[2] ? 1 : 2;
    const double k = image.rgb[p + m] / double(base[m]);
    if (k < 0.3 || k > 1.01) continue;
    bool shade = true;
    for (int c = 0; c < 3; ++c) shade = shade && std::abs(image.rgb[p + c] - k * base[c]) <= 3.0;
    count += shade;
  }
  return count;
}

int part_of_interface(const StructuralModel& model, const std::string& name) {
  for (size_t p = 0; p < model.parts.size(); ++p)
    if (model.interfaces[model.parts[p].interface].name == name) return static_cast<int>(p);
  return -1;
}

RenderOptions plain_options() {
  RenderOptions options;
  options.width = 160;
  options.height = 120;
  options.supersample = 1;  // no blending: every pixel is one triangle's colour
  options.edges = EdgeDrawing::Never;
  options.contacts = false;
  return options;
}

TEST(Render, TheCutAwayShowsTheHorizonInsideTheBox) {
  const StructuralModel model = build_model(test::lattice_box(4, true));
  const int horizon = part_of_interface(model, "horizon");
  ASSERT_GE(horizon, 0);
  RenderOptions options = plain_options();
  options.cut_away = false;
  const Image closed = render_model(model, options);
  EXPECT_EQ(pixels_of_part(closed, horizon), 0) << "the horizon is hidden inside a closed box";
  options.cut_away = true;
  const Image open = render_model(model, options);
  EXPECT_GT(pixels_of_part(open, horizon), 0.05 * 160 * 120);
}

TEST(Render, TheZBufferKeepsTheNearestSurface) {
  // Seen from straight above with nothing cut, only the top of the box shows.
  const StructuralModel model = build_model(test::lattice_box(2, false));
  RenderOptions options = plain_options();
  options.cut_away = false;
  options.elevation_deg = 90.0;
  const Image image = render_model(model, options);
  const int top = part_of_interface(model, "zmax");
  const int bottom = part_of_interface(model, "zmin");
  ASSERT_GE(top, 0);
  ASSERT_GE(bottom, 0);
  EXPECT_GT(pixels_of_part(image, top), 0.3 * 160 * 120);
  EXPECT_EQ(pixels_of_part(image, bottom), 0);
}

TEST(Render, PerspectiveAndOrthographicViewsDiffer) {
  const StructuralModel model = build_model(test::lattice_box(2, true));
  RenderOptions options = plain_options();
  const Image ortho = render_model(model, options);
  options.perspective = true;
  const Image perspective = render_model(model, options);
  long background = 0;
  for (size_t p = 0; p < perspective.rgb.size(); p += 3)
    background += perspective.rgb[p] == options.background[0] &&
                  perspective.rgb[p + 1] == options.background[1];
  EXPECT_LT(background, 0.8 * 160 * 120);
  EXPECT_NE(ortho.rgb, perspective.rgb);
}

TEST(Render, EdgesAndContactsAreDrawnDark) {
  const StructuralModel model = build_model(test::lattice_box(2, true));
  RenderOptions options = plain_options();
  const Image plain = render_model(model, options);
  options.contacts = true;
  options.edges = EdgeDrawing::Always;
  const Image lined = render_model(model, options);
  auto dark = [](const Image& image) {
    long n = 0;
    for (size_t p = 0; p < image.rgb.size(); p += 3)
      n += image.rgb[p] < 40 && image.rgb[p + 1] < 40;
    return n;
  };
  EXPECT_EQ(dark(plain), 0);
  EXPECT_GT(dark(lined), 100);
}

TEST(Render, AnEmptyModelGivesTheBackgroundAndBadSizesThrow) {
  const StructuralModel empty;
  RenderOptions options = plain_options();
  const Image image = render_model(empty, options);
  ASSERT_EQ(image.rgb.size(), 3u * 160 * 120);
  EXPECT_EQ(image.rgb[0], options.background[0]);
  options.width = 2;
  EXPECT_THROW(render_model(empty, options), ParameterError);
  options.width = 100;
  options.supersample = 9;
  EXPECT_THROW(render_model(empty, options), ParameterError);
}

TEST(Render, ColoursOfNeighbouringPartsDiffer) {
  for (int i = 0; i < 40; ++i) {
    const auto a = surface_colour(i), b = surface_colour(i + 1);
    EXPECT_GT(std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]), 60) << i;
  }
}

TEST(Render, ScaleBarsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(scale_bar_length(0.1, 176), 1000);  // 1,760 units fit
  EXPECT_DOUBLE_EQ(scale_bar_length(0.1, 250), 2000);
  EXPECT_DOUBLE_EQ(scale_bar_length(2, 150), 50);
  EXPECT_DOUBLE_EQ(scale_bar_length(400, 100), 0.2);
  EXPECT_EQ(scale_bar_length(0, 100), 0);
  EXPECT_EQ(scale_bar_label(2000), "2 km");
  EXPECT_EQ(scale_bar_label(500), "500 m");
  EXPECT_EQ(scale_bar_label(0.5), "0.5 m");
}

TEST(Render, AxesAndScaleBarAreDrawnInTheLowerCorners) {
  const StructuralModel model = build_model(test::lattice_box(2, true));
  RenderOptions options = plain_options();
  options.width = 480;
  options.height = 320;
  const Image plain = render_model(model, options);
  options.axes_and_scale = true;
  const Image annotated = render_model(model, options);
  // Dark ink (the bar and its label) on the right, the red x axis on the left, low down.
  long ink = 0, red = 0, changed_above = 0;
  for (int y = 0; y < annotated.height; ++y)
    for (int x = 0; x < annotated.width; ++x) {
      const uint8_t* p = &annotated.rgb[3 * (size_t(y) * annotated.width + x)];
      const uint8_t* q = &plain.rgb[3 * (size_t(y) * plain.width + x)];
      const bool bottom = y > 0.6 * annotated.height;
      if (!bottom) changed_above += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
      if (bottom && x > annotated.width / 2 && p[0] < 60 && p[1] < 60 && p[2] < 60) ++ink;
      if (bottom && x < annotated.width / 4 && p[0] > 150 && p[1] < 80 && p[2] < 80) ++red;
    }
  EXPECT_GT(ink, 100);
  EXPECT_GT(red, 20);
  EXPECT_EQ(changed_above, 0) << "the annotations stay in the lower corners";
}

}  // namespace
}  // namespace voroseal
