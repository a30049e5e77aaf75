#include "io/vtk_format.h"

#include "framework/geometry/triangle_quality.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "framework/core/error.h"
#include "io/format_common.h"

namespace voroseal {

namespace {

constexpr int kTriangle = 5, kPolygon = 7, kQuad = 9, kTetra = 10;
constexpr long long kMaxId = 1000000;  // surface / region ids beyond this are refused

// Just enough XML for VTK files: tags with attributes, comments, declarations, text.
class XmlScanner {
 public:
  struct Tag {
    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;
    bool closing = false;
    bool self_closing = false;
    size_t begin = 0, end = 0;  // [begin, end) in the text
    const std::string* attribute(const std::string& key) const {
      for (const auto& [k, v] : attributes)
        if (k == key) return &v;
      return nullptr;
    }
  };

  explicit XmlScanner(const TextSource& source) : source_(source), text_(source.text()) {}

  /// 1-based line of a text position; the end of the text belongs to the last line.
  long line_of(size_t pos) const {
    if (text_.empty()) return 0;
    pos = std::min(pos, text_.size() - 1);
    // Lines are counted from the last position asked (positions mostly grow), so that a file
    // is not scanned for its newlines before its first tag is read.
    if (pos < counted_pos_) {
      counted_pos_ = 0;
      counted_line_ = 1;
    }
    counted_line_ += std::count(text_.begin() + counted_pos_, text_.begin() + pos, '\n');
    counted_pos_ = pos;
    return counted_line_;
  }
  [[noreturn]] void fail(size_t pos, const std::string& message) const {
    throw InputError(source_.name(), line_of(pos), message);
  }

  /// Next element tag; false at the end of the text (only blank text may remain).
  bool next(Tag& tag) {
    for (;;) {
      const size_t lt = text_.find('<', pos_);
      if (lt == std::string::npos) {
        pos_ = text_.size();
        return false;
      }
      if (text_.compare(lt, 4, "<!--") == 0) {
        pos_ = skip_past(lt, "-->");
        continue;
      }
      if (text_.compare(lt, 2, "<?") == 0) {
        pos_ = skip_past(lt, "?>");
        continue;
      }
      if (text_.compare(lt, 2, "<!") == 0) {
        pos_ = skip_past(lt, ">");
        continue;
      }
      parse_tag(lt, tag);
      return true;
    }
  }

  /// The text from the current position to the next '<'.
  std::pair<size_t, size_t> content() {
    const size_t lt = text_.find('<', pos_);
    const size_t end = lt == std::string::npos ? text_.size() : lt;
    const std::pair<size_t, size_t> range{pos_, end};
    pos_ = end;
    return range;
  }

  std::string_view text() const { return text_; }

 private:
  size_t skip_past(size_t from, const char* terminator) {
    const size_t e = text_.find(terminator, from);
    if (e == std::string::npos) fail(from, "unterminated XML markup");
    return e + std::strlen(terminator);
  }

  static bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '.' || c == '-';
  }

