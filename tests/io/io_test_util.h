// Helpers shared by the io tests: a scratch directory, small files, a hand-made tet mesh.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "framework/model/volume_mesh.h"

namespace voroseal::test {

/// A fresh directory under the system temp dir, removed with its content at destruction.
class ScratchDir {
 public:
  ScratchDir() {
    std::random_device rd;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = info ? std::string(info->test_suite_name()) + "_" + info->name() : "io";
    path_ = std::filesystem::temp_directory_path() / ("voroseal_" + name + "_" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }
  /// Names of the files in the directory (to find leftover temporaries).
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A cube [0, 2]^3 offset by `origin`, split into the 6 tetrahedra around its diagonal
/// (Freudenthal), positively oriented; 3 tets in region 0 and 3 in region 1; its 12 boundary
/// triangles carry the id of their cube face (0..5).
inline VolumeMesh cube_tet_mesh(const Vec3& origin = Vec3(500000.0, 4000000.0, -1200.0)) {
  VolumeMesh m;
  m.frame.origin = origin;
  for (int k = 0; k < 8; ++k) m.vertices.emplace_back(2.0 * (k & 1) - 1.0, 2.0 * ((k >> 1) & 1) - 1.0, 2.0 * (k >> 2) - 1.0);
  const int perms[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
  for (int p = 0; p < 6; ++p) {
    Tetrahedron t{0, perms[p][0], perms[p][0] + perms[p][1], 7};
    const Vec3& a = m.vertices[t[0]];
    if ((m.vertices[t[1]] - a).dot((m.vertices[t[2]] - a).cross(m.vertices[t[3]] - a)) < 0) std::swap(t[1], t[2]);
    m.tets.push_back(t);
    m.tet_region.push_back(p < 3 ? 0 : 1);
  }
  // Faces x=0, x=1, y=0, y=1, z=0, z=1 as quads of vertex ids (bit 0: x, bit 1: y, bit 2: z).
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (int f = 0; f < 6; ++f) {
    m.triangles.push_back({faces[f][0], faces[f][1], faces[f][2]});
    m.triangles.push_back({faces[f][0], faces[f][2], faces[f][3]});
    m.triangle_surface.insert(m.triangle_surface.end(), 2, f);
  }
  m.region_names = {"lower", "upper"};
  m.surface_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  return m;
}

}  // namespace voroseal::test
