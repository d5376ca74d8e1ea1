// diffuv: the PLY reader, shared by every reader of PLY files: the header
// (elements and their typed properties) and the values, as text or as
// little- or big-endian binary, read from the file's bytes. `scan_ply()`
// reads the points and polygons of a mesh in one pass, as CGAL's PLY reader
// reads them, and says why a file is bad, so that CGAL's reader is not
// called (issue #20); `read_ply_paint()` (read_paint.h) reads the colours and
// labels of the same elements.
#ifndef DIFFUV_IO_INTERNAL_PLY_SCANNER_H
#define DIFFUV_IO_INTERNAL_PLY_SCANNER_H

#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/number_tokens.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <iterator>
#include <sstream>
#include <streambuf>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <vector>

namespace diffuv {
namespace internal {

enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

/// The type named `name` (both PLY spellings: "uchar" or "uint8"); false if unknown.
inline bool ply_type(const std::string& name, Ply_type& type)
{
  static const char* const names[16] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                        "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  const auto it = std::find(names, names + 16, name);
  type = static_cast<Ply_type>((it - names) % 8);
  return it != names + 16;
}

/// Bytes of a binary value of type `type`.
inline std::size_t ply_size(Ply_type type)
{
  static const std::size_t sizes[8] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[static_cast<int>(type)];
}

inline bool is_float(Ply_type type) { return type == Ply_type::float32 || type == Ply_type::float64; }

struct Ply_property {
  std::string name;
  Ply_type type = Ply_type::int8;       ///< of the value, or of each entry of a list
  bool list = false;
  Ply_type count_type = Ply_type::int8; ///< of the length of a list
};

struct Ply_element {
  std::string name;
  std::uintmax_t count = 0; ///< items announced
  std::size_t line = 0;     ///< of the element line
  std::vector<Ply_property> properties;
};

struct Ply_header {
  int format = 0; ///< 0 text, 1 little-endian, 2 big-endian
  std::vector<Ply_element> elements;
  std::size_t lines = 0; ///< lines read, the end_header line included
  bool ended = false;    ///< the end_header line was read (else the header ran to the end of the file)
};

/// How a header is read. `cgal`: as CGAL's PLY reader (CGAL 5.5) reads it,
/// so that a mesh file is judged by what that reader will do: line 2 is the
/// format line whatever its keyword, properties of unknown type are skipped,
/// other lines ignored, and a header without end_header ends with the file.
/// `strict`: every line must be known (blank lines, comments and obj_info
/// aside), every type too, and the header must end.
enum class Ply_header_rules { cgal, strict };

/// Reads the header of a PLY file from `in`, which is left at the first
/// byte of data. Returns the problem ("" if none), and its line in
/// `error_line` (0 if not on a line).
inline std::string read_ply_header(std::istream& in, std::uintmax_t file_size, Ply_header_rules rules,
                                   Ply_header& header, std::size_t& error_line)
{
  const bool cgal = rules == Ply_header_rules::cgal;
  header = Ply_header();
  header.format = cgal ? 0 : -1;
  auto fail = [&](std::size_t line, const std::string& what) {
    error_line = line;
    return what;
  };
  auto format_of = [](const std::string& name) {
    return name == "ascii" ? 0 : name == "binary_little_endian" ? 1 : name == "binary_big_endian" ? 2 : -1;
  };
  std::string text;
  for(std::size_t number = 1;; ++number) {
    if(!std::getline(in, text)) {
      if(cgal)
        break; // CGAL reads the data it finds
      return fail(0, "the header has no end_header line");
    }
    header.lines = number;
    if(!text.empty() && text.back() == '\r')
      text.pop_back(); // CRLF files: not part of the line quoted in messages
    std::istringstream words(text);
    std::string keyword, a, b, c, name;
    const bool has_keyword = static_cast<bool>(words >> keyword);
    if(number == 1) {
      if(keyword != "ply")
        return fail(1, "the file does not start with \"ply\"");
    } else if(cgal && number == 2) {
      if(!has_keyword || !(words >> a >> b))
        return fail(2, "the second line is not a format line");
      header.format = format_of(a);
      if(header.format < 0)
        return fail(2, "unknown format \"" + a + "\"");
    } else if(!has_keyword) {
      if(cgal)
        return fail(number, "empty header line");
    } else if(!cgal && keyword == "format") {
      words >> a;
      header.format = format_of(a);
      if(header.format < 0)
        return fail(number, "unknown format \"" + a + "\"");
    } else if(keyword == "element") {
      std::uintmax_t count = 0;
      if(cgal) {
        std::size_t n = 0;
        if(!(words >> a >> n))
          return fail(number, "cannot read the element line");
        count = n;
        // An element without properties is "read" that many times.
        if(count > file_size)
          return fail(number, "the header announces " + std::to_string(count) + " " + a + " items, more than the " +
                                  std::to_string(file_size) + " bytes of the file can hold");
      } else if(!(words >> a >> b) || std::from_chars(b.data(), b.data() + b.size(), count).ec != std::errc()) {
        return fail(number, "cannot read the element line \"" + text + "\"");
      }
      header.elements.push_back({a, count, number, {}});
    } else if(keyword == "property") {
      // "property TYPE NAME" or "property list SIZE_TYPE TYPE NAME"
      Ply_property p;
      p.list = (words >> a) && a == "list";
      const bool read = p.list ? static_cast<bool>(words >> b >> c >> name) : static_cast<bool>(words >> name);
      p.name = name;
      const bool known_count = p.list && ply_type(b, p.count_type);
      const bool known_type = ply_type(p.list ? c : a, p.type);
      if(cgal) {
        if(!read)
          return fail(number, "cannot read the property line");
        // CGAL would take the last element of an empty list.
        if(header.elements.empty())
          return fail(number, "a property line comes before any element line");
        // CGAL skips a property of unknown type, and a list with a float length.
        if(known_type && (!p.list || (known_count && !is_float(p.count_type))))
          header.elements.back().properties.push_back(p);
      } else {
        if(!read || !known_type || (p.list && !known_count) || header.elements.empty())
          return fail(number, "cannot read the property line \"" + text + "\"");
        header.elements.back().properties.push_back(p);
      }
    } else if(keyword == "end_header") {
      header.ended = true;
      break;
    } else if(!cgal && keyword != "comment" && keyword != "obj_info") {
      return fail(number, "unexpected header line \"" + text + "\"");
    }
  }
  if(!cgal && header.format < 0)
    return fail(0, "the header has no format line");
  return std::string();
}

/// A stream over bytes in memory, for the header only: its lines are read
/// with `std::getline` and `>>` as CGAL's reader reads them, and it says
/// where the data start. The data are read without a stream.
class Ply_header_buffer : public std::streambuf {
public:
  explicit Ply_header_buffer(std::string_view bytes)
  {
    char* first = const_cast<char*>(bytes.data()); // read only: the buffer has no put area
    setg(first, first, first + bytes.size());
  }
  std::size_t offset() const { return static_cast<std::size_t>(gptr() - eback()); }
};

/// Reads the header at the start of `bytes` (see the stream version);
/// `data_start` receives the offset of the first byte after it.
inline std::string read_ply_header(std::string_view bytes, std::uintmax_t file_size, Ply_header_rules rules,
                                   Ply_header& header, std::size_t& error_line, std::size_t& data_start)
{
  Ply_header_buffer buffer(bytes);
  std::istream in(&buffer);
  std::string problem = read_ply_header(in, file_size, rules, header, error_line);
  data_start = buffer.offset();
  return problem;
}

/// Reads the values of a PLY file after its header, as text or as little- or
/// big-endian binary, from the file's bytes.
class Ply_value_reader {
public:
  /// \param data the bytes after the header
  /// \param line the line of the first value (text files)
  Ply_value_reader(std::string_view data, int format, std::size_t line)
      : at_(data.data()), end_(data.data() + data.size()), format_(format), line_(line)
  {
    const std::uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    swap_ = (format == 2) == (first == 1); // big-endian file on a little-endian host, or the reverse
  }