  void parse_tag(size_t lt, Tag& tag) {
    tag = Tag{};
    tag.begin = lt;
    size_t i = lt + 1;
    if (i < text_.size() && text_[i] == '/') {
      tag.closing = true;
      ++i;
    }
    const size_t name_start = i;
    while (i < text_.size() && name_char(text_[i])) ++i;
    if (i == name_start) fail(lt, "malformed XML tag");
    tag.name = text_.substr(name_start, i - name_start);
    for (;;) {
      while (i < text_.size() && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
      if (i >= text_.size()) fail(lt, "unterminated XML tag <" + tag.name + ">");
      if (text_[i] == '>') {
        ++i;
        break;
      }
      if (text_[i] == '/' && i + 1 < text_.size() && text_[i + 1] == '>' && !tag.closing) {
        tag.self_closing = true;
        i += 2;
        break;
      }
      if (tag.closing) fail(i, "malformed closing tag </" + tag.name + ">");
      const size_t key_start = i;
      while (i < text_.size() && name_char(text_[i])) ++i;
      if (i == key_start) fail(i, "malformed attribute in <" + tag.name + ">");
      std::string key(text_.substr(key_start, i - key_start));
      while (i < text_.size() && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
      if (i >= text_.size() || text_[i] != '=') fail(i, "attribute " + key + " of <" + tag.name + "> has no value");
      ++i;
      while (i < text_.size() && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
      if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\''))
        fail(i, "attribute " + key + " of <" + tag.name + "> needs a quoted value");
      const char quote = text_[i++];
      const size_t value_end = text_.find(quote, i);
      if (value_end == std::string::npos) fail(i, "unterminated value of attribute " + key);
      tag.attributes.emplace_back(std::move(key), text_.substr(i, value_end - i));
      i = value_end + 1;
    }
    tag.end = i;
    pos_ = i;
  }

  const TextSource& source_;
  std::string_view text_;
  mutable size_t counted_pos_ = 0;  // line_of(): the newlines before here are counted
  mutable long counted_line_ = 1;
  size_t pos_ = 0;
};

struct VtuData {
  long long points_declared = -1, cells_declared = -1;
  std::vector<Vec3> points;
  std::vector<long long> connectivity, offsets, types, surface, region;
  long piece_line = 0;  // line of <Piece>
  long connectivity_line = 0, offsets_line = 0, types_line = 0, surface_line = 0, region_line = 0;  // DataArray tags
};

// True when `text` ends, but for white space, with "</VTKFile>" (spaces allowed before '>').
bool ends_with_closing_tag(std::string_view text) {
  size_t end = text.size();
  auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (end > 0 && space(text[end - 1])) --end;
  if (end == 0 || text[end - 1] != '>') return false;
  --end;
  while (end > 0 && space(text[end - 1])) --end;
  const std::string_view tail = "</VTKFile";
  return end >= tail.size() && text.substr(end - tail.size(), tail.size()) == tail;
}

class VtuParser {
 public:
  explicit VtuParser(const TextSource& source) : xml_(source), name_(source.name()) {}

  VtuData parse() {
    XmlScanner::Tag tag;
    if (!xml_.next(tag)) xml_.fail(xml_.text().size(), "not a VTK XML file: no <VTKFile>");
    if (tag.name != "VTKFile" || tag.closing) xml_.fail(tag.begin, "not a VTK XML file: no <VTKFile>");
    const std::string* type = tag.attribute("type");
    if (!type || *type != "UnstructuredGrid") xml_.fail(tag.begin, "only VTK UnstructuredGrid files are supported");
    if (tag.attribute("compressor")) xml_.fail(tag.begin, "compressed VTK files are not supported");
    // Checked on the file's last bytes first: a truncated or padded file is refused before its
    // data is read.
    if (!ends_with_closing_tag(xml_.text()))
      xml_.fail(tag.begin,
                "the <VTKFile> opened here is not closed by </VTKFile> at the end of "
                "the file (truncated?)");
    std::string section;
    bool piece = false;
    while (xml_.next(tag)) {
      if (tag.name == "VTKFile" && tag.closing) {
        finish();
        return std::move(d_);
      }
      if (tag.name == "AppendedData") xml_.fail(tag.begin, "appended (binary) VTK data is not supported");
      if (tag.name == "Piece" && !tag.closing) {
        if (piece) xml_.fail(tag.begin, "several Pieces are not supported");
        piece = true;
        d_.piece_line = xml_.line_of(tag.begin);
        d_.points_declared = count_attribute(tag, "NumberOfPoints");
        d_.cells_declared = count_attribute(tag, "NumberOfCells");
      } else if (tag.name == "Points" || tag.name == "Cells" || tag.name == "CellData" || tag.name == "PointData" ||
                 tag.name == "FieldData") {
        section = tag.closing || tag.self_closing ? "" : tag.name;
      } else if (tag.name == "DataArray" && !tag.closing) {
        data_array(tag, section);
      }
    }
    xml_.fail(xml_.text().size(), "the file is truncated: no </VTKFile>");
  }

 private:
  long long count_attribute(const XmlScanner::Tag& tag, const char* key) {
    const std::string* v = tag.attribute(key);
    long long n = 0;
    if (!v || !parse_integer(*v, n) || n < 0)
      xml_.fail(tag.begin, std::string("<Piece> needs a non-negative integer ") + key);
    if (static_cast<unsigned long long>(n) > xml_.text().size())
      xml_.fail(tag.begin, std::string(key) + " = " + *v + " is more than the file can hold");
    return n;
  }

