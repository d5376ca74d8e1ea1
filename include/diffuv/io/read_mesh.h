// diffuv: reading a triangle mesh whose vertex numbering is the file's.
//
// Everything downstream of the reader refers to vertices by index: corner
// and source selections, label files, correspondences between two meshes.
// Those indices are the file's, so the reader must give vertex i of the mesh
// the i-th point of the file. `CGAL::IO::read_polygon_mesh` does not promise
// that: when the soup is not a valid mesh it repairs and reorients it, merging
// or duplicating points. This reader instead reads the polygon soup, rejects
// anything that would need a repair with a message naming the file, the line
// and the element, and only then builds the mesh.
//
// Elements are numbered from 0 in file order in every message, as in the
// mesh (vertex 0 is the first vertex of the file); only a vertex index that
// is out of range is quoted as written in the file (from 1 in OBJ).
#ifndef DIFFUV_IO_READ_MESH_H
#define DIFFUV_IO_READ_MESH_H

#include <diffuv/core/error.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/exceptions.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/property_map/vector_property_map.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <istream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace diffuv {

/// What `read_triangle_mesh()` read and what it changed.
struct Mesh_read_report {
  std::size_t vertices = 0;              ///< points of the file = vertices of the mesh, in the same order
  std::size_t faces_in_file = 0;         ///< polygons of the file
  std::size_t polygons_triangulated = 0; ///< polygons of more than three vertices split into triangles
  std::size_t faces = 0;                 ///< triangles of the mesh
  std::size_t degenerate_faces = 0;      ///< triangles of zero area (collinear or coinciding corners)
  std::size_t isolated_vertices = 0;     ///< points used by no face, kept so that indices stay those of the file
  /// The polygon of the file each face comes from: `faces` entries, one per
  /// face of the mesh in the order of `faces(mesh)`. The triangles cut from a
  /// polygon all map to it, so per-polygon data of the file (labels, colours)
  /// can be carried to the triangles.
  std::vector<std::size_t> file_face;
};

namespace internal {

enum class Mesh_format { off, obj, ply, stl };

inline const char* format_name(Mesh_format format)
{
  switch(format) {
    case Mesh_format::off: return "OFF";
    case Mesh_format::obj: return "OBJ";
    case Mesh_format::ply: return "PLY";
    case Mesh_format::stl: return "STL";
  }
  return "mesh"; // unreachable for valid enum values
}

/// The format named by the extension of `path`, case-insensitively.
inline Mesh_format mesh_format(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if(ext == ".off") return Mesh_format::off;
  if(ext == ".obj") return Mesh_format::obj;
  if(ext == ".ply") return Mesh_format::ply;
  if(ext == ".stl") return Mesh_format::stl;
  if(ext.empty())
    throw Input_error(path, 0, "the file name has no extension (expected .off, .obj, .ply or .stl)");
  throw Input_error(path, 0, "unknown mesh file extension \"" + std::filesystem::path(path).extension().string() +
                             "\" (expected .off, .obj, .ply or .stl)");
}

/// An index as the file wrote it: PLY's signed indices come back from CGAL
/// as huge unsigned ones.
inline std::string index_text(std::size_t index)
{
  if(index > static_cast<std::size_t>(std::numeric_limits<long long>::max()))
    return std::to_string(static_cast<long long>(index));
  return std::to_string(index);
}

inline std::string out_of_range_message(std::size_t face, const std::string& index, std::size_t nb_vertices)
{
  return "face " + std::to_string(face) + " has vertex index " + index + ", out of range (the file has " +
         std::to_string(nb_vertices) + " vertices)";
}

inline std::string non_finite_message(std::size_t vertex)
{
  return "vertex " + std::to_string(vertex) + " has a coordinate that is NaN or infinite";
}

/// True if the whole of `token` is a number in C syntax that is not finite
/// ("nan", "inf", "1e999"): `operator>>` refuses those, so CGAL's readers
/// report a syntax error where the user needs to hear about the value.
inline bool is_non_finite_number(const std::string& token)
{
  if(token.empty())
    return false;
  char* end = nullptr;
  const double d = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !std::isfinite(d);
}

/// The numbers at the start of `line` (up to a `#` comment), read with
/// `operator>>` as CGAL's OFF scanner reads them; `stop` is the first
/// whitespace-separated token that was not read, if any (`operator>>`
/// consumes "1e999" before failing, so the token is not taken from the stream).
inline std::vector<double> leading_numbers(std::string line, std::string& stop)
{
  const std::size_t hash = line.find('#');
  if(hash != std::string::npos)
    line.erase(hash);
  std::istringstream in(line);
  std::vector<double> numbers;
  double d;
  while(in >> d)
    numbers.push_back(d);
  std::istringstream tokens(line);
  stop.clear();
  for(std::size_t k = 0; k <= numbers.size() && tokens >> stop; ++k) {}
  if(!tokens)
    stop.clear();
  return numbers;
}

/// Where the vertices and faces of a text mesh file are, and the first
/// problem met when reading it the way CGAL reads it. CGAL's readers answer
/// only true or false; this second, line-counting pass turns a `false` into
/// a line and a reason, and gives the line of an element named in a later
/// check. Lines count from 1; 0 means unknown.
struct Text_mesh_scan {
  std::vector<std::size_t> vertex_line;
  std::vector<std::size_t> face_line;
  std::size_t error_line = 0;
  std::string error; ///< empty if no problem was found
};

/// An input stream that counts lines.
class Line_counting_reader {
public:
  explicit Line_counting_reader(std::istream& in) : in_(in) {}

  std::size_t line() const { return line_; }

  int peek() { return in_.peek(); }

  int get()
  {
    const int c = in_.get();
    if(c == '\n')
      ++line_;
    return c;
  }

  /// Skips white space and `#` comments, as CGAL's `skip_comment_OFF`.
  /// Returns false at the end of the input.
  bool skip_space_and_comments()
  {
    for(;;) {
      const int c = peek();
      if(c == std::char_traits<char>::eof())
        return false;
      if(c == '#')
        rest_of_line();
      else if(std::isspace(c))
        get();
      else
        return true;
    }
  }

  /// The characters up to white space or `#`.
  std::string token()
  {
    std::string t;
    for(int c = peek(); c != std::char_traits<char>::eof() && c != '#' && !std::isspace(c); c = peek())
      t += static_cast<char>(get());
    return t;
  }