  /// True once every byte was read (what a stream's eof() says after a read that failed).
  bool at_end() const { return at_ == end_; }

  /// Skips white space (text) and returns the line of the next value, 0 in binary.
  std::size_t start_item()
  {
    if(format_ != 0)
      return 0;
    for(; at_ < end_ && is_blank(*at_); ++at_)
      if(*at_ == '\n')
        ++line_;
    return line_;
  }

  /// Reads a value of type `type`; in text, the whole white-space separated
  /// word must be a number (`parse_number()`). Returns false if it cannot.
  bool read(Ply_type type, double& value)
  {
    if(format_ != 0)
      return read_binary(type, value);
    start_item();
    const char* const first = at_;
    while(at_ < end_ && !is_blank(*at_))
      ++at_;
    return parse_number(std::string_view(first, static_cast<std::size_t>(at_ - first)), value);
  }

  /// Reads a value of type `type` as CGAL's PLY reader reads it: in text,
  /// as `operator>>` into that type reads it (8-bit values through 16-bit
  /// ones, then cut to 8 bits), which stops at the first character that does
  /// not fit; a float is read as a float, then widened. Lines are not counted.
  bool read_like_cgal(Ply_type type, double& value)
  {
    if(format_ != 0)
      return read_binary(type, value);
    switch(type) {
      case Ply_type::int8: return text<short, signed char>(value);
      case Ply_type::uint8: return text<unsigned short, unsigned char>(value);
      case Ply_type::int16: return text<std::int16_t, std::int16_t>(value);
      case Ply_type::uint16: return text<std::uint16_t, std::uint16_t>(value);
      case Ply_type::int32: return text<std::int32_t, std::int32_t>(value);
      case Ply_type::uint32: return text<std::uint32_t, std::uint32_t>(value);
      case Ply_type::float32: return text<float, float>(value);
      case Ply_type::float64: return text<double, double>(value);
    }
    return false;
  }

private:
  // `>> Read` (a libstdc++ stream), stored as a `Stored`.
  template <class Read, class Stored> bool text(double& value)
  {
    Read read{}; // the value of a failed read is not used, but is not left uninitialised
    bool ok;
    if constexpr(std::is_floating_point_v<Read>)
      ok = extract_floating(at_, end_, read);
    else
      ok = extract_integer(at_, end_, read);
    value = static_cast<Stored>(read);
    return ok;
  }

