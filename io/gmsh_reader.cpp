#include "io/gmsh_reader.h"

#include <algorithm>
#include <climits>
#include <unordered_map>

#include "framework/core/error.h"
#include "io/gmsh_stream.h"

namespace voroseal {

namespace {

constexpr long long kMaxTag = 1000000;  // entity / physical tags that become ids
constexpr size_t kIntBytes = 4;         // an int of a binary file
constexpr size_t kRealBytes = 8;        // a double of a binary file

// Nodes of the element types read (15 point, 1 line, 8 3-node line, 2 triangle, 3 quadrangle,
// 4 tetrahedron); 0 for the other types, which are refused.
int element_nodes(long long type) {
  switch (type) {
    case 15:
      return 1;
    case 1:
      return 2;
    case 8:
    case 2:
      return 3;
    case 3:
    case 4:
      return 4;
    default:
      return 0;
  }
}

// Points, 2-node lines, triangles, quadrangles and tetrahedra are kept; 3-node lines are read
// and dropped.
bool kept(long long type) {
  return type == 15 || type == 1 || type == 2 || type == 3 || type == 4;
}

// Points and lines without a positive tag are dropped; the other kinds must have one.
bool needs_tag(long long type) {
  return type == 2 || type == 3 || type == 4;
}

struct MshFormat {
  int version = 41;  // 41 or 22
  bool binary = false;
  size_t size_bytes = 8;  // the size_t of a binary MSH 4.1 file
};

class MshParser {
 public:
  explicit MshParser(const TextSource& source) : in_(source) {}

  MshData parse() {
    bool format = false;
    while (in_.next_nonblank()) {
      const std::string section(in_[0].substr(0, 60));
      if (section.size() < 2 || section[0] != '$' || section.compare(0, 4, "$End") == 0)
        in_.fail("expected a section such as $Nodes, found '" + section + "'");
      const std::string name = section.substr(1);
      if (!format && name != "MeshFormat")
        in_.fail("not a Gmsh file: it must start with $MeshFormat");
      if (!read_section(name)) {
        skip_section(name);
        continue;
      }
      format = true;
      end_section(name);
    }
    if (!format) in_.fail("empty file: no $MeshFormat");
    return std::move(d_);
  }

 private:
  // Reads a known section up to its end line; false for a section to skip.
  bool read_section(const std::string& name) {
    const bool v41 = format_.version == 41, binary = format_.binary;
    if (name == "MeshFormat")
      mesh_format();
    else if (name == "PhysicalNames")
      physical_names();
    else if (name == "VorosealPieces")
      piece_names();
    else if (name == "Entities" && !v41)  // a MSH 4 body under a 2.2 format line
      in_.fail("$Entities is a MSH 4 section, but the format line says 2.2");
    else if (name == "Entities")
      binary ? entities_binary() : entities();
    else if (name == "Nodes")
      v41 ? (binary ? nodes41_binary() : nodes41()) : (binary ? nodes22_binary() : nodes22());
    else if (name == "Elements")
      v41 ? (binary ? elements41_binary() : elements41())
          : (binary ? elements22_binary() : elements22());
    else
      return false;
    return true;
  }

  // ---- text lines ----

  void line(const char* what) {
    if (!in_.next_nonblank()) in_.fail(std::string("file ends where ") + what + " was expected");
    if (in_[0][0] == '$')
      in_.fail(std::string("expected ") + what + ", found '" + std::string(in_[0].substr(0, 40)) +
               "' (a count does not match the entries)");
  }

  void end_section(const std::string& name) {
    if (!in_.next_nonblank()) in_.fail("file ends inside $" + name + " (no $End" + name + ")");
    if (in_[0] != "$End" + name)
      in_.fail("expected $End" + name + ", found '" + std::string(in_[0].substr(0, 40)) +
               "' (a count does not match the entries)");
  }

  void skip_section(const std::string& name) {
    if (!in_.skip_to_line("$End" + name)) in_.fail("section $" + name + " has no $End" + name);
  }

  long long count(size_t i, const char* what, size_t min_bytes_per_entry) {
    const long long n = in_.integer(i, what);
    if (n < 0) in_.fail(std::string("negative ") + what);
    if (static_cast<unsigned long long>(n) > in_.remaining_bytes() / min_bytes_per_entry)
      in_.fail(std::string(what) + " = " + std::to_string(n) +
               " is more than the rest of the file can hold");
    return n;
  }