  /// The characters up to the end of the line, which is consumed.
  std::string rest_of_line()
  {
    std::string s;
    if(std::getline(in_, s) && !in_.eof())
      ++line_; // the end of line was read
    return s;
  }

private:
  std::istream& in_;
  std::size_t line_ = 1;
};

inline bool parse_count(const std::string& token, long long& value)
{
  const char* first = token.data();
  const char* last = first + token.size();
  const auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last;
}

/// `value` as written in messages.
inline std::string number_text_of(double value)
{
  std::ostringstream text;
  text << std::setprecision(15) << value;
  return text.str();
}

/// The numbers of an OFF line as CGAL's `File_scanner_OFF` reads them: up to
/// a `#` comment, with `CGAL::IO::iformat()` (whose syntax differs from
/// `operator>>`: "1e999" is infinite, "1-2" is one number).
inline std::vector<double> cgal_off_numbers(std::string line)
{
  const std::size_t hash = line.find('#');
  if(hash != std::string::npos)
    line.erase(hash);
  std::istringstream in(line);
  std::vector<double> numbers;
  double d;
  while(in >> CGAL::IO::iformat(d))
    numbers.push_back(d);
  return numbers;
}

/// The numbers of an OFF line made of plain decimal numbers only (up to a `#`
/// comment), on which `leading_numbers()` and `cgal_off_numbers()` agree,
/// without their string streams; false if the line has anything else.
inline bool plain_numbers(const std::string& line, std::vector<double>& numbers)
{
  numbers.clear();
  const char* p = line.c_str();
  const char* const end = p + line.size();
  for(;;) {
    while(p < end && std::isspace(static_cast<unsigned char>(*p)))
      ++p;
    if(p == end || *p == '#')
      return true;
    const char* const start = p;
    for(; p < end && !std::isspace(static_cast<unsigned char>(*p)); ++p)
      if(!std::isdigit(static_cast<unsigned char>(*p)) && *p != '.' && *p != '-' && *p != '+' && *p != 'e' && *p != 'E')
        return false;
    char* stop = nullptr;
    const double d = std::strtod(start, &stop);
    if(stop != p || !std::isfinite(d))
      return false;
    numbers.push_back(d);
  }
}

/// True if CGAL's OFF header reader can double `edges` (an int) without overflow.
inline bool edge_count_fits(long long edges)
{
  return edges >= std::numeric_limits<int>::min() / 2 && edges <= std::numeric_limits<int>::max() / 2;
}

/// Scans an OFF file like CGAL's `File_scanner_OFF`: header, then one vertex
/// per line, then one face per line. With `header_only`, stops after the
/// header, whose counts are checked against the size of the file: CGAL
/// resizes its arrays to the announced counts before reading them, so a
/// corrupt header would otherwise allocate gigabytes.
/// Binary OFF has no lines: its data is only walked for what CGAL trusts.
inline Text_mesh_scan scan_off(const std::string& path, std::uintmax_t file_size, bool header_only)
{
  Text_mesh_scan scan;
  std::ifstream file(path, std::ios::binary);
  Line_counting_reader in(file);
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid OFF file (" + what + ")";
    return scan;
  };

  if(!in.skip_space_and_comments())
    return fail(0, "the file has no OFF header");
  const std::size_t header_line = in.line();
  const std::string keyword = in.token();
  // [ST][C][N][4][n]OFF, as CGAL accepts it
  std::size_t k = 0;
  const bool texture = keyword.compare(k, 2, "ST") == 0;
  if(texture) k += 2;
  const bool colors = k < keyword.size() && keyword[k] == 'C';
  if(colors) ++k;
  const bool normals = k < keyword.size() && keyword[k] == 'N';
  if(normals) ++k;
  const bool homogeneous = k < keyword.size() && keyword[k] == '4';
  if(homogeneous) ++k;
  const bool n_dimensional = k < keyword.size() && keyword[k] == 'n';
  if(n_dimensional) ++k;
  if(keyword.substr(k) != "OFF")
    return fail(header_line, "the file does not start with an OFF header");

  long long nv = 0, nf = 0, ne = 0;
  in.skip_space_and_comments();
  std::size_t counts_line = in.line();
  std::string token = in.token();
  if(token == "BINARY") {
    // Three big-endian 32-bit counts after the end of the line (after the
    // dimension for nOFF, which CGAL's reader does not use: it reads three
    // coordinates per vertex whatever the dimension).
    in.rest_of_line();
    unsigned char bytes[12];
    if(n_dimensional && !file.read(reinterpret_cast<char*>(bytes), 4))
      return fail(counts_line, "cannot read the dimension");
    if(!file.read(reinterpret_cast<char*>(bytes), 12))
      return fail(counts_line, "cannot read the numbers of vertices, faces and edges");
    auto read32 = [&](int i) {
      const std::uint32_t u = (std::uint32_t(bytes[4 * i]) << 24) | (std::uint32_t(bytes[4 * i + 1]) << 16) |
                              (std::uint32_t(bytes[4 * i + 2]) << 8) | std::uint32_t(bytes[4 * i + 3]);
      return static_cast<long long>(static_cast<std::int32_t>(u));
    };
    nv = read32(0);
    nf = read32(1);
    ne = read32(2);
    if(nv < 0 || nf < 0)
      return fail(counts_line, "negative number of vertices or faces");
    if(!edge_count_fits(ne))
      return fail(counts_line, "the number of edges " + std::to_string(ne) + " is out of range");
    // At least three 4-byte floats per vertex, one 4-byte count per face.
    if(static_cast<std::uintmax_t>(nv) * 12 + static_cast<std::uintmax_t>(nf) * 4 > file_size)
      return fail(counts_line, "the header announces " + std::to_string(nv) + " vertices and " +
                                   std::to_string(nf) + " faces, more than the " + std::to_string(file_size) +
                                   " bytes of the file can hold");
    if(header_only)
      return scan;
    // Binary data has no lines to find; walk it as CGAL reads it for the
    // face sizes, which CGAL allocates before reading the indices.
    const std::size_t h = homogeneous ? 1 : 0;
    const std::streamsize floats = static_cast<std::streamsize>(3 + h + (normals ? 3 + h : 0) + (texture ? 2 + h : 0));
    auto next32 = [&](std::int32_t& value) {
      if(!file.read(reinterpret_cast<char*>(bytes), 4))
        return false;
      value = static_cast<std::int32_t>(read32(0));
      return true;
    };
    // CGAL's read_OFF() reads no colour in binary files (nor their counts).
    if(!file.ignore(4 * floats * static_cast<std::streamsize>(nv)) || file.gcount() != 4 * floats * nv)
      return scan; // CGAL stops in the vertices too
    std::int32_t count = 0;
    for(long long j = 0; j < nf; ++j) {
      if(!next32(count)) // CGAL would allocate the face with the unread (uninitialised) size
        return fail(0, "the file ends before face " + std::to_string(j) + " of " + std::to_string(nf));
      if(count < 0 || static_cast<std::uintmax_t>(count) * 4 > file_size)
        return fail(0, "face " + std::to_string(j) + " has " + std::to_string(count) + " vertices, " +
                           (count < 0 ? "a negative number" : "more than the file can hold"));
      if(!file.ignore(4 * static_cast<std::streamsize>(count)))
        return scan;
    }
    return scan;
  }