  bool read_binary(Ply_type type, double& value)
  {
    switch(type) {
      case Ply_type::int8: return binary<std::int8_t>(value);
      case Ply_type::uint8: return binary<std::uint8_t>(value);
      case Ply_type::int16: return binary<std::int16_t>(value);
      case Ply_type::uint16: return binary<std::uint16_t>(value);
      case Ply_type::int32: return binary<std::int32_t>(value);
      case Ply_type::uint32: return binary<std::uint32_t>(value);
      case Ply_type::float32: return binary<float>(value);
      case Ply_type::float64: return binary<double>(value);
    }
    return false;
  }

  template <class T> bool binary(double& value)
  {
    if(static_cast<std::size_t>(end_ - at_) < sizeof(T)) {
      at_ = end_; // a stream reads what is left, and fails
      return false;
    }
    unsigned char b[sizeof(T)];
    std::memcpy(b, at_, sizeof(T));
    at_ += sizeof(T);
    if(swap_)
      std::reverse(b, b + sizeof(T));
    T t;
    std::memcpy(&t, b, sizeof(T));
    value = static_cast<double>(t);
    return true;
  }

  const char* at_;
  const char* end_;
  int format_; // 0 text, 1 little-endian, 2 big-endian
  std::size_t line_;
  bool swap_;
};

/// The property CGAL's PLY reader takes the vertex indices of a face from:
/// the first property named "vertex_indices" if it is a list of int or of
/// uint, else the first named "vertex_index" if it is; -1 if none is.
inline int ply_face_indices(const Ply_element& face)
{
  for(const char* name : {"vertex_indices", "vertex_index"})
    for(std::size_t k = 0; k < face.properties.size(); ++k) {
      const Ply_property& p = face.properties[k];
      if(p.name != name)
        continue;
      if(p.list && (p.type == Ply_type::int32 || p.type == Ply_type::uint32))
        return static_cast<int>(k);
      break; // only the first property of a name counts
    }
  return -1;
}

/// How many items of `e` the `bytes` after the header can hold at most, for
/// reserving arrays: each value takes a byte and a separator in text, its
/// size in binary (a list at least its length).
inline std::uintmax_t ply_items_that_fit(const Ply_element& e, std::size_t bytes, int format)
{
  std::size_t least = 0;
  for(const Ply_property& p : e.properties)
    least += format == 0 ? 2 : ply_size(p.list ? p.count_type : p.type);
  return least == 0 ? e.count : std::min<std::uintmax_t>(e.count, bytes / least + 1);
}

/// Reads the PLY file `bytes` (of `file_size` bytes, for messages) in one
/// pass, as CGAL's `read_PLY()` (CGAL 5.5) reads it: the header with
/// `Ply_header_rules::cgal`; then every element in turn, each value as
/// `Ply_value_reader::read_like_cgal()` reads it; a point from the first
/// properties named x, y and z of each "vertex" or "vertices" item (0 for
/// one that is missing), a polygon from the list of `ply_face_indices()` of
/// each "face" or "faces" item (a negative int index becomes a huge one);
/// other properties and elements read and dropped. Fills `soup` with what
/// CGAL would give; `soup.complete` is whether CGAL would accept the file.
///
/// The scan gives what CGAL's reader does not survive, before the file is
/// read further (CGAL 5.5 would crash or allocate without bound): a property
/// line before any element line (CGAL takes the last element of an empty
/// list); an element count larger than the file (an element without
/// properties is "read" that many times); a vertex coordinate or colour, or
/// a halfedge index, of another type than the one CGAL reads it as (a failed
/// assertion, then a null pointer); a list longer than the file, or whose
/// length cannot be read (CGAL allocates the list before reading it, with an
/// uninitialised length if the read failed). The lists are checked when one
/// list length is 32-bit (an 8- or 16-bit length cannot ask for much); with
/// none, a negative 8- or 16-bit length gets the message of the exception
/// that CGAL's reader throws (vector::_M_default_append). Elements have no
/// lines in the scan.
inline Text_mesh_scan scan_ply(std::string_view bytes, std::uintmax_t file_size, Polygon_soup& soup)
{
  Text_mesh_scan scan;
  soup = Polygon_soup();
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid PLY file (" + what + ")";
    return scan;
  };
  Ply_header header;
  std::size_t error_line = 0, data_start = 0;
  const std::string problem =
      read_ply_header(bytes, file_size, Ply_header_rules::cgal, header, error_line, data_start);
  if(!problem.empty())
    return fail(error_line, problem);
  const std::vector<Ply_element>& elements = header.elements;