  int tag(size_t i, const char* what) {
    const long long t = in_.integer(i, what);
    if (t < -kMaxTag || t > kMaxTag)
      in_.fail(std::string(what) + " " + std::to_string(t) + " out of range");
    return static_cast<int>(t);
  }

  int node(size_t i) {
    const long long t = in_.integer(i, "node tag");
    const int v = node_of(t);
    if (v < 0) in_.fail("element refers to unknown node " + std::to_string(t));
    return v;
  }

  // ---- binary values ----

  // A size_t of a MSH 4.1 file.
  uint64_t size_value(const char* what) { return in_.unsigned_integer(format_.size_bytes, what); }

  // A count of entries of at least `item_bytes` bytes each, checked against the rest.
  uint64_t binary_count(const char* what, uint64_t item_bytes) {
    const size_t at = in_.offset();
    const uint64_t n = size_value(what);
    in_.require_items(at, n, item_bytes, what);
    return n;
  }

  int binary_tag(const char* what) {
    const size_t at = in_.offset();
    const int32_t t = in_.int32(what);
    if (t < -kMaxTag || t > kMaxTag)
      in_.fail_at_byte(at, std::string(what) + " " + std::to_string(t) + " out of range");
    return t;
  }

  // The node of a binary node tag: an int (MSH 2.2) or a size_t (MSH 4.1).
  int binary_node(bool int_tags) {
    const size_t at = in_.offset();
    if (int_tags) {
      const int32_t t = in_.int32("node tag");
      const int v = node_of(t);
      if (v < 0) in_.fail_at_byte(at, "element refers to unknown node " + std::to_string(t));
      return v;
    }
    const uint64_t t = size_value("node tag");
    const int v = t <= LLONG_MAX ? node_of(static_cast<long long>(t)) : -1;
    if (v < 0) in_.fail_at_byte(at, "element refers to unknown node " + std::to_string(t));
    return v;
  }

  // ---- $MeshFormat, $PhysicalNames ----

  void mesh_format() {
    line("the format line (4.1 0 8)");
    in_.require(3, "version file-type data-size");
    const std::string version(in_[0].substr(0, 20));
    if (version != "4.1" && version != "2.2")
      in_.fail("only MSH versions 4.1 and 2.2 are supported, found '" + version + "'");
    format_.version = version == "4.1" ? 41 : 22;
    const long long type = in_.integer(1, "file type");
    if (type != 0 && type != 1)
      in_.fail("file type must be 0 (ASCII) or 1 (binary), found " + std::to_string(type));
    format_.binary = type == 1;
    const long long size = in_.integer(2, "data size");
    if (!format_.binary) return;
    // data-size is sizeof(double) in MSH 2.2 and sizeof(size_t) in MSH 4.1.
    if (size != 8 && !(size == 4 && format_.version == 41))
      in_.fail("binary MSH " + version + " with data size " + std::to_string(size) +
               " is not supported (8" + (format_.version == 41 ? " or 4)" : ")"));
    format_.size_bytes = static_cast<size_t>(size);
    endianness_check();
  }

  // A binary file writes the int 1 after the format line: its bytes tell the byte order.
  void endianness_check() {
    const size_t at = in_.offset();
    const int32_t one = in_.int32("the binary integer 1 (endianness check)");
    if (one == 0x01000000) in_.fail_at_byte(at, "big-endian binary .msh files are not supported");
    if (one != 1)
      in_.fail_at_byte(at,
                       "expected the binary integer 1 (endianness check) after the format line");
  }

  void physical_names() {
    line("the number of physical names");
    const long long n = count(0, "number of physical names", 6);
    for (long long i = 0; i < n; ++i) {
      line("a physical name (dim tag \"name\")");
      in_.require(3, "a physical name (dim tag \"name\")");
      const int dim = tag(0, "dimension");
      const int t = tag(1, "physical tag");
      d_.physical_names[{dim, t}] = quoted("a physical name");
    }
  }

  // voroseal's own section (written after $Elements; other readers skip it): the name of each
  // surface entity, a piece of a surface.
  void piece_names() {
    line("the number of piece names");
    const long long n = count(0, "number of piece names", 5);
    for (long long i = 0; i < n; ++i) {
      line("a piece name (entity \"name\")");
      in_.require(2, "a piece name (entity \"name\")");
      const int t = tag(0, "entity tag");
      d_.piece_names[t] = quoted("a piece name");
    }
  }

