#include "framework/host/render.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <unordered_set>

#include "framework/core/edge_key.h"
#include "framework/core/error.h"
#include "framework/host/render_annotations.h"

namespace voroseal {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::array<uint8_t, 3> hsv_to_rgb(double h, double s, double v) {
  const double i = std::floor(h * 6.0);
  const double f = h * 6.0 - i;
  const double p = v * (1 - s), q = v * (1 - f * s), t = v * (1 - (1 - f) * s);
  double r = v, g = t, b = p;
  switch (static_cast<int>(i) % 6) {
    case 0:
      r = v, g = t, b = p;
      break;
    case 1:
      r = q, g = v, b = p;
      break;
    case 2:
      r = p, g = v, b = t;
      break;
    case 3:
      r = p, g = q, b = v;
      break;
    case 4:
      r = t, g = p, b = v;
      break;
    case 5:
      r = v, g = p, b = q;
      break;
  }
  auto byte = [](double c) {
    return static_cast<uint8_t>(std::clamp(std::lround(255.0 * c), 0L, 255L));
  };
  return {byte(r), byte(g), byte(b)};
}

// One triangle ready for rasterisation, in supersampled pixel coordinates. `depth` is affine in
// screen space and larger nearer the viewer (-z for orthographic views, 1/z for perspective).
struct ScreenTriangle {
  float x[3], y[3], depth[3];
  float inv_length[3];  // 1 / pixel length of the edge opposite vertex i
  std::array<uint8_t, 3> colour;
  uint8_t contact_edges = 0;  // bit i: the edge opposite vertex i is on a contact
  int ymin = 0, ymax = -1;
};

float edge_function(float ax, float ay, float bx, float by, float px, float py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// The camera: an orthonormal frame (right, up, towards the viewer) centred on the bbox centre.
struct Camera {
  Vec3 centre, right, up, eye_direction;
  double exaggeration = 1.0;
  bool perspective = false;
  double distance = 0.0;  // eye to centre (perspective)

  Vec3 world(const Vec3& p) const {  // vertical exaggeration about the centre
    Vec3 q = p - centre;
    q.z() *= exaggeration;
    return q;
  }
  // (x, y) on the image plane through the centre, and the affine depth.
  Vec3 project(const Vec3& p) const {
    const Vec3 q = world(p);
    const double x = q.dot(right), y = q.dot(up), z = q.dot(eye_direction);
    if (!perspective) return {x, y, z};
    const double along = std::max(distance - z, 1e-9 * distance);  // distance from the eye
    return {x * distance / along, y * distance / along, 1.0 / along};
  }
};

}  // namespace

std::array<uint8_t, 3> surface_colour(int index) {
  const double golden = 0.6180339887498949;
  const double hue = std::fmod(0.08 + golden * std::max(index, 0), 1.0);
  const double saturation = (index / 2) % 2 == 0 ? 0.36 : 0.52;
  const double value = index % 2 == 0 ? 0.97 : 0.87;
  return hsv_to_rgb(hue, saturation, value);
}

Image render_model(const StructuralModel& model, const RenderOptions& options) {
  TriangleScene scene;
  scene.vertices = model.vertices;
  scene.frame = model.bbox();
  ModelTriangles flat = flatten(model);
  scene.triangles = std::move(flat.triangles);
  scene.colours.resize(scene.triangles.size());
  for (size_t t = 0; t < scene.triangles.size(); ++t) {
    const int part = flat.part[t];
    const int id = options.colour_by == ColourBy::Part ? part : model.parts[part].interface;
    scene.colours[t] = surface_colour(id);
  }
  if (options.contacts && !model.contacts.empty()) {
    std::unordered_set<uint64_t> contact_edges;
    for (const Contact& contact : model.contacts)
      for (size_t i = 1; i < contact.vertices.size(); ++i)
        contact_edges.insert(edge_key(contact.vertices[i - 1], contact.vertices[i]));
    scene.lines.assign(scene.triangles.size(), 0);
    for (size_t t = 0; t < scene.triangles.size(); ++t) {
      const Triangle& tri = scene.triangles[t];
      for (int i = 0; i < 3; ++i)
        if (contact_edges.count(edge_key(tri[(i + 1) % 3], tri[(i + 2) % 3])))
          scene.lines[t] |= static_cast<uint8_t>(1u << i);
    }
  }
  return render_scene(scene, options);
}

Image render_scene(const TriangleScene& scene, const RenderOptions& options) {
  if (options.width < 16 || options.width > 8192 || options.height < 16 || options.height > 8192)
    throw ParameterError("picture size must be between 16 and 8192 pixels");
  if (options.supersample < 1 || options.supersample > 4)
    throw ParameterError("picture supersampling must be 1 to 4");
  const int ss = options.supersample;
  const int W = options.width * ss, H = options.height * ss;

  Image image;
  image.width = options.width;
  image.height = options.height;
  std::vector<std::array<uint8_t, 3>> colour(static_cast<size_t>(W) * H, options.background);
  std::vector<float> zbuffer(static_cast<size_t>(W) * H, -std::numeric_limits<float>::infinity());

  const BoundingBox& box = scene.frame;
  if (box.empty() || scene.triangles.empty()) {
    image.rgb.resize(3 * static_cast<size_t>(image.width) * image.height);
    for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = options.background[i % 3];
    return image;
  }

  Camera camera;
  const double az = options.azimuth_deg * kPi / 180.0, el = options.elevation_deg * kPi / 180.0;
  camera.centre = box.center();
  camera.exaggeration = options.vertical_exaggeration;
  camera.eye_direction =
      Vec3(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el));
  camera.right = Vec3(-std::cos(az), std::sin(az), 0.0);
  camera.up = Vec3(-std::sin(el) * std::sin(az), -std::sin(el) * std::cos(az), std::cos(el));
  camera.perspective = options.perspective;
  const Vec3 extent = box.max - box.min;
  const double diagonal =
      Vec3(extent.x(), extent.y(), extent.z() * options.vertical_exaggeration).norm();
  const double half_fov = std::clamp(options.field_of_view_deg, 5.0, 120.0) * kPi / 360.0;
  camera.distance = 0.5 * diagonal / std::tan(half_fov) + 0.5 * diagonal;

