#include "io/vtk_format.h"

#include "framework/geometry/triangle_quality.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <list>

#include "framework/core/error.h"
#include "framework/core/markup_text.h"
#include "io/format_common.h"
#include "io/tag_names.h"
#include "io/vtk_binary.h"

namespace voroseal {

namespace {

constexpr int kVertex = 1, kLine = 3, kTriangle = 5, kPolygon = 7, kQuad = 9, kTetra = 10;

// Categories of the FieldData names voroseal writes: "<category>:<name>" with [id, dim].
const char* const kNameCategories[] = {"horizon", "fault",  "boundary", "unconformity", "unknown",
                                       "part",    "region", "contact",  "corner"};
bool is_name_array(const std::string& key) {
  const std::string category = key.substr(0, key.find(':'));
  if (category.size() == key.size()) return false;
  for (const char* c : kNameCategories)
    if (category == c) return true;
  return false;
}

// The character entities escape_markup() writes (the XML ones), back to characters.
std::string xml_unescaped(const std::string& text) {
  static const std::pair<const char*, char> entities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (size_t i = 0; i < text.size();) {
    bool replaced = false;
    for (const auto& [entity, ch] : entities)
      if (text.compare(i, std::strlen(entity), entity) == 0) {
        out += ch;
        i += std::strlen(entity);
        replaced = true;
        break;
      }
    if (!replaced) out += text[i++];
  }
  return out;
}
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

  /// Continues scanning at `pos` (past binary data that must not be read as XML).
  void skip_to(size_t pos) { pos_ = pos; }

  std::string_view text() const { return text_; }

 private:
  size_t skip_past(size_t from, const char* terminator) {
    const size_t e = text_.find(terminator, from);
    if (e == std::string::npos) fail(from, "unterminated XML markup");
    return e + std::strlen(terminator);
  }