  // The types CGAL asserts: the first property of each name it reads.
  for(const Ply_element& e : elements) {
    auto find = [&](const char* name) -> const Ply_property* {
      for(const Ply_property& p : e.properties)
        if(p.name == name) return &p;
      return nullptr;
    };
    auto is = [&](const char* name, Ply_type type) {
      const Ply_property* p = find(name);
      return p && !p->list && p->type == type;
    };
    auto require = [&](const char* name, const char* type, bool ok) {
      const Ply_property* p = find(name);
      if(p && !ok)
        fail(e.line, "property \"" + std::string(name) + "\" of element \"" + e.name + "\" is not of type " + type);
      return !p || ok;
    };
    const bool vertex = e.name == "vertex" || e.name == "vertices";
    if(vertex)
      for(const char* xyz : {"x", "y", "z"})
        if(!require(xyz, "float or double", is(xyz, Ply_type::float32) || is(xyz, Ply_type::float64)))
          return scan;
    if(vertex || e.name == "face" || e.name == "faces") {
      const bool red = is("red", Ply_type::uint8);
      if((red || is("r", Ply_type::uint8)) && (is("green", Ply_type::uint8) || is("g", Ply_type::uint8)) &&
         (is("blue", Ply_type::uint8) || is("b", Ply_type::uint8)))
        for(const char* rgb : red ? std::vector<const char*>{"red", "green", "blue"} : std::vector<const char*>{"r", "g", "b"})
          if(!require(rgb, "uchar", is(rgb, Ply_type::uint8)))
            return scan;
    }
    if(e.name == "halfedge" && !(is("source", Ply_type::uint32) && is("target", Ply_type::uint32) &&
                                 is("u", Ply_type::float32) && is("v", Ply_type::float32)))
      for(const char* end : {"source", "target"})
        if(!require(end, "uint", is(end, Ply_type::uint32)))
          return scan;
  }

  // Lists are checked as they are read when one has a 32-bit length.
  auto long_list = [](const Ply_property& p) { return p.list && ply_size(p.count_type) == 4; };
  bool long_lists = false;
  for(const Ply_element& e : elements)
    for(const Ply_property& p : e.properties)
      long_lists = long_lists || long_list(p);

  // Room for every point and polygon the file can hold, so that the arrays
  // never grow (growing copies them into fresh memory).
  const std::string_view data = bytes.substr(data_start);
  std::uintmax_t points = 0, polygons = 0;
  for(const Ply_element& e : elements) {
    if(e.name == "vertex" || e.name == "vertices")
      points += ply_items_that_fit(e, data.size(), header.format);
    if(e.name == "face" || e.name == "faces")
      polygons += ply_items_that_fit(e, data.size(), header.format);
  }
  soup.points.reserve(static_cast<std::size_t>(points));
  soup.polygons.reserve(static_cast<std::size_t>(polygons));