  // The text between the first and the last double quote of the line.
  std::string quoted(const std::string& what) {
    const std::string_view text = in_.text();
    const size_t open = text.find('"'), close = text.rfind('"');
    if (open == std::string_view::npos || close == open) in_.fail(what + " must be quoted");
    return std::string(text.substr(open + 1, close - open - 1));
  }

  // ---- $Entities (MSH 4.1) ----

  void entities() {
    line("the entity counts");
    in_.require(4, "numPoints numCurves numSurfaces numVolumes");
    long long n[4];
    for (int k = 0; k < 4; ++k) n[k] = count(k, "number of entities", 8);
    for (int dim = 0; dim < 4; ++dim)
      for (long long i = 0; i < n[dim]; ++i) entity(dim);
  }

  void entity(int dim) {
    line("an entity");
    const size_t first_physical = dim == 0 ? 4 : 7;
    in_.require(first_physical + 1, "an entity");
    const int t = tag(0, "entity tag");
    for (size_t k = 1; k < first_physical; ++k) in_.real(k, "coordinate");
    const long long np = in_.integer(first_physical, "number of physical tags");
    if (np < 0 || static_cast<size_t>(np) > in_.size()) in_.fail("bad number of physical tags");
    in_.require(first_physical + 1 + np + (dim == 0 ? 0 : 1), "an entity");
    if (np > 0) entity_physical_[{dim, t}] = tag(first_physical + 1, "physical tag");
    for (long long k = 1; k < np; ++k) tag(first_physical + 1 + k, "physical tag");
    if (dim > 0) {
      const size_t nb_at = first_physical + 1 + np;
      const long long nb = in_.integer(nb_at, "number of bounding entities");
      if (nb < 0 || static_cast<size_t>(nb) + nb_at + 1 != in_.size())
        in_.fail("the number of bounding entities does not match the line");
      for (long long k = 0; k < nb; ++k) tag(nb_at + 1 + k, "bounding entity tag");
    }
  }

  // Binary: int tag, doubles (a point's 3 coordinates, else a box of 6), size_t and ints of the
  // physical tags, then for curves, surfaces and volumes size_t and ints of the bounding entities.
  void entities_binary() {
    uint64_t n[4];
    const uint64_t smallest = kIntBytes + 3 * kRealBytes + format_.size_bytes;
    for (int k = 0; k < 4; ++k) n[k] = binary_count("number of entities", smallest);
    for (int dim = 0; dim < 4; ++dim)
      for (uint64_t i = 0; i < n[dim]; ++i) entity_binary(dim);
  }

  void entity_binary(int dim) {
    const int t = binary_tag("entity tag");
    in_.skip((dim == 0 ? 3 : 6) * kRealBytes, "an entity's coordinates");
    const uint64_t np = binary_count("number of physical tags", kIntBytes);
    if (np > 0) entity_physical_[{dim, t}] = binary_tag("physical tag");
    in_.skip((np - std::min<uint64_t>(np, 1)) * kIntBytes, "an entity's physical tags");
    if (dim == 0) return;
    const uint64_t nb = binary_count("number of bounding entities", kIntBytes);
    in_.skip(nb * kIntBytes, "an entity's bounding entities");
  }

  // ---- nodes ----

  // Index of a new node, false when the tag is already used.
  bool add_node(long long tag, const Vec3& p) {
    if (!node_index_.emplace(tag, static_cast<int>(d_.nodes.size())).second) return false;
    d_.nodes.push_back(p);
    return true;
  }

  int node_of(long long tag) const {
    const auto it = node_index_.find(tag);
    return it == node_index_.end() ? -1 : it->second;
  }

  void nodes41() {
    line("the node counts");
    in_.require(4, "numEntityBlocks numNodes minNodeTag maxNodeTag");
    const long long blocks = count(0, "number of node blocks", 8);
    const long long total = count(1, "number of nodes", 8);
    in_.integer(2, "min node tag");
    in_.integer(3, "max node tag");
    d_.nodes.reserve(d_.nodes.size() + total);
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b) {
      line("a node block header");
      in_.require(4, "entityDim entityTag parametric numNodesInBlock");
      const long long dim = in_.integer(0, "entity dimension");
      tag(1, "entity tag");
      const long long parametric = in_.integer(2, "parametric flag");
      if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1) in_.fail("bad node block header");
      const long long n = count(3, "number of nodes in block", 8);
      if (seen + n > total) in_.fail("node blocks hold more nodes than declared");
      seen += n;
      node_block(n, 3 + (parametric ? static_cast<size_t>(dim) : 0));
    }
    if (seen != total)
      in_.fail("$Nodes declares " + std::to_string(total) + " nodes but its blocks hold " +
               std::to_string(seen));
  }

