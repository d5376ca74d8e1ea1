// diffuv: the PLY scanner, shared by every reader of PLY files: the header
// (elements and their typed properties) and the values, as text or as
// little- or big-endian binary. `scan_ply()` checks a file for what CGAL's
// PLY reader does not survive, before it reads the mesh; `read_ply_paint()`
// (read_paint.h) reads the colours and labels of the same elements.
#ifndef DIFFUV_IO_INTERNAL_PLY_SCANNER_H
#define DIFFUV_IO_INTERNAL_PLY_SCANNER_H

#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/number_tokens.h>

#include <CGAL/IO/io.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
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
      break;
    } else if(!cgal && keyword != "comment" && keyword != "obj_info") {
      return fail(number, "unexpected header line \"" + text + "\"");
    }
  }
  if(!cgal && header.format < 0)
    return fail(0, "the header has no format line");
  return std::string();
}

/// Reads the values of a PLY file after its header, as text or as little- or
/// big-endian binary.
class Ply_value_reader {
public:
  /// \param line the line of the first value (text files)
  Ply_value_reader(std::istream& in, int format, std::size_t line) : in_(in), format_(format), line_(line)
  {
    const std::uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    swap_ = (format == 2) == (first == 1); // big-endian file on a little-endian host, or the reverse
  }

  /// Skips white space (text) and returns the line of the next value, 0 in binary.
  std::size_t start_item()
  {
    if(format_ != 0)
      return 0;
    for(int c = in_.peek(); c != EOF && std::isspace(c); c = in_.peek())
      if(in_.get() == '\n')
        ++line_;
    return line_;
  }

  /// Reads a value of type `type`; in text, the whole white-space separated
  /// word must be a number. Returns false if it cannot.
  bool read(Ply_type type, double& value)
  {
    if(format_ != 0)
      return read_binary(type, value);
    start_item();
    std::string token;
    for(int c = in_.peek(); c != EOF && !std::isspace(c); c = in_.peek())
      token += static_cast<char>(in_.get());
    return parse_number(token, value);
  }

  /// Reads a value of type `type` as CGAL's PLY reader reads it: in text,
  /// with `operator>>` into that type (8-bit values through 16-bit ones),
  /// which stops at the first character that does not fit. Lines are not
  /// counted.
  bool read_like_cgal(Ply_type type, double& value)
  {
    if(format_ != 0)
      return read_binary(type, value);
    switch(type) {
      case Ply_type::int8: { short v; if(!(in_ >> v)) return false; value = static_cast<signed char>(v); return true; }
      case Ply_type::uint8: { unsigned short v; if(!(in_ >> v)) return false; value = static_cast<unsigned char>(v); return true; }
      case Ply_type::int16: { std::int16_t v; if(!(in_ >> v)) return false; value = v; return true; }
      case Ply_type::uint16: { std::uint16_t v; if(!(in_ >> v)) return false; value = v; return true; }
      case Ply_type::int32: { std::int32_t v; if(!(in_ >> v)) return false; value = v; return true; }
      case Ply_type::uint32: { std::uint32_t v; if(!(in_ >> v)) return false; value = v; return true; }
      default: { double v; if(!(in_ >> CGAL::IO::iformat(v))) return false; value = v; return true; }
    }
  }

private:
  bool read_binary(Ply_type type, double& value)
  {
    unsigned char b[8];
    const std::size_t n = ply_size(type);
    if(!in_.read(reinterpret_cast<char*>(b), static_cast<std::streamsize>(n)))
      return false;
    if(swap_)
      std::reverse(b, b + n);
    switch(type) {
      case Ply_type::int8: value = as<std::int8_t>(b); break;
      case Ply_type::uint8: value = b[0]; break;
      case Ply_type::int16: value = as<std::int16_t>(b); break;
      case Ply_type::uint16: value = as<std::uint16_t>(b); break;
      case Ply_type::int32: value = as<std::int32_t>(b); break;
      case Ply_type::uint32: value = as<std::uint32_t>(b); break;
      case Ply_type::float32: value = as<float>(b); break;
      case Ply_type::float64: value = as<double>(b); break;
    }
    return true;
  }

