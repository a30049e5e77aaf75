// A small software rasteriser for looking at a StructuralModel without ParaView: z-buffer,
// flat two-sided shading, one colour per surface part (or interface), contacts drawn as dark
// lines, triangle edges when they are large enough to see, an optional cut-away of the box
// sides that face the viewer, orthographic or perspective view, optional axes and scale bar.
// Output: PNG (zlib deflate). Used by the study reports (pictures of each run) and the Python
// module; volume_cut.h draws tet meshes through render_scene().
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "framework/model/structural_model.h"

namespace voroseal {

/// An 8-bit RGB image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;  // 3 * width * height
};

enum class ColourBy { Part, Interface };
enum class EdgeDrawing { Auto, Always, Never };

struct RenderOptions {
  int width = 800;
  int height = 560;
  int supersample = 2;          // anti-aliasing: rendered at this factor, then averaged
  double azimuth_deg = 210.0;   // where the viewer stands, clockwise from north (+y)
  double elevation_deg = 28.0;  // above the horizontal
  double vertical_exaggeration = 1.0;
  bool perspective = false;         // orthographic by default
  double field_of_view_deg = 30.0;  // perspective only
  ColourBy colour_by = ColourBy::Part;
  /// Hide the triangles lying on the sides of the model's bounding box that face the viewer,
  /// so horizons and faults inside the box are visible.
  bool cut_away = true;
  /// Triangle edges: Auto draws them when the mean edge is at least `min_edge_pixels` long.
  EdgeDrawing edges = EdgeDrawing::Auto;
  double min_edge_pixels = 5.0;
  bool contacts = true;  // draw contact lines
  /// Axes (x east, y north, z up) in the lower left corner and a scale bar in the lower right.
  bool axes_and_scale = false;
  std::array<uint8_t, 3> background{{246, 246, 242}};
};

/// Colour of surface part (or interface) number `index`: distinct hues from the golden ratio.
std::array<uint8_t, 3> surface_colour(int index);

/// Renders the model. The view frames the model's whole bounding box (cut parts included), so
/// pictures of one model at several resolutions line up.
/// \throws ParameterError on a size outside [16, 8192] or a supersample outside [1, 4].
Image render_model(const StructuralModel& model, const RenderOptions& options = {});

/// Triangles with colours of their own, drawn the way render_model draws a model's surfaces.
struct TriangleScene {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
  std::vector<std::array<uint8_t, 3>> colours;  // one per triangle
  /// One per triangle, or empty: bit i set when the edge opposite corner i is a dark line.
  std::vector<uint8_t> lines;
  BoundingBox frame;  // what the view frames and what the cut-away cuts
};

/// Renders the scene; options.colour_by and options.contacts do not apply (the scene has its
/// colours and lines). \throws ParameterError as render_model.
Image render_scene(const TriangleScene& scene, const RenderOptions& options);

/// PNG bytes of the image (8-bit RGB, deflate-compressed with zlib).
std::vector<uint8_t> encode_png(const Image& image);

/// Writes the image as a PNG file. \throws OutputError
void write_png(const Image& image, const std::string& path);

}  // namespace voroseal