  static bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '.' ||
           c == '-';
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
      if (i >= text_.size() || text_[i] != '=')
        fail(i, "attribute " + key + " of <" + tag.name + "> has no value");
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
  std::vector<long long> connectivity, offsets, types, surface, region, part, contact, corner;
  long piece_line = 0;  // line of <Piece>
  long connectivity_line = 0, offsets_line = 0, types_line = 0, surface_line = 0;  // DataArray tags
  long region_line = 0, part_line = 0, contact_line = 0, corner_line = 0;
  /// FieldData names (tag_names.h: "<category>:<name>") with their [id, dim] values.
  struct Name {
    std::string category, name;
    long long id = -1;
    long line = 0;
  };
  std::vector<Name> names;
  /// Scalar PointData arrays (one component), by name, with the line of their DataArray tag.
  struct PointArray {
    std::string name;
    std::vector<double> values;
    long line = 0;
  };
  std::vector<PointArray> point_data;
  std::vector<std::string> other_point_data;  // PointData arrays of several components
};

// A DataArray the reader uses: its tag and, when inline, the text up to </DataArray>. Arrays
// are decoded once the whole file is scanned: appended data comes last, and the offsets give
// the size of the connectivity.
struct ArrayRef {
  XmlScanner::Tag tag;
  long line = 0;
  size_t begin = 0, end = 0;
  bool found = false;
};

// How binary arrays are stored: attributes of <VTKFile>, and the <AppendedData> section.
struct BinaryLayout {
  int header_size = 4;  // header_type UInt32 (VTK's default) or UInt64
  bool zlib = false;
  bool appended = false, appended_base64 = false;
  std::string_view appended_data;  // the bytes after '_'
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
    if (tag.name != "VTKFile" || tag.closing)
      xml_.fail(tag.begin, "not a VTK XML file: no <VTKFile>");
    const std::string* type = tag.attribute("type");
    if (!type || *type != "UnstructuredGrid")
      xml_.fail(tag.begin, "only VTK UnstructuredGrid files are supported");
    read_layout(tag);
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
        decode();
        finish();
        return std::move(d_);
      }
      if (tag.name == "AppendedData" && !tag.closing) {
        appended_data(tag);
      } else if (tag.name == "Piece" && !tag.closing) {
        if (piece) xml_.fail(tag.begin, "several Pieces are not supported");
        piece = true;
        d_.piece_line = xml_.line_of(tag.begin);
        d_.points_declared = count_attribute(tag, "NumberOfPoints");
        d_.cells_declared = count_attribute(tag, "NumberOfCells");
      } else if (tag.name == "Points" || tag.name == "Cells" || tag.name == "CellData" ||
                 tag.name == "PointData" || tag.name == "FieldData") {
        section = tag.closing || tag.self_closing ? "" : tag.name;
      } else if (tag.name == "DataArray" && !tag.closing) {
        data_array(tag, section);
      }
    }
    xml_.fail(xml_.text().size(), "the file is truncated: no </VTKFile>");
  }

 private:
  // The <VTKFile> attributes that say how binary data is stored.
  void read_layout(const XmlScanner::Tag& tag) {
    const std::string* order = tag.attribute("byte_order");
    if (order && *order == "BigEndian")
      xml_.fail(tag.begin, "big-endian VTK files are not supported (write them LittleEndian)");
    if (order && *order != "LittleEndian")
      xml_.fail(tag.begin, "unknown byte_order \"" + *order + "\"");
    const std::string* header = tag.attribute("header_type");
    if (header && *header != "UInt32" && *header != "UInt64")
      xml_.fail(tag.begin, "header_type must be UInt32 or UInt64, not \"" + *header + "\"");
    layout_.header_size = header && *header == "UInt64" ? 8 : 4;
    const std::string* compressor = tag.attribute("compressor");
    if (compressor && !compressor->empty() && *compressor != "vtkZLibDataCompressor")
      xml_.fail(tag.begin,
                "compressor " + *compressor + " is not supported (only vtkZLibDataCompressor)");
    layout_.zlib = compressor && !compressor->empty();
  }

  // <AppendedData encoding="raw|base64">_DATA</AppendedData>: the data is binary, so it is not
  // scanned as XML; it ends at the file's last </AppendedData>.
  void appended_data(const XmlScanner::Tag& tag) {
    if (layout_.appended) xml_.fail(tag.begin, "several <AppendedData> sections");
    const std::string* encoding = tag.attribute("encoding");
    if (!encoding || (*encoding != "raw" && *encoding != "base64"))
      xml_.fail(tag.begin, "<AppendedData> needs encoding=\"raw\" or \"base64\"");
    layout_.appended = true;
    layout_.appended_base64 = *encoding == "base64";
    if (tag.self_closing) return;
    const std::string_view text = xml_.text();
    size_t i = tag.end;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i == text.size() || text[i] != '_')
      xml_.fail(tag.begin, "<AppendedData> needs '_' before its data");
    const size_t close = text.rfind("</AppendedData");
    if (close == std::string_view::npos || close < i)
      xml_.fail(tag.begin, "<AppendedData> is not closed by </AppendedData>");
    layout_.appended_data = text.substr(i + 1, close - i - 1);
    xml_.skip_to(close);
  }

  long long count_attribute(const XmlScanner::Tag& tag, const char* key) {
    const std::string* v = tag.attribute(key);
    long long n = 0;
    if (!v || !parse_integer(*v, n) || n < 0)
      xml_.fail(tag.begin, std::string("<Piece> needs a non-negative integer ") + key);
    if (static_cast<unsigned long long>(n) > xml_.text().size())
      xml_.fail(tag.begin, std::string(key) + " = " + *v + " is more than the file can hold");
    return n;
  }

  void close_data_array(const XmlScanner::Tag& open) {
    XmlScanner::Tag tag;
    if (!xml_.next(tag) || tag.name != "DataArray" || !tag.closing)
      xml_.fail(open.begin, "DataArray is not closed by </DataArray>");
  }

  ArrayRef* slot(const std::string& section, const std::string& key) {
    if (section == "Points") return &points_;
    if (section == "Cells" && key == "connectivity") return &connectivity_;
    if (section == "Cells" && key == "offsets") return &offsets_;
    if (section == "Cells" && key == "types") return &types_;
    if (section == "CellData" && key == "surface") return &surface_;
    if (section == "CellData" && key == "region") return &region_;
    if (section == "CellData" && key == "part") return &part_;
    if (section == "CellData" && key == "contact") return &contact_;
    if (section == "CellData" && key == "corner") return &corner_;
    if (section == "FieldData" && is_name_array(key)) {
      names_.emplace_back();
      return &names_.back();
    }
    if (section == "PointData") {
      point_data_.emplace_back();
      return &point_data_.back();
    }
    return nullptr;
  }

  void data_array(const XmlScanner::Tag& tag, const std::string& section) {
    const std::string* name = tag.attribute("Name");
    ArrayRef* ref = slot(section, name ? *name : "");
    std::pair<size_t, size_t> content{0, 0};
    if (!tag.self_closing) {
      content = xml_.content();
      close_data_array(tag);
    }
    if (!ref) return;
    const std::string* format = tag.attribute("format");
    if (!format || (*format != "ascii" && *format != "binary" && *format != "appended"))
      xml_.fail(tag.begin, "DataArray needs format=\"ascii\", \"binary\" or \"appended\" (" +
                               section + " " + (name ? *name : "") + ")");
    if (section == "Points") {
      const std::string* nc = tag.attribute("NumberOfComponents");
      if (nc && *nc != "3") xml_.fail(tag.begin, "Points need NumberOfComponents=\"3\"");
    }
    *ref = ArrayRef{tag, xml_.line_of(tag.begin), content.first, content.second, true};
  }

  // Values of an ASCII DataArray as reals or integers, with the line of each bad token.
  template <class T>
  std::vector<T> ascii_values(const ArrayRef& ref, bool integers) {
    std::vector<T> out;
    const std::string_view s = xml_.text();
    size_t i = ref.begin;
    while (i < ref.end) {
      while (i < ref.end && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i >= ref.end) break;
      const size_t start = i;
      while (i < ref.end && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      const std::string_view token(s.data() + start, i - start);
      if (integers) {
        long long v = 0;
        if (!parse_integer(token, v))
          xml_.fail(start, "expected an integer in DataArray, found '" +
                               std::string(token.substr(0, 40)) + "'");
        out.push_back(static_cast<T>(v));
      } else {
        double v = 0;
        if (!parse_finite_real(token, v))
          xml_.fail(start, "expected a finite number in DataArray, found '" +
                               std::string(token.substr(0, 40)) + "'");
        out.push_back(static_cast<T>(v));
      }
    }
    return out;
  }

  // The bytes where a binary array starts: its inline text, or its offset in <AppendedData>.
  std::string_view binary_start(const ArrayRef& ref, const DataPlace& place) const {
    if (*ref.tag.attribute("format") == "binary")
      return xml_.text().substr(ref.begin, ref.end - ref.begin);
    if (!layout_.appended) place.fail("format=\"appended\" but the file has no <AppendedData>");
    const std::string* offset = ref.tag.attribute("offset");
    long long at = 0;
    if (!offset || !parse_integer(*offset, at) || at < 0)
      place.fail("an appended DataArray needs a non-negative integer offset");
    if (static_cast<unsigned long long>(at) > layout_.appended_data.size())
      place.fail("offset " + *offset + " is past the end of the appended data (" +
                 std::to_string(layout_.appended_data.size()) + " bytes)");
    return layout_.appended_data.substr(static_cast<size_t>(at));
  }

  // The bytes of a binary array holding `expected` values (checked before they are read).
  std::vector<unsigned char> binary_bytes(const ArrayRef& ref, const VtkType& type,
                                          long long expected, const char* what,
                                          const DataPlace& place) const {
    const bool base64 = *ref.tag.attribute("format") == "binary" || layout_.appended_base64;
    VtkBytes bytes(binary_start(ref, place), base64, place);
    VtkArrayReader reader(bytes, layout_.header_size, layout_.zlib, place);
    const uint64_t size = reader.read_header();
    if (size % static_cast<uint64_t>(type.size) != 0)
      place.fail(std::string(what) + ": " + std::to_string(size) +
                 " bytes are not a whole number of " + type.name + " values");
    const uint64_t count = size / static_cast<uint64_t>(type.size);
    if (expected < 0 || count != static_cast<uint64_t>(expected))
      place.fail(std::string(what) + " has " + std::to_string(count) + " values where " +
                 std::to_string(expected) + " are expected");
    return reader.read_data();
  }

  const VtkType& binary_type(const ArrayRef& ref, bool integers, const char* what,
                             const DataPlace& place) const {
    const std::string* name = ref.tag.attribute("type");
    const VtkType* type = name ? vtk_type(*name) : nullptr;
    if (!type)
      place.fail(std::string(what) + " has an unknown DataArray type \"" + (name ? *name : "") +
                 "\"");
    if (integers && type->real)
      place.fail(std::string(what) + " needs an integer type, not " + type->name);
    return *type;
  }

  std::vector<long long> integers(const ArrayRef& ref, long long expected, const char* what) {
    if (!ref.found) return {};
    if (*ref.tag.attribute("format") == "ascii") return ascii_values<long long>(ref, true);
    const DataPlace place{name_, ref.line};
    const VtkType& type = binary_type(ref, true, what, place);
    const std::vector<unsigned char> bytes = binary_bytes(ref, type, expected, what, place);
    std::vector<long long> out(bytes.size() / static_cast<size_t>(type.size));
    for (size_t i = 0; i < out.size(); ++i)
      if (!vtk_integer(bytes.data() + i * type.size, type, out[i]))
        place.fail(std::string(what) + " value " + std::to_string(i) + " is too large");
    return out;
  }

  std::vector<double> reals(const ArrayRef& ref, long long expected, const char* what) {
    if (!ref.found) return {};
    if (*ref.tag.attribute("format") == "ascii") return ascii_values<double>(ref, false);
    const DataPlace place{name_, ref.line};
    const VtkType& type = binary_type(ref, false, what, place);
    const std::vector<unsigned char> bytes = binary_bytes(ref, type, expected, what, place);
    std::vector<double> out(bytes.size() / static_cast<size_t>(type.size));
    for (size_t i = 0; i < out.size(); ++i) {
      out[i] = vtk_real(bytes.data() + i * type.size, type);
      if (!std::isfinite(out[i]))
        place.fail("expected a finite number in DataArray, found " + std::to_string(out[i]));
    }
    return out;
  }

  // Decodes the arrays in an order that gives each binary one its expected size: the cell
  // arrays from NumberOfCells, then the connectivity from the last offset.
  void decode() {
    if (d_.points_declared < 0) throw InputError(name_, 0, "no <Piece>");
    const std::vector<double> xyz = reals(points_, 3 * d_.points_declared, "Points");
    if (xyz.size() % 3 != 0)
      xml_.fail(points_.tag.begin, "the number of point coordinates is not a multiple of 3");
    for (size_t i = 0; i < xyz.size(); i += 3)
      d_.points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
    d_.offsets = integers(offsets_, d_.cells_declared, "offsets");
    d_.types = integers(types_, d_.cells_declared, "types");
    d_.surface = integers(surface_, d_.cells_declared, "surface");
    d_.region = integers(region_, d_.cells_declared, "region");
    d_.part = integers(part_, d_.cells_declared, "part");
    d_.contact = integers(contact_, d_.cells_declared, "contact");
    d_.corner = integers(corner_, d_.cells_declared, "corner");
    d_.part_line = part_.line;
    d_.contact_line = contact_.line;
    d_.corner_line = corner_.line;
    for (const ArrayRef& ref : names_) {
      const std::vector<long long> v = integers(ref, 2, "a field data name's [id, dim]");
      if (v.size() != 2)
        throw InputError(name_, ref.line, "a field data name needs two integers, id and dim");
      const std::string text = xml_unescaped(*ref.tag.attribute("Name"));
      const size_t colon = text.find(':');
      d_.names.push_back({text.substr(0, colon), text.substr(colon + 1), v[0], ref.line});
    }
    for (const ArrayRef& ref : point_data_) {
      const std::string* name = ref.tag.attribute("Name");
      const std::string text = name ? xml_unescaped(*name) : "";
      const std::string* components = ref.tag.attribute("NumberOfComponents");
      if (components && *components != "1") {
        d_.other_point_data.push_back(text);
        continue;
      }
      d_.point_data.push_back({text, reals(ref, d_.points_declared, "point data"), ref.line});
      if (static_cast<long long>(d_.point_data.back().values.size()) != d_.points_declared)
        throw InputError(name_, ref.line,
                         "point data \"" + text + "\" must have one value per point");
    }
    d_.connectivity =
        integers(connectivity_, d_.offsets.empty() ? 0 : d_.offsets.back(), "connectivity");
    d_.connectivity_line = connectivity_.line;
    d_.offsets_line = offsets_.line;
    d_.types_line = types_.line;
    d_.surface_line = surface_.line;
    d_.region_line = region_.line;
  }

  void finish() {
    auto fail = [&](long line, const std::string& m) { throw InputError(name_, line, m); };
    if (static_cast<long long>(d_.points.size()) != d_.points_declared)
      fail(d_.piece_line, "NumberOfPoints is " + std::to_string(d_.points_declared) +
                              " but the file gives " + std::to_string(d_.points.size()) +
                              " points");
    const size_t nc = static_cast<size_t>(d_.cells_declared);
    if (d_.offsets.size() != nc || d_.types.size() != nc)
      fail(d_.piece_line, "NumberOfCells is " + std::to_string(nc) + " but offsets/types give " +
                              std::to_string(d_.offsets.size()) + "/" +
                              std::to_string(d_.types.size()));
    if (!d_.surface.empty() && d_.surface.size() != nc)
      fail(d_.surface_line, "cell data \"surface\" must have one value per cell");
    if (!d_.region.empty() && d_.region.size() != nc)
      fail(d_.region_line, "cell data \"region\" must have one value per cell");
    if (!d_.part.empty() && d_.part.size() != nc)
      fail(d_.part_line, "cell data \"part\" must have one value per cell");
    if (!d_.contact.empty() && d_.contact.size() != nc)
      fail(d_.contact_line, "cell data \"contact\" must have one value per cell");
    if (!d_.corner.empty() && d_.corner.size() != nc)
      fail(d_.corner_line, "cell data \"corner\" must have one value per cell");
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
        fail(d_.connectivity_line, "cell connectivity refers to point " + std::to_string(v) +
                                       " but there are " + std::to_string(np) + " points");
  }

  XmlScanner xml_;
  std::string name_;
  BinaryLayout layout_;
  ArrayRef points_, connectivity_, offsets_, types_, surface_, region_, part_, contact_, corner_;
  std::list<ArrayRef> names_;  // FieldData names (stable addresses while they are filled)
  std::list<ArrayRef> point_data_;  // PointData arrays, the same way
  VtuData d_;
};