  if(n_dimensional) { // the dimension, then the counts
    long long dimension = 0;
    if(!parse_count(token, dimension))
      return fail(counts_line, "cannot read the dimension");
    in.skip_space_and_comments();
    counts_line = in.line();
    token = in.token();
  }
  if(!parse_count(token, nv))
    return fail(counts_line, "cannot read the numbers of vertices, faces and edges");
  in.skip_space_and_comments();
  counts_line = in.line();
  if(!parse_count(in.token(), nf))
    return fail(counts_line, "cannot read the numbers of vertices, faces and edges");
  in.skip_space_and_comments();
  counts_line = in.line();
  if(!parse_count(in.token(), ne))
    return fail(counts_line, "cannot read the numbers of vertices, faces and edges");
  if(nv < 0 || nf < 0)
    return fail(counts_line, "negative number of vertices or faces");
  if(!edge_count_fits(ne))
    return fail(counts_line, "the number of edges " + std::to_string(ne) + " is out of range");
  // Each vertex line holds at least "x y z" and an end of line, each face
  // line at least its size and an end of line; the last line may have no end.
  const std::uintmax_t needed = static_cast<std::uintmax_t>(nv) * 6 + static_cast<std::uintmax_t>(nf) * 2;
  if(needed > file_size + 1)
    return fail(counts_line, "the header announces " + std::to_string(nv) + " vertices and " +
                                 std::to_string(nf) + " faces, more than the " + std::to_string(file_size) +
                                 " bytes of the file can hold");
  if(header_only)
    return scan;

  // What CGAL's File_scanner_OFF (CGAL 5.5) takes on trust, checked on the
  // numbers as it reads them (cgal_off_numbers()): a vertex line long enough
  // for its normal, texture coordinates and colour; colours of 1 (an index in
  // CGAL's colour map), 3 or 4 components in range, on every vertex (face)
  // after a coloured one; face sizes and indices it can convert. Else it
  // reads past the end of its vector or converts out-of-range values. It
  // reads texture coordinates at an uninitialised position unless the
  // vertices are coloured too (STCOFF).
  if(texture && !colors)
    return fail(header_line, "texture coordinates without colours (STOFF) cannot be read");
  const std::size_t h = homogeneous ? 1 : 0;
  const std::size_t vertex_numbers = 3 + h + (normals ? 3 + h : 0) + (texture ? 2 + h : 0);
  // The `n` colour components at `first` in `entries` (before texture
  // coordinates, as Geomview writes them); "" if they are fine.
  auto color_problem = [](const std::vector<double>& entries, std::size_t first, std::size_t n,
                          bool& colored) -> std::string {
    colored = colored || n > 0;
    if(!colored)
      return std::string();
    if(n == 0)
      return "has no colour, but an earlier one has";
    if(n != 1 && n != 3 && n != 4)
      return "has " + std::to_string(n) + " colour components; expected 3 or 4";
    if(n == 1)
      return entries[first] >= 0 && entries[first] < 149
               ? std::string()
               : "has colour-map index " + number_text_of(entries[first]) + ", outside [0, 148]";
    bool integers = true;
    for(std::size_t c = first; c < first + 3; ++c)
      integers = integers && std::floor(entries[c]) == entries[c];
    for(std::size_t c = first; c < first + 3; ++c)
      if(!(entries[c] >= 0 && entries[c] <= (integers ? 255 : 1)))
        return "has colour component " + number_text_of(entries[c]) + ", outside " +
               (integers ? "[0, 255] (integers)" : "[0, 1]");
    return std::string();
  };
  bool vertex_colored = false, face_colored = false;

  const std::size_t needed_coordinates = homogeneous ? 4 : 3;
  std::string stop;
  std::vector<double> numbers, entries;
  // The numbers of `text` read as the messages below describe them
  // (operator>>), and as CGAL reads them.
  auto read_numbers = [&](const std::string& text) {
    if(plain_numbers(text, numbers)) {
      entries = numbers;
      stop.clear();
    } else {
      numbers = leading_numbers(text, stop);
      entries = cgal_off_numbers(text);
    }
  };
  for(long long i = 0; i < nv; ++i) {
    if(!in.skip_space_and_comments())
      return fail(0, "the file ends before vertex " + std::to_string(i) + " of " + std::to_string(nv));
    const std::size_t line = in.line();
    scan.vertex_line.push_back(line);
    const std::string text = in.rest_of_line();
    read_numbers(text);
    if(numbers.size() < needed_coordinates) {
      if(is_non_finite_number(stop)) {
        scan.error_line = line;
        scan.error = non_finite_message(static_cast<std::size_t>(i));
        return scan;
      }
      return fail(line, "vertex " + std::to_string(i) + " does not have " + std::to_string(needed_coordinates) +
                            " coordinates");
    }
    if(entries.size() < needed_coordinates)
      return fail(line, "vertex " + std::to_string(i) + " does not have " + std::to_string(needed_coordinates) +
                            " coordinates");
    if(homogeneous && entries[3] == 0) { // a point at infinity
      scan.error_line = line;
      scan.error = non_finite_message(static_cast<std::size_t>(i));
      return scan;
    }
    if(entries.size() < vertex_numbers && (colors || normals))
      return fail(line, "vertex " + std::to_string(i) + " has " + std::to_string(entries.size()) + " numbers; " +
                            keyword + " needs " + std::to_string(vertex_numbers));
    if(colors) {
      const std::string problem = color_problem(entries, vertex_numbers - (texture ? 2 + h : 0),
                                                entries.size() - vertex_numbers, vertex_colored);
      if(!problem.empty())
        return fail(line, "vertex " + std::to_string(i) + " " + problem);
    }
  }

  for(long long j = 0; j < nf; ++j) {
    if(!in.skip_space_and_comments())
      return fail(0, "the file ends before face " + std::to_string(j) + " of " + std::to_string(nf));
    const std::size_t line = in.line();
    scan.face_line.push_back(line);
    const std::string text = in.rest_of_line();
    read_numbers(text);
    if(numbers.empty() || numbers[0] < 0 || numbers[0] != std::floor(numbers[0]))
      return fail(line, "face " + std::to_string(j) + " does not start with its number of vertices");
    if(static_cast<double>(numbers.size()) <= numbers[0])
      return fail(line, "face " + std::to_string(j) + " lists fewer than its " + number_text_of(numbers[0]) +
                            " vertex indices");
    const std::size_t size = static_cast<std::size_t>(numbers[0]);
    for(std::size_t c = 1; c <= size; ++c) {
      const double index = numbers[c];
      if(index < 0 || index >= static_cast<double>(nv) || index != std::floor(index)) {
        scan.error_line = line;
        scan.error = out_of_range_message(static_cast<std::size_t>(j), number_text_of(index),
                                          static_cast<std::size_t>(nv));
        return scan;
      }
    }
    if(entries.empty() || !(entries[0] >= 0) || static_cast<double>(entries.size()) <= entries[0])
      return fail(line, "face " + std::to_string(j) + " does not start with its number of vertices, then as many indices");
    const std::size_t cgal_size = static_cast<std::size_t>(entries[0]);
    for(std::size_t c = 1; c <= cgal_size; ++c)
      if(!(entries[c] >= 0 && entries[c] < static_cast<double>(nv))) {
        scan.error_line = line;
        scan.error = out_of_range_message(static_cast<std::size_t>(j), number_text_of(entries[c]),
                                          static_cast<std::size_t>(nv));
        return scan;
      }
    if(colors) {
      const std::string problem = color_problem(entries, cgal_size + 1, entries.size() - cgal_size - 1, face_colored);
      if(!problem.empty())
        return fail(line, "face " + std::to_string(j) + " " + problem);
    }
  }
  return scan;
}