  // Framing: the projected corners of the bounding box fill 92% of the smaller dimension.
  double fx0 = std::numeric_limits<double>::infinity(), fx1 = -fx0, fy0 = fx0, fy1 = -fx0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner((i & 1) ? box.max.x() : box.min.x(), (i & 2) ? box.max.y() : box.min.y(),
                      (i & 4) ? box.max.z() : box.min.z());
    const Vec3 p = camera.project(corner);
    fx0 = std::min(fx0, p.x()), fx1 = std::max(fx1, p.x());
    fy0 = std::min(fy0, p.y()), fy1 = std::max(fy1, p.y());
  }
  const double scale =
      0.92 * std::min(W / std::max(fx1 - fx0, 1e-300), H / std::max(fy1 - fy0, 1e-300));
  const double ox = 0.5 * W - scale * 0.5 * (fx0 + fx1);
  const double oy = 0.5 * H + scale * 0.5 * (fy0 + fy1);

  Vec3 light = 0.35 * camera.right + 0.75 * camera.up + 0.55 * camera.eye_direction;
  light.normalize();

  // Cut-away: the bbox planes facing the viewer, on axes where the model has an extent.
  const double tolerance = 1e-6 * box.diagonal();
  std::array<int, 3> cut_side{{0, 0, 0}};  // -1: min plane, +1: max plane, 0: none
  if (options.cut_away)
    for (int k = 0; k < 3; ++k) {
      if (extent[k] <= 1e-3 * box.diagonal()) continue;
      if (camera.eye_direction[k] < -1e-6) cut_side[k] = -1;
      if (camera.eye_direction[k] > 1e-6) cut_side[k] = 1;
    }
  auto on_cut_side = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    for (int k = 0; k < 3; ++k) {
      if (cut_side[k] == 0) continue;
      const double plane = cut_side[k] < 0 ? box.min[k] : box.max[k];
      if (std::abs(a[k] - plane) <= tolerance && std::abs(b[k] - plane) <= tolerance &&
          std::abs(c[k] - plane) <= tolerance)
        return true;
    }
    return false;
  };

  const long n = static_cast<long>(scene.triangles.size());
  std::vector<ScreenTriangle> screen(n);
  std::vector<char> visible(n, 0);
  std::vector<double> edge_pixels(n, 0.0);