struct VtuCells {
  std::vector<Triangle> triangles;
  std::vector<long long> triangle_surface, triangle_part;
  std::vector<Tetrahedron> tets;
  std::vector<long long> tet_region;
  std::vector<Edge> edges;  // line cells
  std::vector<long long> edge_contact;
  std::vector<int> corners;  // vertex cells
  std::vector<long long> corner_id;
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
        throw InputError(file, d.types_line,
                         "cell " + std::to_string(k) + " of type " + std::to_string(type) +
                             " has " + std::to_string(n) + " points");
    };
    const long long surface = d.surface.empty() ? 0 : d.surface[k];
    if (type == kTriangle || type == kQuad || type == kPolygon) {
      if (type == kTriangle) need(3);
      if (type == kQuad) need(4);
      if (n < 3) need(3);
      for (long long i = 1; i + 1 < n; ++i) {
        c.triangles.push_back(
            {static_cast<int>(v[0]), static_cast<int>(v[i]), static_cast<int>(v[i + 1])});
        c.triangle_surface.push_back(surface);
        if (!d.part.empty()) c.triangle_part.push_back(d.part[k]);
      }
    } else if (type == kTetra) {
      need(4);
      if (volume) {
        c.tets.push_back({static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]),
                          static_cast<int>(v[3])});
        c.tet_region.push_back(d.region.empty() ? 0 : d.region[k]);
      }
    } else if (type == kLine) {
      need(2);
      if (volume) {
        c.edges.push_back({static_cast<int>(v[0]), static_cast<int>(v[1])});
        c.edge_contact.push_back(d.contact.empty() ? 0 : d.contact[k]);
      }
    } else if (type == kVertex) {
      need(1);
      if (volume) {
        c.corners.push_back(static_cast<int>(v[0]));
        c.corner_id.push_back(d.corner.empty() ? 0 : d.corner[k]);
      }
    } else if (type != 2 && type != 4) {
      throw InputError(file, d.types_line, "unsupported VTK cell type " + std::to_string(type));
    }
  }
  return c;
}