/// Scans an OBJ file line by line like CGAL's OBJ reader.
inline Text_mesh_scan scan_obj(const std::string& path)
{
  Text_mesh_scan scan;
  std::ifstream file(path);
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid OBJ file (" + what + ")";
    return scan;
  };

  // The keywords CGAL's reader skips without an error.
  static const char* const ignored[] = {
    "vt", "vn", "vp", "bevel", "lod", "ctech", "c_interp", "usemap", "usemtl", "stech", "d_interp", "mtllib",
    "shadow_obj", "trace_obj", "o", "g", "s", "p", "cstype", "deg", "step", "bmat", "con", "curv", "curv2",
    "surf", "parm", "trim", "hole", "scrv", "sp", "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2",
    "q0_2", "q1_2", "curv2d_2", "bsp", "bzp", "cdc", "cdp", "res"};

  struct Written_face { std::size_t line, vertices_before; std::vector<int> indices; };
  std::vector<Written_face> written;

  std::string line;
  std::size_t number = 0;
  while(std::getline(file, line)) {
    ++number;
    std::istringstream in(line);
    std::string keyword;
    if(!(in >> keyword))
      continue;
    if(keyword == "v") {
      scan.vertex_line.push_back(number);
      double x, y, z;
      if(!(in >> x >> y >> z)) {
        std::string stop;
        leading_numbers(line.substr(line.find('v') + 1), stop);
        if(is_non_finite_number(stop)) {
          scan.error_line = number;
          scan.error = non_finite_message(scan.vertex_line.size() - 1);
          return scan;
        }
        return fail(number, "cannot read the coordinates of vertex " + std::to_string(scan.vertex_line.size() - 1));
      }
    } else if(keyword == "f") {
      scan.face_line.push_back(number);
      Written_face face{number, scan.vertex_line.size(), {}};
      int i;
      while(in >> i) {
        face.indices.push_back(i);
        in.ignore(256, ' '); // "v/vt/vn": CGAL keeps v and skips to the next space
      }
      written.push_back(std::move(face));
    } else if(keyword.front() == '#' ||
              std::find(std::begin(ignored), std::end(ignored), keyword) != std::end(ignored)) {
      continue;
    } else {
      return fail(number, "unknown keyword \"" + keyword + "\"");
    }
  }

  // Positive indices count from 1, negative ones back from the last vertex
  // read so far.
  const long long nv = static_cast<long long>(scan.vertex_line.size());
  for(std::size_t j = 0; j < written.size(); ++j) {
    for(int i : written[j].indices) {
      const long long resolved = i < 1 ? static_cast<long long>(written[j].vertices_before) + i : i - 1LL;
      if(resolved < 0 || resolved >= nv) {
        scan.error_line = written[j].line;
        scan.error = out_of_range_message(j, std::to_string(i), scan.vertex_line.size());
        return scan;
      }
    }
  }
  if(written.empty()) {
    scan.error = "the file has no face";
    return scan;
  }
  return scan;
}

