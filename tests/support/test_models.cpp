#include "tests/support/test_models.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <random>

namespace voroseal::test {

namespace {

// Groups and quads of a soup being built.
struct SoupWriter {
  SurfaceSoup& soup;
  int group(const std::string& name, SurfaceKind kind) {
    soup.groups.push_back({name, name, kind, ""});
    return static_cast<int>(soup.groups.size()) - 1;
  }
  // Quad (a, b, c, d) as two triangles, split along a–c or (`other`) b–d; a quad with two
  // corners on one point (a layer closing at a pinch-out) is one triangle.
  void quad(int g, int a, int b, int c, int d, bool other = false) {
    std::vector<Triangle> halves;
    if (a == d)
      halves = {Triangle{a, b, c}};
    else if (b == c)
      halves = {Triangle{a, b, d}};
    else
      halves = other ? std::vector<Triangle>{{a, b, d}, {b, c, d}} : std::vector<Triangle>{{a, b, c}, {a, c, d}};
    for (const Triangle& t : halves) {
      soup.triangles.push_back(t);
      soup.triangle_group.push_back(g);
    }
  }
};

// The groups of a box cut by two horizons.
struct LayerBoxGroups {
  int zmin, zmax, ymin, ymax, xmin, xmax, lower, upper;
};

LayerBoxGroups layer_box_groups(SoupWriter& w) {
  LayerBoxGroups g{};
  g.zmin = w.group("zmin", SurfaceKind::Boundary);
  g.zmax = w.group("zmax", SurfaceKind::Boundary);
  g.ymin = w.group("ymin", SurfaceKind::Boundary);
  g.ymax = w.group("ymax", SurfaceKind::Boundary);
  g.xmin = w.group("xmin", SurfaceKind::Boundary);
  g.xmax = w.group("xmax", SurfaceKind::Boundary);
  g.lower = w.group("lower", SurfaceKind::Horizon);
  g.upper = w.group("upper", SurfaceKind::Horizon);
  return g;
}

}  // namespace

SurfaceSoup lattice_box(int n, bool horizon, const Vec3& lo, const Vec3& hi, unsigned shuffle_seed) {
  SurfaceSoup soup;
  soup.source = "lattice_box";
  auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        soup.points.push_back(lo + (hi - lo).cwiseProduct(Vec3(i, j, k) / n));
  std::mt19937 rng(shuffle_seed);
  auto add_group = [&](const std::string& name, SurfaceKind kind) {
    soup.groups.push_back({name, name, kind, ""});
    return static_cast<int>(soup.groups.size()) - 1;
  };
  // Quad (a, b, c, d) counter-clockwise seen from where its normal points.
  auto quad = [&](int g, int a, int b, int c, int d) {
    for (Triangle t : {Triangle{a, b, c}, Triangle{a, c, d}}) {
      if (shuffle_seed != 0 && (rng() & 1)) std::swap(t[1], t[2]);
      soup.triangles.push_back(t);
      soup.triangle_group.push_back(g);
    }
  };
  const int zmin = add_group("zmin", SurfaceKind::Boundary), zmax = add_group("zmax", SurfaceKind::Boundary);
  const int ymin = add_group("ymin", SurfaceKind::Boundary), ymax = add_group("ymax", SurfaceKind::Boundary);
  const int xmin = add_group("xmin", SurfaceKind::Boundary), xmax = add_group("xmax", SurfaceKind::Boundary);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      quad(zmin, id(a, b, 0), id(a, b + 1, 0), id(a + 1, b + 1, 0), id(a + 1, b, 0));
      quad(zmax, id(a, b, n), id(a + 1, b, n), id(a + 1, b + 1, n), id(a, b + 1, n));
      quad(ymin, id(a, 0, b), id(a + 1, 0, b), id(a + 1, 0, b + 1), id(a, 0, b + 1));
      quad(ymax, id(a, n, b), id(a, n, b + 1), id(a + 1, n, b + 1), id(a + 1, n, b));
      quad(xmin, id(0, a, b), id(0, a, b + 1), id(0, a + 1, b + 1), id(0, a + 1, b));
      quad(xmax, id(n, a, b), id(n, a + 1, b), id(n, a + 1, b + 1), id(n, a, b + 1));
    }
  if (horizon) {
    const int h = add_group("horizon", SurfaceKind::Horizon);
    const int k = n / 2;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) quad(h, id(a, b, k), id(a + 1, b, k), id(a + 1, b + 1, k), id(a, b + 1, k));
  }
  return soup;
}