std::vector<int> checked_ids(const std::vector<long long>& ids, const std::string& file, long line,
                             const char* what, std::vector<std::string>* names) {
  std::vector<int> out;
  long long hi = -1;
  for (long long id : ids) {
    if (id < 0 || id > kMaxId)
      throw InputError(file, line,
                       std::string(what) + " id " + std::to_string(id) + " out of range");
    hi = std::max(hi, id);
    out.push_back(static_cast<int>(id));
  }
  if (names)
    for (long long i = 0; i <= hi; ++i)
      names->push_back(std::string(what) + "_" + std::to_string(i));
  return out;
}

// One inline DataArray of `values`, zlib-compressed and base64-encoded as VTK writes it.
template <class T>
void write_binary(std::ostream& out, const std::string& attributes, const std::vector<T>& values) {
  const std::vector<unsigned char> bytes = little_endian_bytes(values);
  out << "        <DataArray " << attributes << " format=\"binary\">\n          "
      << vtk_zlib_base64(bytes.data(), bytes.size()) << "\n        </DataArray>\n";
}

// A name of the FieldData: "<category>:<name>" with the values id and dim.
struct FieldName {
  std::string text;
  int id = 0, dim = 0;
};

void write_header(std::ostream& out, size_t points, size_t cells, bool ascii,
                  const std::vector<FieldName>& names = {}) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\""
      << (ascii ? "" : " compressor=\"vtkZLibDataCompressor\"") << ">\n"
      << "  <UnstructuredGrid>\n";
  if (!names.empty()) {
    out << "    <FieldData>\n";
    for (const FieldName& n : names) {
      const std::string attributes = "type=\"Int32\" Name=\"" + escape_markup(n.text, "&apos;") +
                                     "\" NumberOfTuples=\"1\" NumberOfComponents=\"2\"";
      if (!ascii) {
        write_binary(out, attributes, std::vector<int32_t>{n.id, n.dim});
        continue;
      }
      out << "        <DataArray " << attributes << " format=\"ascii\">" << n.id << ' ' << n.dim
          << "</DataArray>\n";
    }
    out << "    </FieldData>\n";
  }
  out << "    <Piece NumberOfPoints=\"" << points << "\" NumberOfCells=\"" << cells << "\">\n";
}