/// Checks a PLY file for what CGAL's PLY reader (CGAL 5.5) does not survive,
/// before it reads the file: a property line before any element line (CGAL
/// takes the last element of an empty list); an element count larger than
/// the file (an element without properties is "read" that many times); a
/// vertex coordinate or colour, or a halfedge index, of another type than
/// the one CGAL reads it as (a failed assertion, then a null pointer); a list
/// longer than the file, or whose length cannot be read (CGAL allocates the
/// list before reading it, with an uninitialised length if the read failed).
/// The header is read as CGAL reads it (line 1 "ply", line 2 the format,
/// properties of unknown type skipped); the data only if a list length is
/// 32-bit (an 8- or 16-bit length cannot ask for much), with CGAL's reads.
inline Text_mesh_scan scan_ply(const std::string& path, std::uintmax_t file_size)
{
  Text_mesh_scan scan;
  auto fail = [&](std::size_t line, const std::string& what) {
    scan.error_line = line;
    scan.error = "not a valid PLY file (" + what + ")";
    return scan;
  };
  // CGAL's types: int8, uint8, int16, uint16, int32, uint32, float32, float64.
  static const char* const names[16] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                        "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  auto type_of = [](const std::string& name) {
    const auto it = std::find(std::begin(names), std::end(names), name);
    return it == std::end(names) ? -1 : static_cast<int>((it - std::begin(names)) % 8);
  };
  enum { uint8 = 1, uint32 = 5, float32 = 6, float64 = 7 };
  struct Property { std::string name; int type; int size_type; }; // size_type -1: not a list
  struct Element { std::string name; std::size_t count; std::size_t line; std::vector<Property> properties; };

  std::ifstream in(path, std::ios::binary);
  std::vector<Element> elements;
  int format = 0; // 0 text, 1 little-endian, 2 big-endian
  std::string text;
  for(std::size_t number = 1; std::getline(in, text); ++number) {
    std::istringstream words(text);
    std::string keyword, a, b, c, d;
    if(number == 1) {
      if(!(words >> keyword) || keyword != "ply")
        return fail(1, "the file does not start with \"ply\"");
    } else if(number == 2) {
      if(!(words >> keyword >> a >> b))
        return fail(2, "the second line is not a format line");
      format = a == "ascii" ? 0 : a == "binary_little_endian" ? 1 : a == "binary_big_endian" ? 2 : -1;
      if(format < 0)
        return fail(2, "unknown format \"" + a + "\"");
    } else if(!(words >> keyword)) {
      return fail(number, "empty header line");
    } else if(keyword == "property") {
      if(!(words >> a >> b) || (a == "list" && !(words >> c >> d)))
        return fail(number, "cannot read the property line");
      // "property TYPE NAME" or "property list SIZE_TYPE TYPE NAME"
      const Property p = a == "list" ? Property{d, type_of(c), type_of(b)} : Property{b, type_of(a), -1};
      if(elements.empty())
        return fail(number, "a property line comes before any element line");
      // CGAL skips a property of unknown type (and a list with a float length); so does the walk below.
      if(p.type >= 0 && (a != "list" || (p.size_type >= 0 && p.size_type <= uint32)))
        elements.back().properties.push_back(p);
    } else if(keyword == "element") {
      std::size_t count = 0;
      if(!(words >> a >> count))
        return fail(number, "cannot read the element line");
      if(count > file_size)
        return fail(number, "the header announces " + std::to_string(count) + " " + a + " items, more than the " +
                                std::to_string(file_size) + " bytes of the file can hold");
      elements.push_back({a, count, number, {}});
    } else if(keyword == "end_header") {
      break;
    }
  }

  // The types CGAL asserts: the first property of each name it reads.
  for(const Element& e : elements) {
    auto find = [&](const char* name) -> const Property* {
      for(const Property& p : e.properties)
        if(p.name == name) return &p;
      return nullptr;
    };
    auto is = [&](const char* name, int type) {
      const Property* p = find(name);
      return p && p->size_type < 0 && p->type == type;
    };
    auto require = [&](const char* name, const char* type, bool ok) {
      const Property* p = find(name);
      if(p && !ok)
        fail(e.line, "property \"" + std::string(name) + "\" of element \"" + e.name + "\" is not of type " + type);
      return !p || ok;
    };
    const bool vertex = e.name == "vertex" || e.name == "vertices";
    if(vertex)
      for(const char* xyz : {"x", "y", "z"})
        if(!require(xyz, "float or double", is(xyz, float32) || is(xyz, float64)))
          return scan;
    if(vertex || e.name == "face" || e.name == "faces") {
      const bool red = is("red", uint8);
      if((red || is("r", uint8)) && (is("green", uint8) || is("g", uint8)) && (is("blue", uint8) || is("b", uint8)))
        for(const char* rgb : red ? std::vector<const char*>{"red", "green", "blue"} : std::vector<const char*>{"r", "g", "b"})
          if(!require(rgb, "uchar", is(rgb, uint8)))
            return scan;
    }
    if(e.name == "halfedge" && !(is("source", uint32) && is("target", uint32) && is("u", float32) && is("v", float32)))
      for(const char* end : {"source", "target"})
        if(!require(end, "uint", is(end, uint32)))
          return scan;
  }

  // List lengths, read as CGAL reads them.
  bool long_lists = false;
  for(const Element& e : elements)
    for(const Property& p : e.properties)
      long_lists = long_lists || p.size_type >= 4;
  if(!long_lists)
    return scan;
  static const std::size_t sizes[8] = {1, 1, 2, 2, 4, 4, 4, 8};
  auto read = [&](int type, double& value) -> bool {
    if(format == 0) {
      switch(type) {
        case 0: { short v; if(!(in >> v)) return false; value = static_cast<signed char>(v); return true; }
        case 1: { unsigned short v; if(!(in >> v)) return false; value = static_cast<unsigned char>(v); return true; }
        case 2: { std::int16_t v; if(!(in >> v)) return false; value = v; return true; }
        case 3: { std::uint16_t v; if(!(in >> v)) return false; value = v; return true; }
        case 4: { std::int32_t v; if(!(in >> v)) return false; value = v; return true; }
        case 5: { std::uint32_t v; if(!(in >> v)) return false; value = v; return true; }
        default: { double v; if(!(in >> CGAL::IO::iformat(v))) return false; value = v; return true; }
      }
    }
    unsigned char bytes[8];
    if(!in.read(reinterpret_cast<char*>(bytes), static_cast<std::streamsize>(sizes[type])))
      return false;
    if(format == 2)
      std::reverse(bytes, bytes + sizes[type]);
    auto as = [&](auto t) { std::memcpy(&t, bytes, sizeof(t)); return static_cast<double>(t); };
    switch(type) {
      case 0: value = as(std::int8_t()); break;
      case 1: value = as(std::uint8_t()); break;
      case 2: value = as(std::int16_t()); break;
      case 3: value = as(std::uint16_t()); break;
      case 4: value = as(std::int32_t()); break;
      case 5: value = as(std::uint32_t()); break;
      case 6: value = as(float()); break;
      default: value = as(double()); break;
    }
    return true;
  };
  for(std::size_t k = 0; k < elements.size(); ++k) {
    const Element& e = elements[k];
    // CGAL stops at a value it cannot read, except in a face element: it
    // ignores what reading the faces returned and reads the next elements
    // from the failed stream, where a list length is never written before it
    // is allocated (found by fuzzing: 7 GB).
    const bool faces_then_lists =
        (e.name == "face" || e.name == "faces") &&
        std::any_of(elements.begin() + static_cast<std::ptrdiff_t>(k) + 1, elements.end(), [](const Element& later) {
          return std::any_of(later.properties.begin(), later.properties.end(),
                             [](const Property& p) { return p.size_type >= 4; });
        });
    auto cut_short_before_lists = [&](std::size_t j, const Property& p) {
      return fail(0, "item " + std::to_string(j) + " of element \"" + e.name + "\" ends before its property \"" + p.name +
                         "\" can be read, and a later element has lists");
    };
    for(std::size_t j = 0; j < e.count; ++j)
      for(const Property& p : e.properties) {
        double value;
        const bool ok = read(p.size_type >= 0 ? p.size_type : p.type, value);
        if(!ok && faces_then_lists) return cut_short_before_lists(j, p);
        if(!ok && p.size_type < 0)
          return scan; // CGAL stops here too, and reports the file as not valid
        if(!ok) // CGAL would allocate a list of the unread (uninitialised) length first
          return fail(0, "the length of list \"" + p.name + "\" of item " + std::to_string(j) + " of element \"" +
                             e.name + "\" cannot be read");
        if(p.size_type < 0)
          continue;
        // At least one byte per value in binary, two (a digit and a space) in text.
        if(value < 0 || value * static_cast<double>(format == 0 ? 2 : sizes[p.type]) > static_cast<double>(file_size + 1))
          return fail(0, "item " + std::to_string(j) + " of element \"" + e.name + "\" has a list \"" + p.name +
                             "\" of " + std::to_string(static_cast<long long>(value)) + " values, " +
                             (value < 0 ? "a negative length" : "more than the file can hold"));
        for(std::size_t i = 0, n = static_cast<std::size_t>(value); i < n; ++i)
          if(!read(p.type, value)) return faces_then_lists ? cut_short_before_lists(j, p) : scan;
      }
  }
  return scan;
}

/// The lines of a file's elements, scanned on first use: only error
/// messages need them.
class Line_locator {
public:
  Line_locator(const std::string& path, Mesh_format format, std::uintmax_t file_size)
    : path_(path), format_(format), file_size_(file_size) {}

  const Text_mesh_scan& scan()
  {
    if(!scanned_) {
      if(format_ == Mesh_format::off)
        scan_ = scan_off(path_, file_size_, false);
      else if(format_ == Mesh_format::obj)
        scan_ = scan_obj(path_);
      scanned_ = true;
    }
    return scan_;
  }

  std::size_t vertex_line(std::size_t i)
  {
    const auto& lines = scan().vertex_line;
    return i < lines.size() ? lines[i] : 0;
  }