  // Values of a DataArray as reals or integers, with the line of each bad token.
  template <class T>
  std::vector<T> values(const XmlScanner::Tag& tag, bool integers) {
    std::vector<T> out;
    if (tag.self_closing) return out;
    const auto [begin, end] = xml_.content();
    const std::string_view s = xml_.text();
    size_t i = begin;
    while (i < end) {
      while (i < end && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i >= end) break;
      const size_t start = i;
      while (i < end && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      const std::string_view token(s.data() + start, i - start);
      if (integers) {
        long long v = 0;
        if (!parse_integer(token, v))
          xml_.fail(start, "expected an integer in DataArray, found '" + std::string(token.substr(0, 40)) + "'");
        out.push_back(static_cast<T>(v));
      } else {
        double v = 0;
        if (!parse_finite_real(token, v))
          xml_.fail(start, "expected a finite number in DataArray, found '" + std::string(token.substr(0, 40)) + "'");
        out.push_back(static_cast<T>(v));
      }
    }
    close_data_array(tag);
    return out;
  }

  void close_data_array(const XmlScanner::Tag& open) {
    XmlScanner::Tag tag;
    if (!xml_.next(tag) || tag.name != "DataArray" || !tag.closing)
      xml_.fail(open.begin, "DataArray is not closed by </DataArray>");
  }

  void data_array(const XmlScanner::Tag& tag, const std::string& section) {
    const std::string* format = tag.attribute("format");
    const std::string* name = tag.attribute("Name");
    const std::string key = name ? *name : "";
    const bool used = section == "Points" || (section == "Cells" && (key == "connectivity" || key == "offsets" ||
                                                                      key == "types")) ||
                      (section == "CellData" && (key == "surface" || key == "region"));
    if (!used) {
      if (!tag.self_closing) {
        xml_.content();
        close_data_array(tag);
      }
      return;
    }
    if (!format || *format != "ascii")
      xml_.fail(tag.begin, "only format=\"ascii\" DataArrays are supported (" + section + " " + key + ")");
    if (section == "Points") {
      const std::string* nc = tag.attribute("NumberOfComponents");
      if (nc && *nc != "3") xml_.fail(tag.begin, "Points need NumberOfComponents=\"3\"");
      const std::vector<double> v = values<double>(tag, false);
      if (v.size() % 3 != 0) xml_.fail(tag.begin, "the number of point coordinates is not a multiple of 3");
      for (size_t i = 0; i < v.size(); i += 3) d_.points.emplace_back(v[i], v[i + 1], v[i + 2]);
      return;
    }
    std::vector<long long> v = values<long long>(tag, true);
    if (key == "connectivity") d_.connectivity_line = xml_.line_of(tag.begin);
    if (key == "offsets") d_.offsets_line = xml_.line_of(tag.begin);
    if (key == "types") d_.types_line = xml_.line_of(tag.begin);
    if (key == "surface") d_.surface_line = xml_.line_of(tag.begin);
    if (key == "region") d_.region_line = xml_.line_of(tag.begin);
    if (key == "connectivity") d_.connectivity = std::move(v);
    if (key == "offsets") d_.offsets = std::move(v);
    if (key == "types") d_.types = std::move(v);
    if (key == "surface") d_.surface = std::move(v);
    if (key == "region") d_.region = std::move(v);
  }

  void finish() {
    auto fail = [&](long line, const std::string& m) { throw InputError(source_name(), line, m); };
    if (d_.points_declared < 0) fail(0, "no <Piece>");
    if (static_cast<long long>(d_.points.size()) != d_.points_declared)
      fail(d_.piece_line, "NumberOfPoints is " + std::to_string(d_.points_declared) + " but the file gives " +
                              std::to_string(d_.points.size()) + " points");
    const size_t nc = static_cast<size_t>(d_.cells_declared);
    if (d_.offsets.size() != nc || d_.types.size() != nc)
      fail(d_.piece_line, "NumberOfCells is " + std::to_string(nc) + " but offsets/types give " +
                              std::to_string(d_.offsets.size()) + "/" + std::to_string(d_.types.size()));
    if (!d_.surface.empty() && d_.surface.size() != nc)
      fail(d_.surface_line, "cell data \"surface\" must have one value per cell");
    if (!d_.region.empty() && d_.region.size() != nc)
      fail(d_.region_line, "cell data \"region\" must have one value per cell");
    long long previous = 0;
    for (long long o : d_.offsets) {
      if (o < previous || o > static_cast<long long>(d_.connectivity.size()))
        fail(d_.offsets_line, "cell offsets are not increasing within the connectivity");
      previous = o;
    }
    if (previous != static_cast<long long>(d_.connectivity.size()))
      fail(d_.offsets_line, "the last cell offset does not end the connectivity");
    const long long np = static_cast<long long>(d_.points.size());
    for (long long v : d_.connectivity)
      if (v < 0 || v >= np)
        fail(d_.connectivity_line, "cell connectivity refers to point " + std::to_string(v) + " but there are " +
                                       std::to_string(np) + " points");
  }

  const std::string& source_name() const { return name_; }

  XmlScanner xml_;
  VtuData d_;
  std::string name_;
};

struct VtuCells {
  std::vector<Triangle> triangles;
  std::vector<long long> triangle_surface;
  std::vector<Tetrahedron> tets;
  std::vector<long long> tet_region;
};

VtuCells cells_of(const VtuData& d, const std::string& file, bool volume) {
  VtuCells c;
  for (size_t k = 0; k < d.types.size(); ++k) {
    const long long begin = k == 0 ? 0 : d.offsets[k - 1];
    const long long n = d.offsets[k] - begin;
    const long long* v = d.connectivity.data() + begin;
    const long long type = d.types[k];
    auto need = [&](long long expected) {
      if (n != expected)
        throw InputError(file, d.types_line, "cell " + std::to_string(k) + " of type " + std::to_string(type) +
                                                 " has " + std::to_string(n) + " points");
    };
    const long long surface = d.surface.empty() ? 0 : d.surface[k];
    if (type == kTriangle || type == kQuad || type == kPolygon) {
      if (type == kTriangle) need(3);
      if (type == kQuad) need(4);
      if (n < 3) need(3);
      for (long long i = 1; i + 1 < n; ++i) {
        c.triangles.push_back({static_cast<int>(v[0]), static_cast<int>(v[i]), static_cast<int>(v[i + 1])});
        c.triangle_surface.push_back(surface);
      }
    } else if (type == kTetra) {
      need(4);
      if (volume) {
        c.tets.push_back({static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]), static_cast<int>(v[3])});
        c.tet_region.push_back(d.region.empty() ? 0 : d.region[k]);
      }
    } else if (type != 1 && type != 2 && type != 3 && type != 4) {
      throw InputError(file, d.types_line, "unsupported VTK cell type " + std::to_string(type));
    }
  }
  return c;
}

std::vector<int> checked_ids(const std::vector<long long>& ids, const std::string& file, long line, const char* what,
                             std::vector<std::string>* names) {
  std::vector<int> out;
  long long hi = -1;
  for (long long id : ids) {
    if (id < 0 || id > kMaxId) throw InputError(file, line, std::string(what) + " id " + std::to_string(id) + " out of range");
    hi = std::max(hi, id);
    out.push_back(static_cast<int>(id));
  }
  if (names)
    for (long long i = 0; i <= hi; ++i) names->push_back(std::string(what) + "_" + std::to_string(i));
  return out;
}

void write_header(std::ostream& out, size_t points, size_t cells) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << points << "\" NumberOfCells=\"" << cells << "\">\n";
}