void write_points(std::ostream& out, const std::vector<Vec3>& local, const Vec3& origin,
                  int precision, bool ascii) {
  out << "      <Points>\n";
  const char* attributes = "type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"";
  if (ascii) {
    out << "        <DataArray " << attributes << " format=\"ascii\">\n";
    for (const Vec3& v : local) {
      const Vec3 x = v + origin;
      out << "          " << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' '
          << Real{x.z(), precision} << '\n';
    }
    out << "        </DataArray>\n";
  } else {
    std::vector<double> xyz;
    xyz.reserve(3 * local.size());
    for (const Vec3& v : local) {
      const Vec3 x = v + origin;
      xyz.insert(xyz.end(), {x.x(), x.y(), x.z()});
    }
    write_binary(out, attributes, xyz);
  }
  out << "      </Points>\n";
}

// The cells of a file: VTK's three Cells arrays.
struct VtuCellArrays {
  std::vector<int64_t> connectivity, offsets;
  std::vector<uint8_t> types;
  template <class Cell>
  void add(const std::vector<Cell>& cells, uint8_t type) {
    for (const Cell& cell : cells) {
      connectivity.insert(connectivity.end(), cell.begin(), cell.end());
      offsets.push_back(static_cast<int64_t>(connectivity.size()));
      types.push_back(type);
    }
  }
};

