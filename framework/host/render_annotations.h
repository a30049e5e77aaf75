// Axes and a scale bar drawn over a rendered picture, so that a reader knows which way is north
// and how large the model is without opening it. Text uses a 5x7 pixel font of the few
// characters the labels need (digits, '.', '-', ' ', k m x y z).
#pragma once

#include <array>
#include <string>

#include "framework/host/render.h"

namespace voroseal {

/// What the annotations need of the view.
struct ViewScale {
  double pixels_per_unit = 0;  // picture pixels per model unit, at the bounding box centre
  /// Screen direction (right, down) of the model's x, y and z unit vectors in picture pixels
  /// per unit, so an axis seen end-on is short.
  std::array<std::array<double, 2>, 3> axes{};
};

/// The scale bar's length in model units: 1, 2 or 5 times a power of ten, the longest that
/// fits in `max_pixels`. 0 when pixels_per_unit is not positive.
double scale_bar_length(double pixels_per_unit, double max_pixels);

/// The bar's label: "500 m", "2 km", "0.5 m".
std::string scale_bar_label(double length);

/// Draws text with its top left corner at (x, y), each font pixel `size` picture pixels wide;
/// characters outside the font are left blank.
void draw_text(Image& image, int x, int y, const std::string& text, std::array<uint8_t, 3> colour,
               int size);

/// Draws the axes in the lower left corner and the scale bar in the lower right.
void draw_axes_and_scale(Image& image, const ViewScale& view);

}  // namespace voroseal