void write_points(std::ostream& out, const std::vector<Vec3>& local, const Vec3& origin, int precision) {
  out << "      <Points>\n        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (const Vec3& v : local) {
    const Vec3 x = v + origin;
    out << "          " << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' ' << Real{x.z(), precision}
        << '\n';
  }
  out << "        </DataArray>\n      </Points>\n";
}

template <class Cells>
void write_cells(std::ostream& out, const std::vector<Triangle>& triangles, const Cells& tets) {
  out << "      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const Triangle& t : triangles) out << "          " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  for (const Tetrahedron& t : tets) out << "          " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  long long offset = 0;
  for (size_t i = 0; i < triangles.size(); ++i) out << "          " << (offset += 3) << '\n';
  for (size_t i = 0; i < tets.size(); ++i) out << "          " << (offset += 4) << '\n';
  out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (size_t i = 0; i < triangles.size(); ++i) out << "          " << kTriangle << '\n';
  for (size_t i = 0; i < tets.size(); ++i) out << "          " << kTetra << '\n';
  out << "        </DataArray>\n      </Cells>\n";
}

void write_ints(std::ostream& out, const char* name, const std::vector<int>& values) {
  out << "        <DataArray type=\"Int32\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (int v : values) out << "          " << v << '\n';
  out << "        </DataArray>\n";
}