  std::size_t face_line(std::size_t j)
  {
    const auto& lines = scan().face_line;
    return j < lines.size() ? lines[j] : 0;
  }

private:
  std::string path_;
  Mesh_format format_;
  std::uintmax_t file_size_;
  Text_mesh_scan scan_;
  bool scanned_ = false;
};

/// Names one reason why a soup whose polygons have at least three distinct,
/// valid vertices is not a manifold oriented polygon mesh: CGAL's
/// `is_polygon_soup_a_polygon_mesh()` only answers yes or no. Sets `face` to
/// the face concerned, or to `std::size_t(-1)` if it is about a vertex.
/// Returns an empty string if it finds nothing.
inline std::string describe_non_manifold(const std::vector<std::vector<std::size_t>>& polygons,
                                         std::size_t nb_points, std::size_t& face)
{
  face = std::size_t(-1);
  // An oriented edge used twice: three faces on one edge, or two faces
  // that disagree on the orientation.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_face;
  for(std::size_t j = 0; j < polygons.size(); ++j) {
    const auto& p = polygons[j];
    for(std::size_t c = 0; c < p.size(); ++c) {
      const std::pair<std::size_t, std::size_t> e(p[c], p[(c + 1) % p.size()]);
      const auto [it, inserted] = edge_face.emplace(e, j);
      if(!inserted) {
        face = j;
        return "faces " + std::to_string(it->second) + " and " + std::to_string(j) +
               " both go from vertex " + std::to_string(e.first) + " to vertex " + std::to_string(e.second);
      }
    }
  }

  // Around a vertex v, each face (.., b, v, a, ..) links a to b; neighbouring
  // faces share a link end. With each oriented edge used once, the links form
  // paths and cycles, one per fan of faces: a manifold vertex has one fan.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> links(nb_points);
  for(const auto& p : polygons)
    for(std::size_t c = 0; c < p.size(); ++c)
      links[p[c]].emplace_back(p[(c + 1) % p.size()], p[(c + p.size() - 1) % p.size()]);
  for(std::size_t v = 0; v < nb_points; ++v) {
    auto& link = links[v];
    if(link.size() < 2)
      continue;
    std::sort(link.begin(), link.end());
    std::vector<std::size_t> heads; // link ends that no link leads to: starts of paths
    std::vector<std::size_t> targets;
    for(const auto& l : link)
      targets.push_back(l.second);
    std::sort(targets.begin(), targets.end());
    for(const auto& l : link)
      if(!std::binary_search(targets.begin(), targets.end(), l.first))
        heads.push_back(l.first);
    std::vector<bool> used(link.size(), false);
    auto walk = [&](std::size_t from) {
      for(;;) {
        const auto it = std::lower_bound(link.begin(), link.end(), std::make_pair(from, std::size_t(0)));
        if(it == link.end() || it->first != from || used[it - link.begin()])
          return;
        used[it - link.begin()] = true;
        from = it->second;
      }
    };
    std::size_t fans = 0;
    for(std::size_t h : heads) {
      walk(h);
      ++fans;
    }
    for(std::size_t l = 0; l < link.size(); ++l)
      if(!used[l]) {
        walk(link[l].first); // a cycle
        ++fans;
      }
    if(fans > 1)
      return "the faces around vertex " + std::to_string(v) + " form " + std::to_string(fans) + " separate fans";
  }
  return std::string();
}

/// Gives each triangle cut from a polygon the polygon's number, through
/// `CGAL::Polygon_mesh_processing::triangulate_face()`'s visitor (which is
/// copied, hence the pointers).
template <class TriangleMesh, class PolygonMap>
struct Polygon_provenance_visitor {
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  PolygonMap* polygon_of;
  const std::size_t* polygon;

  void before_subface_creations(face_descriptor) {}
  void after_subface_created(face_descriptor f) { put(*polygon_of, f, *polygon); }
  void after_subface_creations() {}
};

/// True when `CGAL::Polygon_mesh_processing::triangulate_face()` would put
/// two corners of face `f` (more than four corners) on one point of its
/// constrained triangulation: they coincide once projected along the face
/// normal, compared with the same projection traits. CGAL then gives up
/// (returns false), except when the two are the first and the last corner,
/// which breaks a precondition of `Constrained_triangulation_2` (found by
/// fuzzing); so such faces are cut as a fan without asking CGAL.
template <class TriangleMesh>
bool polygon_corners_coincide_in_projection(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                                            const TriangleMesh& mesh)
{
  using Point = typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  const auto points = get(CGAL::vertex_point, mesh);
  const typename Kernel::Vector_3 normal = CGAL::Polygon_mesh_processing::compute_face_normal(f, mesh);
  if(normal == CGAL::NULL_VECTOR)
    return false; // triangulate_face() refuses it first
  const CGAL::Projection_traits_3<Kernel> projection(normal);
  const auto compare_x = projection.compare_x_2_object();
  const auto compare_y = projection.compare_y_2_object();
  std::vector<Point> corners;
  for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
    corners.push_back(get(points, v));
  std::sort(corners.begin(), corners.end(), [&](const Point& a, const Point& b) {
    const CGAL::Comparison_result x = compare_x(a, b);
    return x == CGAL::SMALLER || (x == CGAL::EQUAL && compare_y(a, b) == CGAL::SMALLER);
  });
  for(std::size_t k = 1; k < corners.size(); ++k)
    if(compare_x(corners[k - 1], corners[k]) == CGAL::EQUAL && compare_y(corners[k - 1], corners[k]) == CGAL::EQUAL)
      return true;
  return false;
}

} // namespace internal