void write_cells(std::ostream& out, const VtuCellArrays& c, bool ascii) {
  out << "      <Cells>\n";
  if (!ascii) {
    write_binary(out, "type=\"Int64\" Name=\"connectivity\"", c.connectivity);
    write_binary(out, "type=\"Int64\" Name=\"offsets\"", c.offsets);
    write_binary(out, "type=\"UInt8\" Name=\"types\"", c.types);
  } else {
    // One cell a line.
    out << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    int64_t begin = 0;
    for (int64_t end : c.offsets) {
      out << "         ";
      for (int64_t i = begin; i < end; ++i) out << ' ' << c.connectivity[i];
      out << '\n';
      begin = end;
    }
    out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (int64_t o : c.offsets) out << "          " << o << '\n';
    out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
    for (uint8_t t : c.types) out << "          " << int(t) << '\n';
    out << "        </DataArray>\n";
  }
  out << "      </Cells>\n";
}

void write_ints(std::ostream& out, const char* name, const std::vector<int>& values, bool ascii) {
  const std::string attributes = std::string("type=\"Int32\" Name=\"") + name + "\"";
  if (!ascii) return write_binary(out, attributes, values);
  out << "        <DataArray " << attributes << " format=\"ascii\">\n";
  for (int v : values) out << "          " << v << '\n';
  out << "        </DataArray>\n";
}

// Qualities are a diagnostic: 9 digits in ASCII, Float32 in binary.
void write_reals(std::ostream& out, const char* name, const std::vector<double>& values,
                 bool ascii) {
  if (!ascii) {
    const std::vector<float> single(values.begin(), values.end());
    return write_binary(out, std::string("type=\"Float32\" Name=\"") + name + "\"", single);
  }
  out << "        <DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (double v : values) out << "          " << Real{v, 9} << '\n';
  out << "        </DataArray>\n";
}

