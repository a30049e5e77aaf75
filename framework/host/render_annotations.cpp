#include "framework/host/render_annotations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace voroseal {

namespace {

// The longest scale bar and the axes' length, as fractions of the picture width.
constexpr double kScaleBarWidth = 0.22;
constexpr double kAxisLength = 0.055;

// 5x7 glyphs, one row per byte, bit 4 the leftmost pixel.
struct Glyph {
  char c;
  uint8_t rows[7];
};
constexpr Glyph kFont[] = {
    {'0', {14, 17, 19, 21, 25, 17, 14}}, {'1', {4, 12, 4, 4, 4, 4, 14}},
    {'2', {14, 17, 1, 2, 4, 8, 31}},     {'3', {31, 2, 4, 2, 1, 17, 14}},
    {'4', {2, 6, 10, 18, 31, 2, 2}},     {'5', {31, 16, 30, 1, 1, 17, 14}},
    {'6', {6, 8, 16, 30, 17, 17, 14}},   {'7', {31, 1, 2, 4, 8, 8, 8}},
    {'8', {14, 17, 17, 14, 17, 17, 14}}, {'9', {14, 17, 17, 15, 1, 2, 12}},
    {'.', {0, 0, 0, 0, 0, 12, 12}},      {'-', {0, 0, 0, 31, 0, 0, 0}},
    {'k', {16, 16, 18, 20, 24, 20, 18}}, {'m', {0, 0, 26, 21, 21, 17, 17}},
    {'x', {0, 0, 17, 10, 4, 10, 17}},    {'y', {0, 0, 17, 17, 15, 1, 14}},
    {'z', {0, 0, 31, 2, 4, 8, 31}},
};

const Glyph* glyph(char c) {
  for (const Glyph& g : kFont)
    if (g.c == c) return &g;
  return nullptr;
}

void set_pixel(Image& image, int x, int y, std::array<uint8_t, 3> colour) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  uint8_t* p = &image.rgb[3 * (static_cast<size_t>(y) * image.width + x)];
  for (int k = 0; k < 3; ++k) p[k] = colour[k];
}

// Lightens a rectangle so that what is drawn on it reads over the model.
void veil(Image& image, int x0, int y0, int x1, int y1) {
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) {
      uint8_t* p = &image.rgb[3 * (static_cast<size_t>(y) * image.width + x)];
      for (int k = 0; k < 3; ++k) p[k] = static_cast<uint8_t>(p[k] + (255 - p[k]) * 3 / 4);
    }
}

void draw_line(Image& image, double x0, double y0, double x1, double y1, int half_width,
               std::array<uint8_t, 3> colour) {
  const int steps = std::max(1, static_cast<int>(std::ceil(std::hypot(x1 - x0, y1 - y0) * 2)));
  for (int s = 0; s <= steps; ++s) {
    const double t = static_cast<double>(s) / steps;
    const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
    const int y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
    for (int dy = -half_width; dy <= half_width; ++dy)
      for (int dx = -half_width; dx <= half_width; ++dx) set_pixel(image, x + dx, y + dy, colour);
  }
}

int text_width(const std::string& text, int size) {
  return text.empty() ? 0 : static_cast<int>(text.size()) * 6 * size - size;
}

}  // namespace

double scale_bar_length(double pixels_per_unit, double max_pixels) {
  if (!(pixels_per_unit > 0) || !(max_pixels > 0)) return 0;
  const double longest = max_pixels / pixels_per_unit;
  const double decade = std::pow(10.0, std::floor(std::log10(longest)));
  for (double step : {5.0, 2.0, 1.0})
    if (step * decade <= longest * (1 + 1e-12)) return step * decade;
  return decade;
}

std::string scale_bar_label(double length) {
  char text[32];
  if (length >= 1000)
    std::snprintf(text, sizeof text, "%g km", length / 1000);
  else
    std::snprintf(text, sizeof text, "%g m", length);
  return text;
}

void draw_text(Image& image, int x, int y, const std::string& text, std::array<uint8_t, 3> colour,
               int size) {
  for (size_t i = 0; i < text.size(); ++i) {
    const Glyph* g = glyph(text[i]);
    if (!g) continue;
    const int left = x + static_cast<int>(i) * 6 * size;
    for (int row = 0; row < 7; ++row)
      for (int column = 0; column < 5; ++column)
        if ((g->rows[row] >> (4 - column)) & 1)
          for (int dy = 0; dy < size; ++dy)
            for (int dx = 0; dx < size; ++dx)
              set_pixel(image, left + column * size + dx, y + row * size + dy, colour);
  }
}

void draw_axes_and_scale(Image& image, const ViewScale& view) {
  const int size = image.width >= 480 ? 2 : 1;  // font pixel size
  const int margin = 6 * size;
  const std::array<uint8_t, 3> ink{{34, 34, 38}};

  // Scale bar, lower right: the bar with end ticks, its length above.
  const double length = scale_bar_length(view.pixels_per_unit, kScaleBarWidth * image.width);
  if (length > 0) {
    const int bar = static_cast<int>(std::lround(length * view.pixels_per_unit));
    const std::string label = scale_bar_label(length);
    const int x1 = image.width - margin, x0 = x1 - bar, y = image.height - margin - size;
    const int text_x = (x0 + x1 - text_width(label, size)) / 2, text_y = y - 11 * size;
    veil(image, std::min(x0, text_x) - 3 * size, text_y - 3 * size, x1 + 3 * size, y + 5 * size);
    draw_line(image, x0, y, x1, y, size / 2, ink);
    draw_line(image, x0, y - 3 * size, x0, y + 2 * size, 0, ink);
    draw_line(image, x1, y - 3 * size, x1, y + 2 * size, 0, ink);
    draw_text(image, text_x, text_y, label, ink, size);
  }

  // Axes, lower left: each unit vector as it is seen, the longest kAxisLength of the width.
  double longest = 0;
  for (const auto& a : view.axes) longest = std::max(longest, std::hypot(a[0], a[1]));
  if (!(longest > 0)) return;
  // The origin in the middle of a box that holds any axis and its letter.
  const double reach = kAxisLength * image.width / longest;
  const int box = 2 * (static_cast<int>(std::ceil(kAxisLength * image.width)) + 9 * size);
  const double ox = margin + box / 2.0, oy = image.height - margin - box / 2.0;
  veil(image, margin, image.height - margin - box, margin + box, image.height - margin);
  const std::array<uint8_t, 3> colours[3] = {{{200, 40, 40}}, {{30, 140, 50}}, {{40, 70, 200}}};
  const char* names[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const double ex = ox + reach * view.axes[k][0], ey = oy + reach * view.axes[k][1];
    draw_line(image, ox, oy, ex, ey, size / 2, colours[k]);
    // The letter beyond the tip, centred on the axis' direction.
    const double norm = std::max(std::hypot(ex - ox, ey - oy), 1e-9);
    const double lx = ex + (ex - ox) / norm * 5 * size, ly = ey + (ey - oy) / norm * 5 * size;
    draw_text(image, static_cast<int>(lx - 2.5 * size), static_cast<int>(ly - 3.5 * size), names[k],
              colours[k], size);
  }
}

}  // namespace voroseal