  template <class T> static double as(const unsigned char* b)
  {
    T t;
    std::memcpy(&t, b, sizeof(T));
    return static_cast<double>(t);
  }

  std::istream& in_;
  int format_; // 0 text, 1 little-endian, 2 big-endian
  std::size_t line_;
  bool swap_;
};

/// Checks a PLY file for what CGAL's PLY reader (CGAL 5.5) does not survive,
/// before it reads the file: a property line before any element line (CGAL
/// takes the last element of an empty list); an element count larger than
/// the file (an element without properties is "read" that many times); a
/// vertex coordinate or colour, or a halfedge index, of another type than
/// the one CGAL reads it as (a failed assertion, then a null pointer); a list
/// longer than the file, or whose length cannot be read (CGAL allocates the
/// list before reading it, with an uninitialised length if the read failed).
/// The header is read as CGAL reads it (`Ply_header_rules::cgal`); the data
/// only if a list length is 32-bit (an 8- or 16-bit length cannot ask for
/// much), with CGAL's reads.
inline Text_mesh_scan scan_ply(const std::string& path, std::uintmax_t file_size)
{
  Text_mesh_scan scan;
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid PLY file (" + what + ")";
    return scan;
  };
  std::ifstream in(path, std::ios::binary);
  Ply_header header;
  std::size_t error_line = 0;
  const std::string problem = read_ply_header(in, file_size, Ply_header_rules::cgal, header, error_line);
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

  // List lengths, read as CGAL reads them.
  auto long_list = [](const Ply_property& p) { return p.list && ply_size(p.count_type) == 4; };
  bool long_lists = false;
  for(const Ply_element& e : elements)
    for(const Ply_property& p : e.properties)
      long_lists = long_lists || long_list(p);
  if(!long_lists)
    return scan;
  Ply_value_reader reader(in, header.format, header.lines + 1);
  for(std::size_t k = 0; k < elements.size(); ++k) {
    const Ply_element& e = elements[k];
    // CGAL stops at a value it cannot read, except in a face element: it
    // ignores what reading the faces returned and reads the next elements
    // from the failed stream, where a list length is never written before it
    // is allocated (found by fuzzing: 7 GB).
    const bool faces_then_lists =
        (e.name == "face" || e.name == "faces") &&
        std::any_of(elements.begin() + static_cast<std::ptrdiff_t>(k) + 1, elements.end(), [&](const Ply_element& later) {
          return std::any_of(later.properties.begin(), later.properties.end(), long_list);
        });
    auto cut_short_before_lists = [&](std::size_t j, const Ply_property& p) {
      return fail(0, "item " + std::to_string(j) + " of element \"" + e.name + "\" ends before its property \"" + p.name +
                         "\" can be read, and a later element has lists");
    };
    for(std::size_t j = 0; j < e.count; ++j)
      for(const Ply_property& p : e.properties) {
        double value;
        const bool ok = reader.read_like_cgal(p.list ? p.count_type : p.type, value);
        if(!ok && faces_then_lists) return cut_short_before_lists(j, p);
        if(!ok && !p.list)
          return scan; // CGAL stops here too, and reports the file as not valid
        if(!ok) // CGAL would allocate a list of the unread (uninitialised) length first
          return fail(0, "the length of list \"" + p.name + "\" of item " + std::to_string(j) + " of element \"" +
                             e.name + "\" cannot be read");
        if(!p.list)
          continue;
        // At least one byte per value in binary, two (a digit and a space) in text.
        if(value < 0 || value * static_cast<double>(header.format == 0 ? 2 : ply_size(p.type)) >
                            static_cast<double>(file_size + 1))
          return fail(0, "item " + std::to_string(j) + " of element \"" + e.name + "\" has a list \"" + p.name +
                             "\" of " + std::to_string(static_cast<long long>(value)) + " values, " +
                             (value < 0 ? "a negative length" : "more than the file can hold"));
        for(std::size_t i = 0, n = static_cast<std::size_t>(value); i < n; ++i)
          if(!reader.read_like_cgal(p.type, value)) return faces_then_lists ? cut_short_before_lists(j, p) : scan;
      }
  }
  return scan;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_PLY_SCANNER_H