#pragma omp parallel for schedule(static)
  for (long t = 0; t < n; ++t) {
    const Triangle& tri = scene.triangles[t];
    const Vec3& a = scene.vertices[tri[0]];
    const Vec3& b = scene.vertices[tri[1]];
    const Vec3& c = scene.vertices[tri[2]];
    if (on_cut_side(a, b, c)) continue;
    ScreenTriangle& s = screen[t];
    const Vec3 corners[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
      const Vec3 p = camera.project(corners[i]);
      s.x[i] = static_cast<float>(ox + scale * p.x());
      s.y[i] = static_cast<float>(oy - scale * p.y());
      s.depth[i] = static_cast<float>(p.z());
    }
    // Bit i of `lines`: the edge opposite corner i; a swap of corners 1 and 2 swaps bits 1, 2.
    uint8_t lines = scene.lines.empty() ? 0 : scene.lines[t];
    float area = edge_function(s.x[0], s.y[0], s.x[1], s.y[1], s.x[2], s.y[2]);
    if (area < 0) {  // make the screen orientation consistent
      std::swap(s.x[1], s.x[2]), std::swap(s.y[1], s.y[2]), std::swap(s.depth[1], s.depth[2]);
      lines = static_cast<uint8_t>((lines & 1u) | ((lines & 2u) << 1) | ((lines & 4u) >> 1));
      area = -area;
    }
    s.contact_edges = lines;
    if (!(area > 1e-6f)) continue;  // seen edge-on
    double perimeter = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const float length = std::hypot(s.x[k] - s.x[j], s.y[k] - s.y[j]);
      perimeter += length;
      s.inv_length[i] = length > 0 ? 1.0f / length : 0.0f;
    }
    edge_pixels[t] = perimeter / 3.0 / ss;
    const Vec3 normal =
        (camera.world(b) - camera.world(a)).cross(camera.world(c) - camera.world(a));
    const double norm = normal.norm();
    const double lambert = norm > 0 ? std::abs(normal.dot(light)) / norm : 0.0;
    const double shade = 0.38 + 0.62 * lambert;
    const std::array<uint8_t, 3>& base = scene.colours[t];
    for (int i = 0; i < 3; ++i)
      s.colour[i] = static_cast<uint8_t>(std::min(255.0, base[i] * shade));
    s.ymin = std::max(0, static_cast<int>(std::floor(std::min({s.y[0], s.y[1], s.y[2]}))));
    s.ymax = std::min(H - 1, static_cast<int>(std::ceil(std::max({s.y[0], s.y[1], s.y[2]}))));
    const float xmin = std::min({s.x[0], s.x[1], s.x[2]}),
                xmax = std::max({s.x[0], s.x[1], s.x[2]});
    visible[t] = s.ymin <= s.ymax && xmax >= 0 && xmin <= W;
  }

  bool draw_edges = options.edges == EdgeDrawing::Always;
  if (options.edges == EdgeDrawing::Auto) {
    double sum = 0;
    long count = 0;
    for (long t = 0; t < n; ++t)
      if (visible[t]) sum += edge_pixels[t], ++count;
    draw_edges = count > 0 && sum / count >= options.min_edge_pixels;
  }
  const float edge_half_width = 0.45f * ss, contact_half_width = 0.95f * ss;

  // Rows are cut into bands; each band is rasterised by one thread, so no two threads write
  // the same pixel and the z-buffer needs no locks.
  const int band_height = std::max(8, H / 64);
  const int bands = (H + band_height - 1) / band_height;
#pragma omp parallel for schedule(dynamic, 1)
  for (int band = 0; band < bands; ++band) {
    const int y0 = band * band_height, y1 = std::min(H, y0 + band_height);
    for (long t = 0; t < n; ++t) {
      if (!visible[t]) continue;
      const ScreenTriangle& s = screen[t];
      if (s.ymax < y0 || s.ymin >= y1) continue;
      const float area = edge_function(s.x[0], s.y[0], s.x[1], s.y[1], s.x[2], s.y[2]);
      const float inv_area = 1.0f / area;
      const int xa = std::max(0, static_cast<int>(std::floor(std::min({s.x[0], s.x[1], s.x[2]}))));
      const int xb =
          std::min(W - 1, static_cast<int>(std::ceil(std::max({s.x[0], s.x[1], s.x[2]}))));
      const int ya = std::max(y0, s.ymin), yb = std::min(y1 - 1, s.ymax);
      for (int py = ya; py <= yb; ++py) {
        const float cy = py + 0.5f;
        for (int px = xa; px <= xb; ++px) {
          const float cx = px + 0.5f;
          const float w0 = edge_function(s.x[1], s.y[1], s.x[2], s.y[2], cx, cy);
          const float w1 = edge_function(s.x[2], s.y[2], s.x[0], s.y[0], cx, cy);
          const float w2 = edge_function(s.x[0], s.y[0], s.x[1], s.y[1], cx, cy);
          if (w0 < 0 || w1 < 0 || w2 < 0) continue;
          const float depth = (w0 * s.depth[0] + w1 * s.depth[1] + w2 * s.depth[2]) * inv_area;
          const size_t pixel = static_cast<size_t>(py) * W + px;
          if (depth <= zbuffer[pixel]) continue;
          zbuffer[pixel] = depth;
          std::array<uint8_t, 3> c = s.colour;
          const float w[3] = {w0, w1, w2};
          for (int i = 0; i < 3; ++i) {
            const float distance = w[i] * s.inv_length[i];  // pixels to the edge opposite i
            if ((s.contact_edges >> i) & 1u) {
              if (distance < contact_half_width) c = {30, 30, 34};
            } else if (draw_edges && distance < edge_half_width) {
              for (int k = 0; k < 3; ++k) c[k] = static_cast<uint8_t>(s.colour[k] * 0.55f);
            }
          }
          colour[pixel] = c;
        }
      }
    }
  }

  // Average the supersampled pixels.
  image.rgb.assign(3 * static_cast<size_t>(image.width) * image.height, 0);
  const int samples = ss * ss;