void write_footer(std::ostream& out) {
  out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

void write_model_vtu(const StructuralModel& model, std::ostream& out, int precision, bool ascii) {
  const ModelTriangles t = flatten(model);
  write_header(out, model.vertices.size(), t.triangles.size(), ascii);
  write_points(out, model.vertices, model.frame.origin, precision, ascii);
  VtuCellArrays cells;
  cells.add(t.triangles, kTriangle);
  write_cells(out, cells, ascii);
  out << "      <CellData Scalars=\"surface\">\n";
  write_ints(out, "surface", t.part, ascii);
  std::vector<double> quality;
  quality.reserve(t.triangles.size());
  for (const Triangle& f : t.triangles)
    quality.push_back(
        measure_triangle(model.vertices[f[0]], model.vertices[f[1]], model.vertices[f[2]]).q);
  write_reals(out, "quality", quality, ascii);
  out << "      </CellData>\n";
  write_footer(out);
}

// The names of a volume mesh as FieldData (see vtk_format.h).
std::vector<FieldName> field_names(const VolumeMesh& mesh) {
  std::vector<FieldName> names;
  auto add = [&](const std::vector<std::string>& list, const char* category, int dim) {
    for (size_t i = 0; i < list.size(); ++i)
      names.push_back({std::string(category) + ":" + list[i], static_cast<int>(i), dim});
  };
  for (size_t i = 0; i < mesh.surface_names.size(); ++i)
    names.push_back(
        {kind_prefixed_name(mesh.surface_kind(static_cast<int>(i)), mesh.surface_names[i]),
         static_cast<int>(i), 2});
  add(mesh.part_names, "part", 2);
  add(mesh.region_names, "region", 3);
  add(mesh.contact_names, "contact", 1);
  add(mesh.corner_names, "corner", 0);
  return names;
}

// Value `k` of a per-element id list, `fallback` past its end.
int id_at(const std::vector<int>& ids, size_t k, int fallback) {
  return k < ids.size() ? ids[k] : fallback;
}

void write_volume_vtu(const VolumeMesh& mesh, std::ostream& out, int precision, bool ascii) {
  const std::vector<Vec3>& v = mesh.vertices;
  VtuCellArrays cells;
  cells.add(mesh.triangles, kTriangle);
  cells.add(mesh.tets, kTetra);
  cells.add(mesh.edges, kLine);
  std::vector<std::array<int, 1>> corners;
  for (int c : mesh.corners) corners.push_back({c});
  cells.add(corners, kVertex);
  write_header(out, v.size(), cells.types.size(), ascii, field_names(mesh));
  write_points(out, v, mesh.frame.origin, precision, ascii);
  write_cells(out, cells, ascii);
  // Per cell, in the order triangles, tets, edges, corners; -1 where an id does not apply.
  const size_t nf = mesh.triangles.size(), nt = mesh.tets.size(), ne = mesh.edges.size();
  const size_t nc = corners.size(), n = nf + nt + ne + nc;
  std::vector<int> surface(n, -1), region(n, -1), part, contact, corner;
  std::vector<double> quality(n, 0.0);  // 0 on edges and corners
  for (size_t f = 0; f < nf; ++f) {
    surface[f] = id_at(mesh.triangle_surface, f, 0);
    const Triangle& t = mesh.triangles[f];
    quality[f] = measure_triangle(v[t[0]], v[t[1]], v[t[2]]).q;
  }
  for (size_t k = 0; k < nt; ++k) {
    region[nf + k] = id_at(mesh.tet_region, k, 0);
    const Tetrahedron& t = mesh.tets[k];
    quality[nf + k] = tet_quality(v[t[0]], v[t[1]], v[t[2]], v[t[3]]);
  }
  if (!mesh.triangle_part.empty()) {
    part.assign(n, -1);
    for (size_t f = 0; f < nf; ++f) part[f] = id_at(mesh.triangle_part, f, 0);
  }
  if (ne > 0) {
    contact.assign(n, -1);
    for (size_t e = 0; e < ne; ++e) contact[nf + nt + e] = id_at(mesh.edge_contact, e, 0);
  }
  if (nc > 0) {
    corner.assign(n, -1);
    for (size_t c = 0; c < nc; ++c) corner[nf + nt + ne + c] = id_at(mesh.corner_id, c, 0);
  }
  out << "      <CellData Scalars=\"region\">\n";
  write_ints(out, "surface", surface, ascii);
  write_ints(out, "region", region, ascii);
  if (!part.empty()) write_ints(out, "part", part, ascii);
  if (!contact.empty()) write_ints(out, "contact", contact, ascii);
  if (!corner.empty()) write_ints(out, "corner", corner, ascii);
  write_reals(out, "quality", quality, ascii);
  out << "      </CellData>\n";
  write_footer(out);
}

// Names and kinds from the FieldData names (they win over the "<what>_<id>" defaults).
void apply_field_names(const VtuData& d, const std::string& file, VolumeMesh& mesh) {
  auto set = [&](std::vector<std::string>& names, const VtuData::Name& n, const char* prefix) {
    if (n.id < 0 || n.id > kMaxId)
      throw InputError(file, n.line,
                       "field data name id " + std::to_string(n.id) + " out of range");
    while (static_cast<long long>(names.size()) <= n.id)
      names.push_back(prefix + std::to_string(names.size()));
    names[n.id] = n.name;
  };
  for (const VtuData::Name& n : d.names) {
    if (n.category == "part") {
      set(mesh.part_names, n, "part_");
    } else if (n.category == "region") {
      set(mesh.region_names, n, "region_");
    } else if (n.category == "contact") {
      set(mesh.contact_names, n, "contact_");
    } else if (n.category == "corner") {
      set(mesh.corner_names, n, "corner_");
    } else {
      SurfaceKind kind;
      std::string name;
      split_kind_prefixed_name(n.category + ":" + n.name, kind, name);
      set(mesh.surface_names, n, "surface_");
      mesh.surface_kinds.resize(mesh.surface_names.size(), SurfaceKind::Unknown);
      mesh.surface_kinds[n.id] = kind;
    }
  }
}

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
  if (!c.triangle_part.empty())
    mesh.triangle_part =
        checked_ids(c.triangle_part, source.name(), d.part_line, "part", &mesh.part_names);
  mesh.tets = std::move(c.tets);
  mesh.tet_region =
      checked_ids(c.tet_region, source.name(), d.region_line, "region", &mesh.region_names);
  mesh.edges = std::move(c.edges);
  mesh.edge_contact =
      checked_ids(c.edge_contact, source.name(), d.contact_line, "contact", &mesh.contact_names);
  mesh.corners.assign(c.corners.begin(), c.corners.end());
  mesh.corner_id =
      checked_ids(c.corner_id, source.name(), d.corner_line, "corner", &mesh.corner_names);
  apply_field_names(d, source.name(), mesh);
  validate_volume_mesh(mesh, source.name());
  return mesh;
}