  // CGAL's reader stops at a value it cannot read (its result is then
  // false), and at a face element without vertex indices; the lists are
  // still checked to the end of the file, or to the first value that cannot
  // be read, as the scanner that ran before CGAL's reader checked them.
  bool cgal_reads = true;
  Ply_value_reader reader(data, header.format, header.lines + 1);
  std::vector<std::size_t> polygon;
  for(std::size_t k = 0; k < elements.size(); ++k) {
    const Ply_element& e = elements[k];
    const bool vertex = e.name == "vertex" || e.name == "vertices";
    const bool face = e.name == "face" || e.name == "faces";
    // The property each coordinate comes from (-1: none, the coordinate is 0).
    int xyz[3] = {-1, -1, -1};
    static const char* const coordinates[3] = {"x", "y", "z"};
    for(int c = 0; vertex && c < 3; ++c)
      for(std::size_t i = 0; i < e.properties.size() && xyz[c] < 0; ++i)
        if(e.properties[i].name == coordinates[c])
          xyz[c] = static_cast<int>(i);
    const int indices = face ? ply_face_indices(e) : -1;
    if(face && indices < 0) {
      cgal_reads = false; // "can't find vertex indices"
      if(!long_lists)
        break;
    }
    // CGAL ignores what reading the faces returned and reads the next
    // elements from the failed stream, where a list length is never written
    // before it is allocated (found by fuzzing: 7 GB).
    const bool faces_then_lists =
        face && std::any_of(elements.begin() + static_cast<std::ptrdiff_t>(k) + 1, elements.end(),
                            [&](const Ply_element& later) {
                              return std::any_of(later.properties.begin(), later.properties.end(), long_list);
                            });
    auto cut_short_before_lists = [&](std::uintmax_t j, const Ply_property& p) {
      return fail(0, "item " + std::to_string(j) + " of element \"" + e.name + "\" ends before its property \"" + p.name +
                         "\" can be read, and a later element has lists");
    };
    // A value that cannot be read: CGAL's result is false.
    auto stopped = [&](std::uintmax_t j, const Ply_property& p) {
      return long_lists && faces_then_lists ? cut_short_before_lists(j, p) : scan;
    };
    for(std::uintmax_t j = 0; j < e.count; ++j) {
      std::array<double, 3> point{0., 0., 0.};
      for(std::size_t i = 0; i < e.properties.size(); ++i) {
        const Ply_property& p = e.properties[i];
        double value;
        if(!reader.read_like_cgal(p.list ? p.count_type : p.type, value)) {
          // CGAL would allocate a list of the unread (uninitialised) length first.
          if(p.list && long_lists && !faces_then_lists)
            return fail(0, "the length of list \"" + p.name + "\" of item " + std::to_string(j) + " of element \"" +
                               e.name + "\" cannot be read");
          return stopped(j, p);
        }
        if(!p.list) {
          for(int c = 0; c < 3; ++c)
            if(xyz[c] == static_cast<int>(i))
              point[static_cast<std::size_t>(c)] = value;
          continue;
        }
        if(long_lists) {
          // At least one byte per value in binary, two (a digit and a space) in text.
          if(value < 0 || value * static_cast<double>(header.format == 0 ? 2 : ply_size(p.type)) >
                              static_cast<double>(file_size + 1))
            return fail(0, "item " + std::to_string(j) + " of element \"" + e.name + "\" has a list \"" + p.name +
                               "\" of " + std::to_string(static_cast<long long>(value)) + " values, " +
                               (value < 0 ? "a negative length" : "more than the file can hold"));
        } else if(value < 0) {
          // CGAL makes the length a std::size_t and resizes a vector to it.
          scan.error = "not a valid PLY file (vector::_M_default_append)";
          return scan;
        }
        const std::size_t n = static_cast<std::size_t>(value);
        const bool kept = cgal_reads && static_cast<int>(i) == indices;
        if(kept)
          polygon.clear();
        for(std::size_t v = 0; v < n; ++v) {
          if(!reader.read_like_cgal(p.type, value))
            return stopped(j, p);
          if(kept) // an int index as CGAL converts it: sign-extended
            polygon.push_back(static_cast<std::size_t>(static_cast<long long>(value)));
        }
      }
      if(vertex && cgal_reads)
        soup.points.push_back(point);
      if(face && cgal_reads)
        soup.polygons.push_back(polygon);
    }
  }
  // Without end_header, CGAL's stream failed at the end of the header.
  soup.complete = cgal_reads && header.ended;
  return scan;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_PLY_SCANNER_H