SurfaceSoup floating_fault(int n, double x0, double lo, double hi) {
  SurfaceSoup soup;
  soup.source = "floating_fault";
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j) soup.points.emplace_back(x0, lo + (hi - lo) * j / n, lo + (hi - lo) * k / n);
  soup.groups.push_back({"fault", "fault", SurfaceKind::Fault, ""});
  auto id = [n](int j, int k) { return k * (n + 1) + j; };
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) {
      soup.triangles.push_back({id(j, k), id(j + 1, k), id(j + 1, k + 1)});
      soup.triangles.push_back({id(j, k), id(j + 1, k + 1), id(j, k + 1)});
      soup.triangle_group.insert(soup.triangle_group.end(), 2, 0);
    }
  return soup;
}

SurfaceSoup fault_leaving_horizon_box(double angle_deg) {
  SurfaceSoup soup = lattice_box(8, true);
  SurfaceSoup fault;
  fault.groups.push_back({"fault", "fault", SurfaceKind::Fault, ""});
  const double rise = std::tan(angle_deg * M_PI / 180.0);
  for (int j = 0; j <= 4; ++j) {
    const double x = 0.25 + 0.125 * j;
    fault.points.emplace_back(x, 0.5, 0.5 + std::max(0.0, x - 0.5) * rise);
    fault.points.emplace_back(x, 0.5, 0.75);
  }
  for (int j = 0; j < 4; ++j) {
    const int a = 2 * j, b = 2 * j + 2;  // lower points; the upper ones follow them
    fault.triangles.push_back({a, b, b + 1});
    fault.triangles.push_back({a, b + 1, a + 1});
    fault.triangle_group.insert(fault.triangle_group.end(), 2, 0);
  }
  append(soup, fault);
  return soup;
}

SurfaceSoup pinch_out_prism(double angle_deg) {
  SurfaceSoup soup;
  soup.source = "pinch_out_prism";
  const double t = std::tan(angle_deg * M_PI / 180.0);
  // 0, 1: the pinch-out line; 2, 3: bottom at x = 1; 4, 5: top at x = 1 (y = 0, then y = 1).
  soup.points = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {1, 0, t}, {1, 1, t}};
  soup.groups = {{"bottom", "bottom", SurfaceKind::Horizon, ""},
                 {"top", "top", SurfaceKind::Horizon, ""},
                 {"end", "end", SurfaceKind::Boundary, ""},
                 {"south", "south", SurfaceKind::Boundary, ""},
                 {"north", "north", SurfaceKind::Boundary, ""}};
  soup.triangles = {{0, 3, 1}, {0, 2, 3}, {0, 1, 5}, {0, 5, 4}, {2, 5, 3}, {2, 4, 5}, {0, 4, 2}, {1, 3, 5}};
  soup.triangle_group = {0, 0, 1, 1, 2, 2, 3, 4};
  return soup;
}

/// Unit box cut by two horizons `thickness` apart around z = 0.5 (a layer thinner than the
/// horizon triangles, 1/n): horizon "lower" on the regular n × n lattice, horizon "upper" with
/// its interior vertices moved by up to ±0.3 cell and its quads split along the other diagonal,
/// so that the two triangulations do not line up. Box sides are lattices over the z levels
/// 0, 0.25, lower, upper, 0.75, 1. Three regions.
SurfaceSoup thin_layer_box(int n, double thickness) {
  SurfaceSoup soup;
  soup.source = "thin_layer_box";
  const double lower = 0.5 - thickness / 2, upper = 0.5 + thickness / 2;
  const std::vector<double> levels = {0.0, 0.25, lower, upper, 0.75, 1.0};
  const int top = static_cast<int>(levels.size()) - 1, upper_level = 3;
  auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int k = 0; k <= top; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        Vec3 p(static_cast<double>(i) / n, static_cast<double>(j) / n, levels[k]);
        if (k == upper_level && i > 0 && i < n && j > 0 && j < n) {
          p.x() += jitter(rng) / n;
          p.y() += jitter(rng) / n;
        }
        soup.points.push_back(p);
      }
  SoupWriter w{soup};
  const LayerBoxGroups g = layer_box_groups(w);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      w.quad(g.zmin, id(a, b, 0), id(a, b + 1, 0), id(a + 1, b + 1, 0), id(a + 1, b, 0));
      w.quad(g.zmax, id(a, b, top), id(a + 1, b, top), id(a + 1, b + 1, top), id(a, b + 1, top));
      w.quad(g.lower, id(a, b, 2), id(a + 1, b, 2), id(a + 1, b + 1, 2), id(a, b + 1, 2));
      w.quad(g.upper, id(a, b, upper_level), id(a + 1, b, upper_level), id(a + 1, b + 1, upper_level),
             id(a, b + 1, upper_level), true);
    }
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < top; ++k) {
      w.quad(g.ymin, id(a, 0, k), id(a + 1, 0, k), id(a + 1, 0, k + 1), id(a, 0, k + 1));
      w.quad(g.ymax, id(a, n, k), id(a, n, k + 1), id(a + 1, n, k + 1), id(a + 1, n, k));
      w.quad(g.xmin, id(0, a, k), id(0, a, k + 1), id(0, a + 1, k + 1), id(0, a + 1, k));
      w.quad(g.xmax, id(n, a, k), id(n, a + 1, k), id(n, a + 1, k + 1), id(n, a, k + 1));
    }
  return soup;
}