/// Reads a polygon mesh file (OFF, OBJ, PLY or STL, by extension, in any
/// case) into a triangle mesh whose vertex i is the i-th point of the file.
///
/// The file is read as a polygon soup with CGAL's readers and checked
/// before the mesh is built: at least one face; finite coordinates; faces of
/// at least three vertex indices, in range and distinct; a manifold,
/// consistently oriented polygon mesh. Nothing is repaired, merged or
/// reoriented, so that indices stay those of the file.
///
/// Then:
/// - points used by no face become isolated vertices (counted in the report;
///   CGAL's `polygon_soup_to_polygon_mesh()` keeps them, in order);
/// - each polygon with more than three vertices is split into triangles
///   with `CGAL::Polygon_mesh_processing::triangulate_face()`, or, when that
///   fails on a degenerate polygon, into a fan from one corner. No vertex is
///   added; the first triangle keeps the polygon's face descriptor and the
///   others are appended at the end of `faces(mesh)`; `file_face` in the
///   report gives the polygon of every face;
/// - zero-area triangles are kept and counted: a caller that cannot use
///   them decides.
///
/// STL has no vertex list: CGAL numbers its distinct points in order of first
/// appearance, merging identical ones.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex
///         point map whose points have `x()`, `y()`, `z()` and a
///         `CGAL::Kernel_traits`; vertices and faces must be listed in insertion
///         order (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`)
/// \param path the file
/// \param mesh receives the mesh; its previous content is removed. After an
///        exception its content is unspecified.
/// \returns the counts of what was read
/// \throws Input_error naming `path`, with the line when it is known (ASCII
///         OFF and OBJ) or 0, and one of these reasons:
///   - "unknown mesh file extension ...", "the file name has no extension ..."
///   - "cannot open file", "the file is empty"
///   - "not a valid OFF file" (or OBJ, PLY, STL), with the problem in
///     parentheses when it is known (OFF and OBJ)
///   - "the file has no face"
///   - "vertex I has a coordinate that is NaN or infinite"
///   - "vertex I has a coordinate of X, too large to compute with (beyond 1e60): rescale the mesh",
///     "the mesh is too small to compute with (it spans X, under 1e-60): rescale the mesh"
///   - "face J has vertex index X, out of range (the file has N vertices)"
///   - "face J has only K vertices", "face J uses vertex I twice"
///   - "non-manifold edge or vertex, or inconsistent orientation (...)", with
///     "; vertices I and K have the same position: the mesh may need welding"
///     when two used points coincide
///   - "face J cannot be triangulated without a second edge between vertices I and K"
///   - "vertex I is non-manifold"
template <class TriangleMesh>
Mesh_read_report read_triangle_mesh(const std::string& path, TriangleMesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  namespace fs = std::filesystem;
  using Vertex_point_map = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type;
  using Point = typename boost::property_traits<Vertex_point_map>::value_type;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Polygon = std::vector<std::size_t>;

  std::error_code dir_ec;
  if(fs::is_directory(path, dir_ec))
    throw Input_error(path, 0, "is a directory, not a mesh file");
  const internal::Mesh_format format = internal::mesh_format(path);
  const std::string name = internal::format_name(format);

  std::error_code ec;
  if(fs::is_directory(path, ec) || !std::ifstream(path, std::ios::binary))
    throw Input_error(path, 0, "cannot open file");
  const std::uintmax_t file_size = fs::file_size(path, ec);
  if(ec)
    throw Input_error(path, 0, "cannot open file");
  if(file_size == 0)
    throw Input_error(path, 0, "the file is empty");

  internal::Line_locator locate(path, format, file_size);
  if(format == internal::Mesh_format::off) {
    // The whole file, not only the header: CGAL's OFF reader trusts what the
    // scan checks (see scan_off()). The scan is kept for the lines of later errors.
    const internal::Text_mesh_scan& scan = locate.scan();
    if(!scan.error.empty())
      throw Input_error(path, scan.error_line, scan.error);
  }
  if(format == internal::Mesh_format::ply) {
    const internal::Text_mesh_scan checked = internal::scan_ply(path, file_size);
    if(!checked.error.empty())
      throw Input_error(path, checked.error_line, checked.error);
  }

  // CGAL's stream readers of OFF and PLY print to std::cerr unless told not to.
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  bool read = false;
  try {
    const auto np = CGAL::parameters::verbose(false);
    switch(format) {
      case internal::Mesh_format::off: read = CGAL::IO::read_OFF(path, points, polygons, np); break;
      case internal::Mesh_format::obj: read = CGAL::IO::read_OBJ(path, points, polygons, np); break;
      case internal::Mesh_format::ply: read = CGAL::IO::read_PLY(path, points, polygons, np); break;
      case internal::Mesh_format::stl: read = CGAL::IO::read_STL(path, points, polygons, np); break;
    }
  } catch(const std::exception& e) {
    throw Input_error(path, 0, "not a valid " + name + " file (" + e.what() + ")");
  }
  if(!read) {
    const internal::Text_mesh_scan& scan = locate.scan();
    if(!scan.error.empty())
      throw Input_error(path, scan.error_line, scan.error);
    throw Input_error(path, 0, "not a valid " + name + " file");
  }

  // The soup, checked in file order so that the first problem is reported.
  if(polygons.empty())
    throw Input_error(path, 0, "the file has no face");
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      throw Input_error(path, locate.vertex_line(i), internal::non_finite_message(i));
  }
  std::vector<bool> used(points.size(), false);
  for(std::size_t j = 0; j < polygons.size(); ++j) {
    const Polygon& polygon = polygons[j];
    if(polygon.size() < 3)
      throw Input_error(path, locate.face_line(j), "face " + std::to_string(j) + " has only " +
                                                      std::to_string(polygon.size()) + " vertices");
    for(std::size_t index : polygon) {
      if(index >= points.size()) {
        // CGAL's OBJ reader lets the index one past the last vertex through;
        // the scan quotes the index as written.
        if(format == internal::Mesh_format::obj && !locate.scan().error.empty())
          throw Input_error(path, locate.scan().error_line, locate.scan().error);
        throw Input_error(path, locate.face_line(j),
                          internal::out_of_range_message(j, internal::index_text(index), points.size()));
      }
    }
    Polygon sorted = polygon;
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if(twice != sorted.end())
      throw Input_error(path, locate.face_line(j), "face " + std::to_string(j) + " uses vertex " +
                                                      std::to_string(*twice) + " twice");
    for(std::size_t index : polygon)
      used[index] = true;
  }
  // Scale: lengths are squared and areas multiplied in double precision, so
  // a mesh far beyond 1e60 or within 1e-60 gives infinities or zeros (every
  // vertex at the centre of the square): refuse it rather than answer wrong.
  {
    constexpr double largest = 1e60, smallest = 1e-60;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for(std::size_t i = 0; i < points.size(); ++i) {
      if(!used[i]) continue;
      const double c[3] = {CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()),
                           CGAL::to_double(points[i].z())};
      for(int k = 0; k < 3; ++k) {
        if(std::abs(c[k]) > largest) {
          std::ostringstream what;
          what << "vertex " << i << " has a coordinate of " << c[k]
               << ", too large to compute with (beyond 1e60): rescale the mesh";
          throw Input_error(path, locate.vertex_line(i), what.str());
        }
        lo[k] = (std::min)(lo[k], c[k]);
        hi[k] = (std::max)(hi[k], c[k]);
      }
    }
    const double extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    if(extent < smallest) {
      std::ostringstream what;
      what << "the mesh is too small to compute with (it spans " << extent << ", under 1e-60): rescale the mesh";
      throw Input_error(path, 0, what.str());
    }
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    std::size_t face = 0;
    const std::string detail = internal::describe_non_manifold(polygons, points.size(), face);
    // Unwelded copies of a point (common in STL exports and scans) are the
    // usual cause: say so, with the first pair.
    std::string hint;
    std::vector<std::size_t> order;
    for(std::size_t i = 0; i < points.size(); ++i)
      if(used[i]) order.push_back(i);
    const auto position = [&](std::size_t i) {
      return std::make_tuple(points[i].x(), points[i].y(), points[i].z());
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return position(a) < position(b); });
    std::size_t first = std::size_t(-1), second = 0;
    for(std::size_t k = 1; k < order.size(); ++k)
      if(position(order[k - 1]) == position(order[k]) && (std::min)(order[k - 1], order[k]) < first) {
        first = (std::min)(order[k - 1], order[k]);
        second = (std::max)(order[k - 1], order[k]);
      }
    if(first != std::size_t(-1))
      hint = "; vertices " + std::to_string(first) + " and " + std::to_string(second) +
             " have the same position: the mesh may need welding";
    throw Input_error(path, face == std::size_t(-1) ? 0 : locate.face_line(face),
                      "non-manifold edge or vertex, or inconsistent orientation" +
                          (detail.empty() ? std::string() : " (" + detail + ")") + hint);
  }

  Mesh_read_report report;
  report.vertices = points.size();
  report.faces_in_file = polygons.size();
  report.isolated_vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));

  // The mesh, and the polygon of each face: triangulating a polygon of more
  // than four vertices removes its face and fills the hole, so the provenance
  // is tracked through face indices (a map that grows with the mesh).
  // An empty mesh without garbage appends vertices and faces in soup order,
  // which is what makes vertex i the file's point i.
  std::vector<vertex_descriptor> vertex_of;
  using Polygon_map = boost::vector_property_map<std::size_t, typename boost::property_map<TriangleMesh, CGAL::face_index_t>::const_type>;
  Polygon_map polygon_of(get(boost::face_index, mesh));
  auto build = [&](bool use_cdt) {
    CGAL::clear(mesh);
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    vertex_of.assign(vertices(mesh).begin(), vertices(mesh).end());
    const std::vector<face_descriptor> face_of(faces(mesh).begin(), faces(mesh).end());
    polygon_of = Polygon_map(get(boost::face_index, mesh));
    for(std::size_t j = 0; j < polygons.size(); ++j)
      put(polygon_of, face_of[j], j);
    std::size_t current_polygon = 0;
    bool asked_cgal = false;
    const internal::Polygon_provenance_visitor<TriangleMesh, Polygon_map> provenance{&polygon_of, &current_polygon};
    for(std::size_t j = 0; j < polygons.size(); ++j) {
      if(polygons[j].size() == 3)
        continue;
      const face_descriptor f = face_of[j];
      current_polygon = j;
      // (A quad is split along one diagonal with Euler operations: always safe.)
      const bool cdt = polygons[j].size() == 4 ||
                       (use_cdt && !internal::polygon_corners_coincide_in_projection(f, mesh));
      asked_cgal = asked_cgal || (cdt && polygons[j].size() > 4);
      bool cut = false;
      if(cdt) {
        // With assertions on (debug and fuzzing builds), the constrained
        // triangulation of a strongly non-planar polygon can fail one (found
        // by fuzzing); the release build's result is checked below. Either
        // way every polygon is then cut as a fan.
        try {
          cut = PMP::triangulate_face(f, mesh, CGAL::parameters::visitor(provenance));
        } catch(const CGAL::Failure_exception&) {
          return false;
        }
      }
      if(!cut) {
        // triangulate_face() gives up on a polygon without a normal (collinear
        // or coinciding corners), or with corners that coincide once
        // projected, before changing anything: cut a fan instead.
        const halfedge_descriptor h = halfedge(f, mesh);
        while(next(next(next(h, mesh), mesh), mesh) != h)
          put(polygon_of, face(opposite(CGAL::Euler::split_face(h, next(next(h, mesh), mesh), mesh), mesh), mesh), j);
      }
    }
    return !asked_cgal || mesh.is_valid(false);
  };
  // CGAL 5.5's constrained triangulation of a strongly non-planar polygon
  // can leave a corrupt mesh (a vertex whose halfedge does not point to it;
  // found by fuzzing, where walking around the vertex then never ended). Then
  // every polygon is cut as a fan instead, which only uses Euler operations.
  if(!build(true) && !build(false))
    throw Input_error(path, 0, "the polygons of the file cannot be cut into triangles");
  report.polygons_triangulated = static_cast<std::size_t>(
      std::count_if(polygons.begin(), polygons.end(), [](const auto& polygon) { return polygon.size() > 3; }));

  // Euler::split_face() does not look for an existing edge: a diagonal that
  // is already an edge of the mesh becomes a second, parallel edge. A
  // diagonal is an edge between two faces cut from the same polygon; of two
  // parallel diagonals, the later polygon is the one that needs a second edge.
  auto vindex = get(boost::vertex_index, mesh);
  const auto diagonal_of = [&](halfedge_descriptor h) { // its polygon, or none
    const face_descriptor f = face(h, mesh), g = face(opposite(h, mesh), mesh);
    const auto null_face = boost::graph_traits<TriangleMesh>::null_face();
    if(f == null_face || g == null_face || get(polygon_of, f) != get(polygon_of, g)) return std::size_t(-1);
    return polygons[get(polygon_of, f)].size() > 3 ? get(polygon_of, f) : std::size_t(-1);
  };
  std::size_t blamed = std::size_t(-1), a = 0, b = 0;
  for(halfedge_descriptor d : halfedges(mesh)) {
    if(diagonal_of(d) == std::size_t(-1))
      continue;
    std::size_t parallel = 0, latest = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(d, mesh))
      if(source(h, mesh) == source(d, mesh)) {
        ++parallel;
        if(diagonal_of(h) != std::size_t(-1)) latest = (std::max)(latest, diagonal_of(h));
      }
    if(parallel > 1 && latest < blamed) {
      blamed = latest;
      a = (std::min)(get(vindex, source(d, mesh)), get(vindex, target(d, mesh)));
      b = (std::max)(get(vindex, source(d, mesh)), get(vindex, target(d, mesh)));
    }
  }
  if(blamed != std::size_t(-1))
    throw Input_error(path, locate.face_line(blamed),
                      "face " + std::to_string(blamed) + " cannot be triangulated without a second edge between vertices " +
                          std::to_string(a) + " and " + std::to_string(b));

  // The soup check above makes this impossible; it stays as a cheap guard
  // because polygon_soup_to_polygon_mesh()'s own check is a precondition
  // that release builds drop.
  std::vector<halfedge_descriptor> non_manifold;
  PMP::non_manifold_vertices(mesh, std::back_inserter(non_manifold));
  if(!non_manifold.empty()) {
    const vertex_descriptor v = target(non_manifold.front(), mesh);
    const std::size_t i = static_cast<std::size_t>(std::find(vertex_of.begin(), vertex_of.end(), v) - vertex_of.begin());
    throw Input_error(path, 0, "vertex " + std::to_string(i) + " is non-manifold");
  }

  report.faces = static_cast<std::size_t>(num_faces(mesh));
  report.file_face.reserve(report.faces);
  for(face_descriptor f : faces(mesh))
    report.file_face.push_back(get(polygon_of, f));
  for(face_descriptor f : faces(mesh))
    if(PMP::is_degenerate_triangle_face(f, mesh))
      ++report.degenerate_faces;
  return report;
}

} // namespace diffuv

#endif // DIFFUV_IO_READ_MESH_H