VtuPointField read_vtu_point_field(const TextSource& source, const std::string& wanted) {
  const VtuData d = VtuParser(source).parse();
  const VtuData::PointArray* field = nullptr;
  for (const VtuData::PointArray& a : d.point_data)
    if (a.name == wanted || (wanted.empty() && d.point_data.size() == 1)) field = &a;
  for (const char* name : {"size", "h"})
    for (const VtuData::PointArray& a : d.point_data)
      if (!field && wanted.empty() && a.name == name) field = &a;
  if (!field) {
    std::string names;
    for (const VtuData::PointArray& a : d.point_data) names += (names.empty() ? "" : ", ") + a.name;
    for (const std::string& n : d.other_point_data)
      names += (names.empty() ? "" : ", ") + n + " (not scalar)";
    throw InputError(source.name(), d.piece_line,
                     (wanted.empty() ? std::string("no scalar point data array to read (the only "
                                                   "one, or one named size or h)")
                                     : "no scalar point data array named \"" + wanted + "\"") +
                         "; the file has " + (names.empty() ? "none" : names));
  }
  return {d.points, field->values, field->name, field->line};
}

void write_vtu(const StructuralModel& model, std::ostream& out, int precision) {
  write_model_vtu(model, out, precision, false);
}

void write_vtu_volume(const VolumeMesh& mesh, std::ostream& out, int precision) {
  write_volume_vtu(mesh, out, precision, false);
}

void write_vtu_ascii(const StructuralModel& model, std::ostream& out, int precision) {
  write_model_vtu(model, out, precision, true);
}

void write_vtu_volume_ascii(const VolumeMesh& mesh, std::ostream& out, int precision) {
  write_volume_vtu(mesh, out, precision, true);
}

}  // namespace voroseal