#pragma omp parallel for schedule(static)
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      int sum[3] = {0, 0, 0};
      for (int sy = 0; sy < ss; ++sy)
        for (int sx = 0; sx < ss; ++sx) {
          const auto& c = colour[static_cast<size_t>(y * ss + sy) * W + x * ss + sx];
          for (int k = 0; k < 3; ++k) sum[k] += c[k];
        }
      uint8_t* out = &image.rgb[3 * (static_cast<size_t>(y) * image.width + x)];
      for (int k = 0; k < 3; ++k) out[k] = static_cast<uint8_t>((sum[k] + samples / 2) / samples);
    }
  if (options.axes_and_scale) {
    // Pixels per unit at the centre; the axes as the camera sees them (z exaggerated).
    ViewScale view;
    view.pixels_per_unit = scale / ss;
    for (int k = 0; k < 3; ++k) {
      Vec3 unit = Vec3::Zero();
      unit[k] = k == 2 ? options.vertical_exaggeration : 1.0;
      view.axes[k] = {{unit.dot(camera.right) * view.pixels_per_unit,
                       -unit.dot(camera.up) * view.pixels_per_unit}};
    }
    draw_axes_and_scale(image, view);
  }
  return image;
}

std::vector<uint8_t> encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != 3 * static_cast<size_t>(image.width) * image.height)
    throw ParameterError("encode_png: the image size does not match its pixels");
  // Raw scanlines, each preceded by filter type 0 (none).
  const size_t stride = 3 * static_cast<size_t>(image.width);
  std::vector<uint8_t> raw((stride + 1) * image.height);
  for (int y = 0; y < image.height; ++y) {
    raw[y * (stride + 1)] = 0;
    std::copy_n(&image.rgb[y * stride], stride, &raw[y * (stride + 1) + 1]);
  }
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<uint8_t> packed(packed_size);
  if (compress2(packed.data(), &packed_size, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK)
    throw OutputError("PNG compression failed");
  packed.resize(packed_size);

  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  auto put32 = [&png](uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) png.push_back(static_cast<uint8_t>(v >> shift));
  };
  auto chunk = [&](const char* tag, const std::vector<uint8_t>& data) {
    put32(static_cast<uint32_t>(data.size()));
    const size_t start = png.size();
    png.insert(png.end(), tag, tag + 4);
    png.insert(png.end(), data.begin(), data.end());
    put32(static_cast<uint32_t>(crc32(0L, &png[start], static_cast<uInt>(png.size() - start))));
  };
  std::vector<uint8_t> header;
  for (uint32_t v : {static_cast<uint32_t>(image.width), static_cast<uint32_t>(image.height)})
    for (int shift = 24; shift >= 0; shift -= 8) header.push_back(static_cast<uint8_t>(v >> shift));
  header.insert(header.end(),
                {8, 2, 0, 0, 0});  // 8-bit, truecolour, deflate, no filter, no interlace
  chunk("IHDR", header);
  chunk("IDAT", packed);
  chunk("IEND", {});
  return png;
}

void write_png(const Image& image, const std::string& path) {
  const std::vector<uint8_t> png = encode_png(image);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw OutputError(path + ": cannot open for writing");
  out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  out.close();
  if (!out) throw OutputError(path + ": write failed");
}

}  // namespace voroseal