SurfaceSoup pinch_out_tongue_box(int n, double thickness, double tip, double opens) {
  SurfaceSoup soup;
  soup.source = "pinch_out_tongue_box";
  const int i_tip = static_cast<int>(std::lround(tip * n));
  auto height = [&](double x) {  // of the upper horizon above the lower one
    if (x <= tip) return 0.0;
    if (x <= opens) return thickness;
    return thickness + (0.25 - thickness) * (x - opens) / (1.0 - opens);
  };
  // Levels: 0 bottom, 1 lower, 2 upper (the lower's vertex where they meet), 3 top.
  std::vector<int> index(4 * (n + 1) * (n + 1), -1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  auto id = [&](int i, int j, int k) -> int {
    if (k == 2 && i <= i_tip) k = 1;
    int& slot = index[(k * (n + 1) + j) * (n + 1) + i];
    if (slot >= 0) return slot;
    const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
    Vec3 p(x, y, k == 0 ? 0.0 : k == 3 ? 1.0 : 0.5 + (k == 2 ? height(x) : 0.0));
    if (k == 2 && i < n && j > 0 && j < n) {
      p.x() += jitter(rng) / n;
      p.y() += jitter(rng) / n;
      p.z() = 0.5 + height(p.x());
    }
    slot = static_cast<int>(soup.points.size());
    soup.points.push_back(p);
    return slot;
  };
  SoupWriter w{soup};
  const LayerBoxGroups g = layer_box_groups(w);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      w.quad(g.zmin, id(a, b, 0), id(a, b + 1, 0), id(a + 1, b + 1, 0), id(a + 1, b, 0));
      w.quad(g.zmax, id(a, b, 3), id(a + 1, b, 3), id(a + 1, b + 1, 3), id(a, b + 1, 3));
      w.quad(g.lower, id(a, b, 1), id(a + 1, b, 1), id(a + 1, b + 1, 1), id(a, b + 1, 1));
      if (a >= i_tip) w.quad(g.upper, id(a, b, 2), id(a + 1, b, 2), id(a + 1, b + 1, 2), id(a, b + 1, 2), true);
    }
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < 3; ++k) {
      // The sides y = 0 and y = 1 over the levels of the lattice columns a and a + 1; the layer
      // band (levels 1 to 2) closes at the pinch-out.
      if (k == 1 && a + 1 <= i_tip) continue;
      w.quad(g.ymin, id(a, 0, k), id(a + 1, 0, k), id(a + 1, 0, k + 1), id(a, 0, k + 1));
      w.quad(g.ymax, id(a + 1, n, k), id(a, n, k), id(a, n, k + 1), id(a + 1, n, k + 1));
    }
  for (int a = 0; a < n; ++a) {
    // x = 0 lies before the pinch-out: bottom to lower, lower to top.
    w.quad(g.xmin, id(0, a, 0), id(0, a, 1), id(0, a + 1, 1), id(0, a + 1, 0));
    w.quad(g.xmin, id(0, a, 1), id(0, a, 3), id(0, a + 1, 3), id(0, a + 1, 1));
  }
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < 3; ++k) w.quad(g.xmax, id(n, a, k), id(n, a + 1, k), id(n, a + 1, k + 1), id(n, a, k + 1));
  return soup;
}

void append(SurfaceSoup& a, const SurfaceSoup& b) {
  const int offset = static_cast<int>(a.points.size());
  const int goffset = static_cast<int>(a.groups.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (Triangle t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  for (int g : b.triangle_group) a.triangle_group.push_back(g + goffset);
  for (SurfaceGroup g : b.groups) {
    // Keep group names unique.
    for (const SurfaceGroup& existing : a.groups)
      if (existing.name == g.name) g.name += "_" + std::to_string(goffset);
    a.groups.push_back(g);
  }
}

std::string source_dir() {
  if (const char* s = std::getenv("VOROSEAL_SOURCE_DIR")) return s;
  return std::filesystem::current_path().string();
}

std::string shared_model(const std::string& relative) {
  std::vector<std::string> roots;
  if (const char* s = std::getenv("VOROSEAL_SHARED_MODELS")) roots.emplace_back(s);
  roots.push_back(source_dir() + "/../shared/models");
  for (const std::string& r : roots) {
    const std::filesystem::path p = std::filesystem::path(r) / relative;
    if (std::filesystem::exists(p)) return p.string();
  }
  return "";
}

std::string bundled_model(const std::string& name) { return source_dir() + "/models/" + name; }

}  // namespace voroseal::test