  // The tags of the n nodes of a block, then their coordinates (with `values` numbers a line).
  void node_block(long long n, size_t values) {
    std::vector<long long> tags;
    for (long long i = 0; i < n; ++i) {
      line("a node tag");
      tags.push_back(in_.integer(0, "node tag"));
    }
    for (long long i = 0; i < n; ++i) {
      line("node coordinates");
      in_.require(values, "node coordinates");
      const Vec3 p(in_.real(0, "x"), in_.real(1, "y"), in_.real(2, "z"));
      if (!add_node(tags[i], p)) in_.fail("duplicate node tag " + std::to_string(tags[i]));
    }
  }

  // Binary: size_t counts; a block is int dim, int entity, int parametric, size_t count, then
  // its size_t tags and its coordinates (3 doubles, plus dim parametric ones).
  void nodes41_binary() {
    const size_t sz = format_.size_bytes;
    const uint64_t blocks = binary_count("number of node blocks", 3 * kIntBytes + sz);
    const uint64_t total = binary_count("number of nodes", sz + 3 * kRealBytes);
    size_value("min node tag");
    size_value("max node tag");
    d_.nodes.reserve(d_.nodes.size() + total);
    uint64_t seen = 0;
    for (uint64_t b = 0; b < blocks; ++b) {
      const size_t at = in_.offset();
      const int32_t dim = in_.int32("entity dimension");
      binary_tag("entity tag");
      const int32_t parametric = in_.int32("parametric flag");
      if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1)
        in_.fail_at_byte(at, "bad node block header");
      const size_t values = 3 + (parametric ? static_cast<size_t>(dim) : 0);
      const uint64_t n = binary_count("number of nodes in block", sz + values * kRealBytes);
      if (n > total - seen) in_.fail_at_byte(at, "node blocks hold more nodes than declared");
      seen += n;
      node_block_binary(n, values);
    }
    if (seen != total)
      in_.fail_at_byte(in_.offset(), "$Nodes declares " + std::to_string(total) +
                                         " nodes but its blocks hold " + std::to_string(seen));
  }

  void node_block_binary(uint64_t n, size_t values) {
    const int first = static_cast<int>(d_.nodes.size());
    for (uint64_t i = 0; i < n; ++i) {
      const size_t at = in_.offset();
      const uint64_t t = size_value("node tag");
      if (t == 0 || t > LLONG_MAX)
        in_.fail_at_byte(at, "node tag " + std::to_string(t) + " out of range");
      if (!node_index_.emplace(static_cast<long long>(t), first + static_cast<int>(i)).second)
        in_.fail_at_byte(at, "duplicate node tag " + std::to_string(t));
    }
    for (uint64_t i = 0; i < n; ++i) {
      const double x = in_.real64("x"), y = in_.real64("y"), z = in_.real64("z");
      d_.nodes.emplace_back(x, y, z);
      in_.skip((values - 3) * kRealBytes, "parametric coordinates");
    }
  }

  void nodes22() {
    line("the number of nodes");
    const long long n = count(0, "number of nodes", 8);
    d_.nodes.reserve(d_.nodes.size() + n);
    for (long long i = 0; i < n; ++i) {
      line("a node (tag x y z)");
      in_.require(4, "a node (tag x y z)");
      const long long t = in_.integer(0, "node tag");
      const Vec3 p(in_.real(1, "x"), in_.real(2, "y"), in_.real(3, "z"));
      if (!add_node(t, p)) in_.fail("duplicate node tag " + std::to_string(t));
    }
  }

  // Binary: the count as text, then per node int tag and 3 doubles.
  void nodes22_binary() {
    line("the number of nodes");
    const long long n = count(0, "number of nodes", kIntBytes + 3 * kRealBytes);
    d_.nodes.reserve(d_.nodes.size() + n);
    for (long long i = 0; i < n; ++i) {
      const size_t at = in_.offset();
      const int32_t t = in_.int32("node tag");
      const double x = in_.real64("x"), y = in_.real64("y"), z = in_.real64("z");
      if (!add_node(t, Vec3(x, y, z)))
        in_.fail_at_byte(at, "duplicate node tag " + std::to_string(t));
    }
  }

  // ---- elements ----

  // The tag of the elements of an entity: its physical tag, else its own tag.
  int entity_tag(int dim, int entity) const {
    const auto physical = entity_physical_.find({dim, entity});
    return physical != entity_physical_.end() ? physical->second : entity;
  }

  // Stores a kept element (v: its node indices); a quadrangle becomes two triangles.
  void add_element(long long type, int tag, int entity, const int* v) {
    if (!needs_tag(type) && tag < 1) return;
    if (type == 15) {
      d_.points.push_back(v[0]);
      d_.point_tag.push_back(tag);
    } else if (type == 1) {
      d_.lines.push_back({v[0], v[1]});
      d_.line_tag.push_back(tag);
    } else if (type == 2 || type == 3) {
      d_.triangles.push_back({v[0], v[1], v[2]});
      d_.triangle_tag.push_back(tag);
      d_.triangle_entity.push_back(entity);
      if (type == 3) {
        d_.triangles.push_back({v[0], v[2], v[3]});
        d_.triangle_tag.push_back(tag);
        d_.triangle_entity.push_back(entity);
      }
    } else if (type == 4) {
      d_.tets.push_back({v[0], v[1], v[2], v[3]});
      d_.tet_tag.push_back(tag);
    }
  }

  void elements41() {
    line("the element counts");
    in_.require(4, "numEntityBlocks numElements minElementTag maxElementTag");
    const long long blocks = count(0, "number of element blocks", 8);
    const long long total = count(1, "number of elements", 4);
    in_.integer(2, "min element tag");
    in_.integer(3, "max element tag");
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b) {
      line("an element block header");
      in_.require(4, "entityDim entityTag elementType numElementsInBlock");
      const int dim = tag(0, "entity dimension");
      const int entity = tag(1, "entity tag");
      const long long type = in_.integer(2, "element type");
      const long long n = count(3, "number of elements in block", 4);
      seen += n;
      if (seen > total) in_.fail("element blocks hold more elements than declared");
      if (element_nodes(type) == 0) in_.fail("unsupported element type " + std::to_string(type));
      const int id_tag = entity_tag(dim, entity);
      if (needs_tag(type) && id_tag < 1)
        in_.fail("element block of entity " + std::to_string(entity) + " has no positive tag");
      for (long long i = 0; i < n; ++i) element41(type, id_tag, entity);
    }
    if (seen != total)
      in_.fail("$Elements declares " + std::to_string(total) + " elements but its blocks hold " +
               std::to_string(seen));
  }

  void element41(long long type, int id_tag, int entity) {
    const int nodes = element_nodes(type);
    line("an element");
    if (in_.size() != static_cast<size_t>(nodes) + 1)
      in_.fail("element of type " + std::to_string(type) + " needs a tag and " +
               std::to_string(nodes) + " nodes");
    in_.integer(0, "element tag");
    int v[4] = {0, 0, 0, 0};
    for (int k = 0; k < nodes; ++k) {
      if (kept(type))
        v[k] = node(1 + k);
      else
        in_.integer(1 + k, "node tag");
    }
    if (kept(type)) add_element(type, id_tag, entity, v);
  }

  // Binary: size_t counts; a block is int dim, int entity, int type, size_t count, then per
  // element its size_t tag and size_t node tags.
  void elements41_binary() {
    const size_t sz = format_.size_bytes;
    const uint64_t blocks = binary_count("number of element blocks", 3 * kIntBytes + sz);
    const uint64_t total = binary_count("number of elements", 2 * sz);
    size_value("min element tag");
    size_value("max element tag");
    uint64_t seen = 0;
    for (uint64_t b = 0; b < blocks; ++b) {
      const size_t at = in_.offset();
      const int dim = binary_tag("entity dimension");
      const int entity = binary_tag("entity tag");
      const int32_t type = in_.int32("element type");
      const int nodes = element_nodes(type);
      if (nodes == 0) in_.fail_at_byte(at, "unsupported element type " + std::to_string(type));
      const uint64_t n = binary_count("number of elements in block", (1 + nodes) * sz);
      if (n > total - seen) in_.fail_at_byte(at, "element blocks hold more elements than declared");
      seen += n;
      const int id_tag = entity_tag(dim, entity);
      if (needs_tag(type) && id_tag < 1)
        in_.fail_at_byte(
            at, "element block of entity " + std::to_string(entity) + " has no positive tag");
      for (uint64_t i = 0; i < n; ++i) {
        size_value("element tag");
        element_binary_nodes(type, id_tag, entity, false);
      }
    }
    if (seen != total)
      in_.fail_at_byte(in_.offset(), "$Elements declares " + std::to_string(total) +
                                         " elements but its blocks hold " + std::to_string(seen));
  }

  // The node tags of a binary element, ints (MSH 2.2) or size_t (MSH 4.1); kept types only
  // are looked up.
  void element_binary_nodes(long long type, int id_tag, int entity, bool int_tags) {
    int v[4] = {0, 0, 0, 0};
    const int nodes = element_nodes(type);
    if (!kept(type)) {
      in_.skip(nodes * (int_tags ? kIntBytes : format_.size_bytes), "an element's node tags");
      return;
    }
    for (int k = 0; k < nodes; ++k) v[k] = binary_node(int_tags);
    add_element(type, id_tag, entity, v);
  }

  void elements22() {
    line("the number of elements");
    const long long n = count(0, "number of elements", 8);
    for (long long i = 0; i < n; ++i) element22();
  }

  // id type ntags tag... node...: the first tag is the physical tag (0: none), the second the
  // elementary entity, the others (partitions) are ignored.
  void element22() {
    line("an element (id type ntags tags... nodes...)");
    in_.require(3, "an element (id type ntags tags... nodes...)");
    in_.integer(0, "element tag");
    const long long type = in_.integer(1, "element type");
    const int nodes = element_nodes(type);
    if (nodes == 0) in_.fail("unsupported element type " + std::to_string(type));
    const long long ntags = in_.integer(2, "number of tags");
    if (ntags < 0 || static_cast<size_t>(ntags) + 3 + nodes != in_.size())
      in_.fail("element of type " + std::to_string(type) + " with " + std::to_string(ntags) +
               " tags needs " + std::to_string(nodes) + " nodes after them");
    const int physical = ntags > 0 ? tag(3, "physical tag") : 0;
    const int entity = ntags > 1 ? tag(4, "elementary entity tag") : 0;
    for (long long k = 2; k < ntags; ++k) in_.integer(3 + k, "element tag");
    const int id_tag = physical != 0 ? physical : entity;
    if (needs_tag(type) && id_tag < 1) in_.fail("element has no positive physical or entity tag");
    const size_t first = 3 + static_cast<size_t>(ntags);
    int v[4] = {0, 0, 0, 0};
    for (int k = 0; k < nodes; ++k) {
      if (kept(type))
        v[k] = node(first + k);
      else
        in_.integer(first + k, "node tag");
    }
    if (kept(type)) add_element(type, id_tag, entity, v);
  }

  // Binary: the count as text, then blocks of int type, int count, int ntags followed by that
  // many elements of int id, ntags int tags and int node tags.
  void elements22_binary() {
    line("the number of elements");
    const long long total = count(0, "number of elements", 2 * kIntBytes);
    long long seen = 0;
    while (seen < total) {
      const size_t at = in_.offset();
      const int32_t type = in_.int32("element type");
      const int32_t n = in_.int32("number of elements in block");
      const int32_t ntags = in_.int32("number of tags");
      const int nodes = element_nodes(type);
      if (nodes == 0) in_.fail_at_byte(at, "unsupported element type " + std::to_string(type));
      if (n < 0 || ntags < 0) in_.fail_at_byte(at, "negative count in an element block header");
      if (n > total - seen) in_.fail_at_byte(at, "element blocks hold more elements than declared");
      const uint64_t element_bytes = kIntBytes * (1 + static_cast<uint64_t>(ntags) + nodes);
      in_.require_items(at, static_cast<uint64_t>(n), element_bytes, "number of elements in block");
      seen += n;
      for (int32_t i = 0; i < n; ++i) element22_binary(type, ntags);
    }
  }

  void element22_binary(int32_t type, int32_t ntags) {
    const size_t at = in_.offset();
    in_.int32("element tag");
    const int physical = ntags > 0 ? binary_tag("physical tag") : 0;
    const int entity = ntags > 1 ? binary_tag("elementary entity tag") : 0;
    in_.skip(kIntBytes * static_cast<uint64_t>(ntags - std::min(ntags, 2)), "element tags");
    const int id_tag = physical != 0 ? physical : entity;
    if (needs_tag(type) && id_tag < 1)
      in_.fail_at_byte(at, "element has no positive physical or entity tag");
    element_binary_nodes(type, id_tag, entity, true);
  }

  MshStream in_;
  MshFormat format_;
  MshData d_;
  std::map<std::pair<int, int>, int> entity_physical_;
  std::unordered_map<long long, int> node_index_;
};

}  // namespace

MshData parse_msh(const TextSource& source) {
  return MshParser(source).parse();
}

}  // namespace voroseal