void write_reals(std::ostream& out, const char* name, const std::vector<double>& values) {
  out << "        <DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (double v : values) out << "          " << Real{v, 9} << '\n';
  out << "        </DataArray>\n";
}

void write_footer(std::ostream& out) { out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n"; }

}  // namespace

SurfaceSoup read_vtu(const TextSource& source) {
  const VtuData d = VtuParser(source).parse();
  VtuCells c = cells_of(d, source.name(), false);
  SurfaceSoup soup;
  soup.source = source.name();
  soup.points = d.points;
  soup.triangles = std::move(c.triangles);
  const std::vector<int> ids =
      checked_ids(c.triangle_surface, source.name(), d.surface_line, "surface", nullptr);
  group_triangles_by_id(soup, ids, {}, "surface_");
  require_triangles(soup);
  return soup;
}

VolumeMesh read_vtu_volume(const TextSource& source) {
  const VtuData d = VtuParser(source).parse();
  VtuCells c = cells_of(d, source.name(), true);
  VolumeMesh mesh;
  set_volume_vertices(mesh, d.points);
  mesh.triangles = std::move(c.triangles);
  mesh.triangle_surface = checked_ids(c.triangle_surface, source.name(), d.surface_line, "surface",
                                      &mesh.surface_names);
  mesh.tets = std::move(c.tets);
  mesh.tet_region =
      checked_ids(c.tet_region, source.name(), d.region_line, "region", &mesh.region_names);
  validate_volume_mesh(mesh, source.name());
  return mesh;
}

void write_vtu(const StructuralModel& model, std::ostream& out, int precision) {
  const ModelTriangles t = flatten(model);
  write_header(out, model.vertices.size(), t.triangles.size());
  write_points(out, model.vertices, model.frame.origin, precision);
  write_cells(out, t.triangles, std::vector<Tetrahedron>{});
  out << "      <CellData Scalars=\"surface\">\n";
  write_ints(out, "surface", t.part);
  std::vector<double> quality;
  quality.reserve(t.triangles.size());
  for (const Triangle& f : t.triangles)
    quality.push_back(measure_triangle(model.vertices[f[0]], model.vertices[f[1]], model.vertices[f[2]]).q);
  write_reals(out, "quality", quality);
  out << "      </CellData>\n";
  write_footer(out);
}

void write_vtu_volume(const VolumeMesh& mesh, std::ostream& out, int precision) {
  const std::vector<Vec3>& v = mesh.vertices;
  write_header(out, v.size(), mesh.triangles.size() + mesh.tets.size());
  write_points(out, v, mesh.frame.origin, precision);
  write_cells(out, mesh.triangles, mesh.tets);
  std::vector<int> surface, region;
  std::vector<double> quality;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    surface.push_back(f < mesh.triangle_surface.size() ? mesh.triangle_surface[f] : 0);
    region.push_back(-1);
    const Triangle& t = mesh.triangles[f];
    quality.push_back(measure_triangle(v[t[0]], v[t[1]], v[t[2]]).q);
  }
  for (size_t k = 0; k < mesh.tets.size(); ++k) {
    surface.push_back(-1);
    region.push_back(k < mesh.tet_region.size() ? mesh.tet_region[k] : 0);
    const Tetrahedron& t = mesh.tets[k];
    quality.push_back(tet_quality(v[t[0]], v[t[1]], v[t[2]], v[t[3]]));
  }
  out << "      <CellData Scalars=\"region\">\n";
  write_ints(out, "surface", surface);
  write_ints(out, "region", region);
  write_reals(out, "quality", quality);
  out << "      </CellData>\n";
  write_footer(out);
}

}  // namespace voroseal
