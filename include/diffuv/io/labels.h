// diffuv: region labels, the paper's user-painted regions (one patch each).
//
// Labels come as a text file with one integer per polygon of the mesh file,
// or painted in the mesh file itself: per-face colours (MeshLab), an integer
// face property (PLY `label`, `quality`, ...), per-vertex labels or colours
// (Blender, the paper's vertex painting). All of them are numbered per
// polygon of the file, in file order; `face_labels_of_mesh()` carries them to
// the triangles of the mesh built by `read_triangle_mesh()`.
//
// Colours become labels canonically: the distinct colours of the file are
// sorted by (red, green, blue) and a colour's label is its rank. The same
// painting on two meshes gives the same labels, whatever the face order.
#ifndef DIFFUV_IO_LABELS_H
#define DIFFUV_IO_LABELS_H

#include <diffuv/core/color.h>
#include <diffuv/core/error.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/internal/number_format.h>
#include <diffuv/io/read_mesh.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace diffuv {

namespace internal {

inline std::string count_text(std::size_t n, const std::string& noun)
{
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

inline std::string number_text(double value)
{
  std::ostringstream s;
  s << std::setprecision(15) << value;
  return s.str();
}

/// The label written as `token`; throws the reason of a bad one.
inline int parse_label(const std::string& token, const std::string& path, std::size_t line)
{
  long long value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if(ec == std::errc::result_out_of_range && end == token.data() + token.size())
    throw Input_error(path, line, "label " + token + " is out of range");
  if(ec != std::errc() || end != token.data() + token.size())
    throw Input_error(path, line, "\"" + printable(token) + "\" is not an integer label");
  if(value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    throw Input_error(path, line, "label " + token + " is out of range");
  if(value < 0)
    throw Input_error(path, line, "label " + token + " is negative; labels are non-negative integers");
  return static_cast<int>(value);
}

} // namespace internal

/// Reads a per-face label file: integers separated by white space, one per
/// polygon of the mesh file in file order (one per line is the documented
/// form); `#` starts a comment that runs to the end of the line.
/// \param expected_polygons the number of polygons of the mesh file
///        (`Mesh_read_report::faces_in_file`)
/// \returns `expected_polygons` labels, each in [0, 2^31)
/// \throws Input_error naming `path`, with the line of the label concerned
///   (0 for the first two): "cannot open file";
///   "the file has 5000 labels, the mesh has 5804 faces";
///   "\"abc\" is not an integer label"; "label 2147483648 is out of range";
///   "label -3 is negative; labels are non-negative integers"
inline std::vector<int> read_face_labels(const std::string& path, std::size_t expected_polygons)
{
  std::error_code ec;
  std::ifstream in(path, std::ios::binary);
  if(std::filesystem::is_directory(path, ec) || !in)
    throw Input_error(path, 0, "cannot open file");
  std::vector<int> labels;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number) {
    if(number == 1) internal::drop_byte_order_mark(line);
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos)
      line.erase(hash);
    std::istringstream tokens(line); // white space includes the '\r' of CRLF files
    std::string token;
    while(tokens >> token)
      labels.push_back(internal::parse_label(token, path, number));
  }
  if(labels.size() != expected_polygons)
    throw Input_error(path, 0, "the file has " + internal::count_text(labels.size(), "label") + ", the mesh has " +
                                   internal::count_text(expected_polygons, "face"));
  return labels;
}

/// Writes labels one per line, readable by `read_face_labels()`, through
/// `Atomic_output_file`.
/// \throws Output_error naming `path` if the file cannot be written, or if a
///         label is negative ("face 3 has label -1; labels are non-negative
///         integers"); nothing is written then
inline void write_face_labels(const std::string& path, const std::vector<int>& labels)
{
  for(std::size_t j = 0; j < labels.size(); ++j)
    if(labels[j] < 0)
      throw Output_error(path, "face " + std::to_string(j) + " has label " + std::to_string(labels[j]) +
                                   "; labels are non-negative integers");
  Atomic_output_file file(path);
  for(int label : labels)
    file.stream() << label << '\n';
  file.commit();
}

/// Where painted regions were found in a mesh file.
enum class Label_source { none, face_colors, face_property, vertex_colors, vertex_property };

/// Painted regions of a mesh file, as read by `read_painted_labels()`.
struct Painted_labels {
  Label_source source = Label_source::none;
  /// The property used: "red/green/blue" (PLY colours, or "r/g/b"), "rgb"
  /// (OFF colours), or the
  /// name of the integer property ("label", "quality", ...)
  std::string property;
  /// One label per polygon of the file, in file order; empty if none
  std::vector<int> polygon_labels;
  /// For colour sources, `colors[label]` is the colour of `label` (labels are
  /// 0 to `colors.size() - 1`); empty for the other sources
  std::vector<Color> colors;
};

namespace internal {

/// What a mesh file paints on its vertices or its faces.
struct Paint_element {
  explicit Paint_element(std::string k) : kind(std::move(k)) {}
  std::string kind;                          ///< "vertex" or "face", for messages
  std::size_t count = 0;                     ///< items read
  std::vector<std::size_t> line;             ///< line of each item (text files), else empty
  std::string color_name;                    ///< empty if there are no colours
  std::array<bool, 3> float_color{};         ///< component in [0,1] (float), else [0,255]
  std::vector<std::array<double, 3>> color;  ///< one per item if colours
  struct Candidate {
    std::string name;
    bool integer_type = true;
    std::vector<double> values;
  };
  std::vector<Candidate> candidates;         ///< label properties, by priority

  std::size_t line_of(std::size_t j) const { return j < line.size() ? line[j] : 0; }
};

struct Paint_file {
  Paint_element vertices{"vertex"}, faces{"face"};
  std::vector<std::vector<double>> polygons; ///< vertex indices of each face, as read
};

/// Names of the integer properties taken as labels, by priority (any case).
inline const std::vector<std::string>& label_property_names()
{
  static const std::vector<std::string> names = {"label",  "labels",  "segment", "segment_id", "segmentation",
                                                 "region", "region_id", "patch", "patch_id", "part",
                                                 "part_id", "class",   "quality"};
  return names;
}

inline std::string lower(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

inline bool parse_number(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return !token.empty() && end == token.c_str() + token.size();
}

/// The colours of `e`, checked: integers in [0,255], or floats in [0,1]
/// scaled by 255 and rounded.
inline std::vector<Color> colors_of(const std::string& path, const Paint_element& e)
{
  std::vector<Color> colors(e.count);
  for(std::size_t j = 0; j < e.count; ++j) {
    unsigned char rgb[3];
    for(int c = 0; c < 3; ++c) {
      const double v = e.color[j][c];
      const double top = e.float_color[c] ? 1. : 255.;
      if(!(v >= 0 && v <= top) || (!e.float_color[c] && v != std::floor(v)))
        throw Input_error(path, e.line_of(j), e.kind + " " + std::to_string(j) + " has colour component " +
                                                  number_text(v) + ", outside " +
                                                  (e.float_color[c] ? "[0, 1]" : "[0, 255] (integers)"));
      rgb[c] = static_cast<unsigned char>(e.float_color[c] ? std::lround(v * 255) : v);
    }
    colors[j] = Color{rgb[0], rgb[1], rgb[2]};
  }
  return colors;
}

/// Labels = ranks of the colours sorted by (r, g, b); `distinct` receives the sorted colours.
inline std::vector<int> color_ranks(const std::vector<Color>& colors, std::vector<Color>& distinct)
{
  distinct = colors;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::vector<int> labels(colors.size());
  for(std::size_t j = 0; j < colors.size(); ++j)
    labels[j] = static_cast<int>(std::lower_bound(distinct.begin(), distinct.end(), colors[j]) - distinct.begin());
  return labels;
}

template <class Index> bool valid_index(Index i, std::size_t n)
{
  if constexpr(std::is_floating_point<Index>::value)
    return i >= 0 && i < static_cast<double>(n) && i == std::floor(i);
  else if constexpr(std::is_signed<Index>::value)
    return i >= 0 && static_cast<std::size_t>(i) < n;
  else
    return static_cast<std::size_t>(i) < n;
}

inline bool is_label_value(double v) { return v >= 0 && v < 2147483648. && v == std::floor(v); }

/// A candidate is used if it has an integer type (bad values are then
/// errors) or if all its values are labels (MeshLab stores quality as float).
inline bool usable(const Paint_element::Candidate& c)
{
  return c.integer_type || std::all_of(c.values.begin(), c.values.end(), is_label_value);
}

inline std::vector<int> labels_of(const std::string& path, const Paint_element& e, const Paint_element::Candidate& c)
{
  std::vector<int> labels(c.values.size());
  for(std::size_t j = 0; j < labels.size(); ++j) {
    const double v = c.values[j];
    const std::string where = e.kind + " " + std::to_string(j) + " has ";
    if(v != std::floor(v))
      throw Input_error(path, e.line_of(j), where + "value " + number_text(v) + " in property \"" + c.name +
                                                "\", not an integer label");
    if(v < 0)
      throw Input_error(path, e.line_of(j), where + "label " + number_text(v) + " (property \"" + c.name +
                                                "\"); labels are non-negative integers");
    if(!is_label_value(v))
      throw Input_error(path, e.line_of(j), where + "label " + number_text(v) + " (property \"" + c.name +
                                                "\"), out of range");
    labels[j] = static_cast<int>(v);
  }
  return labels;
}

/// True if `c` holds labels that group the items exactly as `ranks` do.
inline bool same_partition(const Paint_element::Candidate& c, const std::vector<int>& ranks)
{
  std::map<double, int> rank_of;
  std::map<int, double> value_of;
  for(std::size_t j = 0; j < ranks.size(); ++j) {
    if(!is_label_value(c.values[j]) || rank_of.emplace(c.values[j], ranks[j]).first->second != ranks[j] ||
       value_of.emplace(ranks[j], c.values[j]).first->second != c.values[j])
      return false;
  }
  return true;
}

// ---- PLY ----------------------------------------------------------------

enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline bool ply_type(const std::string& name, Ply_type& type)
{
  static const char* const names[16] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                        "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  const auto it = std::find(names, names + 16, name);
  type = static_cast<Ply_type>((it - names) % 8);
  return it != names + 16;
}

/// Reads PLY values, as text or as little- or big-endian binary.
class Ply_value_reader {
public:
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

  bool read(Ply_type type, double& value)
  {
    if(format_ == 0) {
      start_item();
      std::string token;
      for(int c = in_.peek(); c != EOF && !std::isspace(c); c = in_.peek())
        token += static_cast<char>(in_.get());
      return parse_number(token, value);
    }
    static const std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
    unsigned char b[8];
    const std::size_t n = sizes[static_cast<int>(type)];
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

private:
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

inline Paint_file read_ply_paint(const std::string& path, const std::string& property, std::uintmax_t file_size)
{
  struct Property { std::string name; Ply_type type, count_type; bool list; };
  struct Element { std::string name; std::uintmax_t count; std::size_t line; std::vector<Property> properties; };
  auto fail = [&](std::size_t line, const std::string& what) {
    return Input_error(path, line, "not a valid PLY file (" + what + ")");
  };

  std::ifstream in(path, std::ios::binary);
  std::vector<Element> elements;
  int format = -1;
  std::string text;
  std::size_t line = 0;
  for(bool end = false; !end;) {
    if(!std::getline(in, text))
      throw fail(0, "the header has no end_header line");
    ++line;
    if(!text.empty() && text.back() == '\r')
      text.pop_back();
    std::istringstream words(text);
    std::string word, a, b, c, d;
    words >> word;
    if(line == 1) {
      if(word != "ply")
        throw fail(1, "the file does not start with \"ply\"");
    } else if(word == "format") {
      words >> a;
      format = a == "ascii" ? 0 : a == "binary_little_endian" ? 1 : a == "binary_big_endian" ? 2 : -1;
      if(format < 0)
        throw fail(line, "unknown format \"" + a + "\"");
    } else if(word == "element") {
      std::uintmax_t count = 0;
      if(!(words >> a >> b) || std::from_chars(b.data(), b.data() + b.size(), count).ec != std::errc())
        throw fail(line, "cannot read the element line \"" + text + "\"");
      elements.push_back({a, count, line, {}});
    } else if(word == "property") {
      Property p{"", Ply_type::int8, Ply_type::int8, false};
      words >> a;
      p.list = a == "list";
      const bool typed = p.list ? (words >> b >> c >> d) && ply_type(b, p.count_type) && ply_type(c, p.type)
                                : (words >> d) && ply_type(a, p.type);
      if(!typed || elements.empty())
        throw fail(line, "cannot read the property line \"" + text + "\"");
      p.name = d;
      elements.back().properties.push_back(p);
    } else if(word == "end_header") {
      end = true;
    } else if(!word.empty() && word != "comment" && word != "obj_info") {
      throw fail(line, "unexpected header line \"" + text + "\"");
    }
  }
  if(format < 0)
    throw fail(0, "the header has no format line");

  Paint_file file;
  Ply_value_reader reader(in, format, line + 1);
  bool seen_vertex = false, seen_face = false;
  for(const Element& element : elements) {
    if(element.properties.empty())
      continue;
    if(element.count > file_size) // each item takes at least one byte
      throw fail(element.line, "the header announces " + std::to_string(element.count) + " " + element.name +
                                   " items, more than the file can hold");
    // Where each property goes: -1 nowhere, 0-2 a colour component,
    // 3 the vertex index list, 4 + k the k-th label candidate.
    const bool is_vertex = !seen_vertex && (element.name == "vertex" || element.name == "vertices");
    const bool is_face = !seen_face && (element.name == "face" || element.name == "faces");
    seen_vertex = seen_vertex || is_vertex;
    seen_face = seen_face || is_face;
    Paint_element* paint = is_vertex ? &file.vertices : is_face ? &file.faces : nullptr;
    std::vector<int> role(element.properties.size(), -1);
    auto find = [&](const std::string& name, bool list) {
      for(std::size_t k = 0; k < element.properties.size(); ++k)
        if(lower(element.properties[k].name) == lower(name) && element.properties[k].list == list)
          return static_cast<int>(k);
      return -1;
    };
    if(paint) {
      paint->count = static_cast<std::size_t>(element.count);
      if(is_face) {
        int k = find("vertex_indices", true);
        k = k >= 0 ? k : find("vertex_index", true);
        if(k < 0)
          throw fail(element.line, "the face element has no vertex_indices list");
        role[k] = 3;
      }
      static const char* const color_names[2][3] = {{"red", "green", "blue"}, {"r", "g", "b"}};
      for(const auto& names : color_names) {
        const int ks[3] = {find(names[0], false), find(names[1], false), find(names[2], false)};
        if(property.empty() && paint->color_name.empty() && ks[0] >= 0 && ks[1] >= 0 && ks[2] >= 0) {
          paint->color_name = std::string(names[0]) + "/" + names[1] + "/" + names[2];
          for(int c = 0; c < 3; ++c) {
            role[ks[c]] = c;
            const Ply_type t = element.properties[ks[c]].type;
            paint->float_color[c] = t == Ply_type::float32 || t == Ply_type::float64;
          }
        }
      }
      for(const std::string& name : property.empty() ? label_property_names() : std::vector<std::string>{property}) {
        const int k = find(name, false);
        if(k >= 0 && role[k] < 0) {
          const Ply_type t = element.properties[k].type;
          const bool integer_type = t != Ply_type::float32 && t != Ply_type::float64;
          role[k] = 4 + static_cast<int>(paint->candidates.size());
          paint->candidates.push_back({element.properties[k].name, integer_type, {}});
        }
      }
    }

    for(std::uintmax_t j = 0; j < element.count; ++j) {
      const std::size_t item_line = reader.start_item();
      if(paint && format == 0)
        paint->line.push_back(item_line);
      if(is_face)
        file.polygons.emplace_back();
      if(paint && !paint->color_name.empty())
        paint->color.emplace_back();
      for(std::size_t k = 0; k < element.properties.size(); ++k) {
        const Property& p = element.properties[k];
        auto bad = [&](const std::string& what) {
          return fail(item_line, (what.empty() ? in.eof() ? "the file ends in" : "cannot read" : what) +
                                     " property \"" + p.name + "\" of " + element.name + " " + std::to_string(j));
        };
        double value = 0;
        if(!reader.read(p.list ? p.count_type : p.type, value))
          throw bad("");
        if(p.list) {
          if(!(value >= 0 && value <= static_cast<double>(file_size)) || value != std::floor(value))
            throw bad("bad list size " + number_text(value) + " in");
          for(std::size_t i = 0, n = static_cast<std::size_t>(value); i < n; ++i) {
            if(!reader.read(p.type, value))
              throw bad("");
            if(role[k] == 3)
              file.polygons.back().push_back(value);
          }
        } else if(role[k] >= 4) {
          paint->candidates[static_cast<std::size_t>(role[k] - 4)].values.push_back(value);
        } else if(role[k] >= 0) {
          paint->color.back()[static_cast<std::size_t>(role[k])] = value;
        }
      }
    }
  }
  return file;
}

// ---- OFF ----------------------------------------------------------------

/// Reads the colours of a text OFF file. Face colours are the numbers after a
/// face's vertex indices, with or without the `C` of the header (Geomview's
/// rule; MeshLab writes "OFF" with face colours); vertex colours, with `C`,
/// follow the coordinates and normals. 3 or 4 components (alpha ignored):
/// integers 0-255 if every component of the element is written as an
/// integer, else floats 0-1. Binary OFF is not read (no colours).
inline Paint_file read_off_paint(const std::string& path)
{
  Paint_file file;
  std::ifstream in(path, std::ios::binary);
  std::size_t line = 0;
  std::vector<std::string> tokens;
  auto next_record = [&]() { // the tokens of the next line that has some
    std::string text;
    tokens.clear();
    while(tokens.empty() && std::getline(in, text)) {
      ++line;
      std::istringstream words(text.substr(0, text.find('#')));
      for(std::string w; words >> w;)
        tokens.push_back(w);
    }
    return !tokens.empty();
  };
  auto fail = [&](std::size_t at, const std::string& what) {
    return Input_error(path, at, "not a valid OFF file (" + what + ")");
  };

  if(!next_record())
    throw fail(0, "the file has no OFF header");
  const std::string keyword = tokens[0];
  const std::size_t off = keyword.size() >= 3 ? keyword.size() - 3 : 0;
  const std::string prefix = keyword.substr(0, off);
  if(keyword.compare(off, std::string::npos, "OFF") != 0)
    throw fail(line, "the file does not start with an OFF header");
  if(prefix.find('n') != std::string::npos)
    return file; // n-dimensional OFF: no colours read
  const std::size_t h = prefix.find('4') != std::string::npos ? 1 : 0;
  const bool has_vertex_colors = prefix.find('C') != std::string::npos;
  const std::size_t skip = 3 + h + (prefix.find('N') != std::string::npos ? 3 + h : 0);
  const std::size_t texture = prefix.find("ST") != std::string::npos ? 2 + h : 0;
  std::vector<std::string> counts(tokens.begin() + 1, tokens.end());
  while(counts.size() < 3 && !(counts.size() == 1 && counts[0] == "BINARY") && next_record())
    counts.insert(counts.end(), tokens.begin(), tokens.end());
  if(!counts.empty() && counts[0] == "BINARY")
    return file;
  long long nv = 0, nf = 0;
  if(counts.size() < 3 || !parse_count(counts[0], nv) || !parse_count(counts[1], nf) || nv < 0 || nf < 0)
    throw fail(line, "cannot read the numbers of vertices, faces and edges");

  // The colour numbers of a record, after its first `first` numbers.
  auto read_colors = [&](Paint_element& e, std::size_t j, std::size_t first, std::size_t last,
                         bool& all_integer) {
    const std::size_t n = last > first ? last - first : 0;
    const std::string item = e.kind + " " + std::to_string(j);
    if(n == 1)
      throw Input_error(path, line, item + " has a colour-map index; colour maps are not supported");
    if(n != 0 && n != 3 && n != 4)
      throw Input_error(path, line, item + " has " + std::to_string(n) + " colour components; expected 3 or 4");
    if(j > 0 && (n == 0) != e.color.empty())
      throw Input_error(path, line, item + (n == 0 ? " has no colour, but " : " has a colour, but ") + e.kind +
                                        " 0 " + (n == 0 ? "has one" : "has none"));
    if(n == 0)
      return;
    std::array<double, 3> rgb{};
    for(std::size_t c = 0; c < n; ++c) {
      double value;
      long long integer;
      if(!parse_number(tokens[first + c], value))
        throw fail(line, "cannot read the colour of " + e.kind + " " + std::to_string(j));
      all_integer = all_integer && parse_count(tokens[first + c], integer);
      if(c < 3)
        rgb[c] = value;
    }
    e.color.push_back(rgb);
    e.color_name = "rgb";
  };

  bool integer_vertex_colors = true, integer_face_colors = true;
  for(long long i = 0; i < nv; ++i) {
    if(!next_record())
      throw fail(0, "the file ends before vertex " + std::to_string(i) + " of " + std::to_string(nv));
    file.vertices.line.push_back(line);
    if(tokens.size() < skip)
      throw fail(line, "vertex " + std::to_string(i) + " does not have its coordinates");
    if(has_vertex_colors)
      read_colors(file.vertices, static_cast<std::size_t>(i), skip, tokens.size() - std::min(texture, tokens.size()),
                  integer_vertex_colors);
  }
  for(long long j = 0; j < nf; ++j) {
    if(!next_record())
      throw fail(0, "the file ends before face " + std::to_string(j) + " of " + std::to_string(nf));
    file.faces.line.push_back(line);
    long long size = 0;
    if(!parse_count(tokens[0], size) || size < 0)
      throw fail(line, "face " + std::to_string(j) + " does not start with its number of vertices");
    if(tokens.size() <= static_cast<std::size_t>(size))
      throw fail(line, "face " + std::to_string(j) + " lists fewer than its " + std::to_string(size) +
                           " vertex indices");
    file.polygons.emplace_back();
    for(long long c = 1; c <= size; ++c) {
      double index;
      if(!parse_number(tokens[static_cast<std::size_t>(c)], index))
        throw fail(line, "face " + std::to_string(j) + " has a vertex index that is not a number");
      file.polygons.back().push_back(index);
    }
    read_colors(file.faces, static_cast<std::size_t>(j), static_cast<std::size_t>(size) + 1, tokens.size(),
                integer_face_colors);
  }
  file.vertices.count = static_cast<std::size_t>(nv);
  file.faces.count = static_cast<std::size_t>(nf);
  file.vertices.float_color.fill(!integer_vertex_colors);
  file.faces.float_color.fill(!integer_face_colors);
  return file;
}

} // namespace internal

/// Converts per-vertex labels to per-polygon labels: a polygon takes the
/// label that most of its vertices have; on a tie (in particular when its
/// vertices all differ) the smallest of the tied labels. The rule depends on
/// the set of labels of the polygon only, not on the order of its vertices.
/// \tparam PolygonRange a range of polygons, each a range of vertex indices
/// \param vertex_labels one label per vertex, indexed by vertex number
/// \returns one label per polygon
/// \throws Error if a polygon has no vertex or a vertex index out of range
template <class PolygonRange>
std::vector<int> vertex_labels_to_polygons(const std::vector<int>& vertex_labels, const PolygonRange& polygons)
{
  std::vector<int> result;
  std::vector<int> labels;
  for(const auto& polygon : polygons) {
    const std::string name = "polygon " + std::to_string(result.size());
    labels.clear();
    for(const auto index : polygon) {
      if(!internal::valid_index(index, vertex_labels.size()))
        throw Error(name + " has vertex index " + internal::number_text(static_cast<double>(index)) +
                    ", but there are " + internal::count_text(vertex_labels.size(), "vertex label"));
      labels.push_back(vertex_labels[static_cast<std::size_t>(index)]);
    }
    if(labels.empty())
      throw Error(name + " has no vertex");
    std::sort(labels.begin(), labels.end());
    int best = labels.front();
    std::ptrdiff_t best_run = 0;
    for(auto run = labels.begin(); run != labels.end();) {
      const auto end = std::upper_bound(run, labels.end(), *run);
      if(end - run > best_run) { // strictly more: the smaller label wins a tie
        best = *run;
        best_run = end - run;
      }
      run = end;
    }
    result.push_back(best);
  }
  return result;
}

/// Reads painted regions from an OFF or PLY file (text or binary PLY).
///
/// Sources, by priority:
/// 1. face colours: PLY face properties red/green/blue (or r/g/b), any
///    integer type 0-255 or float 0-1, alpha ignored (MeshLab); OFF
///    colours after a face's vertex indices. If the faces also have a label
///    property (see 2) that groups them exactly as the colours do (one value
///    per colour and one colour per value), its numbers are used instead
///    (source `face_property`): so `write_labelled_ply()` files read back
///    with their labels, and a file repainted since loses its stale numbers;
/// 2. a face label property, the first of "label", "labels", "segment",
///    "segment_id", "segmentation", "region", "region_id", "patch",
///    "patch_id", "part", "part_id", "class", "quality" (any case) that is
///    present: integer-typed, or float-typed with whole values in [0, 2^31)
///    only (MeshLab's quality is a float; a float property with other values
///    is not a label property and is skipped);
/// 3. a vertex label property, the same way;
/// 4. vertex colours (Blender's red/green/blue/alpha on vertices; OFF `COFF`).
/// Colours become labels by rank (distinct colours sorted by (r, g, b)).
/// Vertex labels become polygon labels by `vertex_labels_to_polygons()`.
///
/// \param property if not empty, only the face, then vertex, property of that
///        name (any case) is used, whatever its type; colours are ignored
/// \returns source `none` for a file with no painting, for OBJ and STL files,
///          and for binary and n-dimensional OFF files (not read)
/// \throws Input_error naming `path` and the line when known: "unknown mesh
///   file extension ...", "cannot open file", "not a valid PLY file (...)" or
///   OFF, "face 3 has colour component 300, outside [0, 255] (integers)",
///   "face 3 has colour component 1.5, outside [0, 1]", "face 2 has 2 colour
///   components; expected 3 or 4", "face 1 has no colour, but face 0 has one",
///   "face 3 has label -1 (property \"label\"); labels are non-negative
///   integers", "face 3 has value 0.5 in property \"quality\", not an integer
///   label", "face 3 has vertex index 9, out of range (the file has 8
///   vertices)" (vertex sources), "the file has no face or vertex property \"p\""
inline Painted_labels read_painted_labels(const std::string& path, const std::string& property = std::string())
{
  const internal::Mesh_format format = internal::mesh_format(path);
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  if(ec || std::filesystem::is_directory(path, ec) || !std::ifstream(path, std::ios::binary))
    throw Input_error(path, 0, "cannot open file");
  Painted_labels result;
  internal::Paint_file file;
  if(format == internal::Mesh_format::ply)
    file = internal::read_ply_paint(path, property, file_size);
  else if(format == internal::Mesh_format::off && property.empty())
    file = internal::read_off_paint(path);
  else if(property.empty())
    return result;
  internal::Paint_element& faces = file.faces;
  internal::Paint_element& vertices = file.vertices;

  auto use = [&](Label_source source, const std::string& name, std::vector<int> labels) {
    result.source = source;
    result.property = name;
    result.polygon_labels = std::move(labels);
    return result;
  };
  auto to_polygons = [&](const std::vector<int>& vertex_labels) {
    for(std::size_t j = 0; j < file.polygons.size(); ++j)
      for(double index : file.polygons[j])
        if(!internal::valid_index(index, vertex_labels.size()))
          throw Input_error(path, faces.line_of(j), internal::out_of_range_message(j, internal::number_text(index),
                                                                                   vertex_labels.size()));
    return vertex_labels_to_polygons(vertex_labels, file.polygons);
  };

  if(!property.empty()) {
    if(!faces.candidates.empty())
      return use(Label_source::face_property, faces.candidates[0].name,
                 internal::labels_of(path, faces, faces.candidates[0]));
    if(!vertices.candidates.empty())
      return use(Label_source::vertex_property, vertices.candidates[0].name,
                 to_polygons(internal::labels_of(path, vertices, vertices.candidates[0])));
    throw Input_error(path, 0, "the file has no face or vertex property \"" + property + "\"");
  }
  if(!faces.color_name.empty()) {
    const std::vector<int> ranks = internal::color_ranks(internal::colors_of(path, faces), result.colors);
    for(const auto& candidate : faces.candidates)
      if(internal::same_partition(candidate, ranks)) {
        result.colors.clear();
        return use(Label_source::face_property, candidate.name, internal::labels_of(path, faces, candidate));
      }
    return use(Label_source::face_colors, faces.color_name, ranks);
  }
  for(const auto& candidate : faces.candidates)
    if(internal::usable(candidate))
      return use(Label_source::face_property, candidate.name, internal::labels_of(path, faces, candidate));
  for(const auto& candidate : vertices.candidates)
    if(internal::usable(candidate))
      return use(Label_source::vertex_property, candidate.name,
                 to_polygons(internal::labels_of(path, vertices, candidate)));
  if(!vertices.color_name.empty())
    return use(Label_source::vertex_colors, vertices.color_name,
               to_polygons(internal::color_ranks(internal::colors_of(path, vertices), result.colors)));
  return result;
}

/// Carries per-polygon labels of a mesh file to the faces of the mesh built
/// by `read_triangle_mesh()`: a triangle cut from a polygon takes its label.
/// \param polygon_labels one label per polygon of the file, in file order
/// \param report the reader's report for that file
/// \returns `report.faces` labels, in the order of `faces(mesh)`
/// \throws Error if `polygon_labels` does not have `report.faces_in_file`
///         entries or the report has no face provenance
inline std::vector<int> face_labels_of_mesh(const std::vector<int>& polygon_labels, const Mesh_read_report& report)
{
  if(polygon_labels.size() != report.faces_in_file)
    throw Error("there are " + internal::count_text(polygon_labels.size(), "polygon label") +
                ", the mesh file has " + internal::count_text(report.faces_in_file, "face"));
  if(report.file_face.size() != report.faces)
    throw Error("the mesh read report has no face provenance (file_face)");
  std::vector<int> labels(report.faces);
  for(std::size_t f = 0; f < report.faces; ++f) {
    if(report.file_face[f] >= polygon_labels.size())
      throw Error("the mesh read report maps face " + std::to_string(f) + " to polygon " +
                  std::to_string(report.file_face[f]) + ", which does not exist");
    labels[f] = polygon_labels[report.file_face[f]];
  }
  return labels;
}

/// Options of `write_labelled_ply()`.
struct Labelled_ply_options {
  /// `colors[label]`, the colour of each label; empty (default): `label_color()`.
  /// Give distinct labels distinct colours, or `read_painted_labels()` reads
  /// the colours back instead of the labels.
  std::vector<Color> colors;
  /// Binary (little-endian) instead of text (default).
  bool binary = false;
};

/// Writes a PLY mesh whose faces carry their region: per-face colours
/// `red`/`green`/`blue` (uchar), which MeshLab and Blender show, and an int
/// property `label`, which `read_painted_labels()` reads back. Vertices are
/// written in the order of `vertices(tm)` (double coordinates), faces in the
/// order of `faces(tm)`, to `out` (`path` names it in errors).
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
/// \tparam VertexPointMap a readable property map from vertices to points with `x()`, `y()`, `z()`
/// \param face_labels one non-negative label per face, in the order of `faces(tm)`
/// \throws Output_error naming `path` if the file cannot be written, or
///   (nothing is written) "5 face labels for a mesh of 6 faces", "face 3 has
///   label -1; labels are non-negative integers", "face 3 has label 7, but
///   only 4 colours are given"
template <class TriangleMesh, class VertexPointMap>
void write_labelled_ply(std::ostream& out, const TriangleMesh& tm, VertexPointMap vpm,
                        const std::vector<int>& face_labels, const Labelled_ply_options& options = {},
                        const std::string& path = "the PLY output")
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Key = typename boost::property_traits<VertexPointMap>::key_type;
  static_assert(std::is_convertible<vertex_descriptor, Key>::value,
                "write_labelled_ply: VertexPointMap must map the mesh's vertex_descriptor to a point");
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  if(face_labels.size() != nf)
    throw Output_error(path, internal::count_text(face_labels.size(), "face label") + " for a mesh of " +
                                 internal::count_text(nf, "face"));
  for(std::size_t j = 0; j < nf; ++j) {
    const std::string which = "face " + std::to_string(j) + " has label " + std::to_string(face_labels[j]);
    if(face_labels[j] < 0)
      throw Output_error(path, which + "; labels are non-negative integers");
    if(!options.colors.empty() && static_cast<std::size_t>(face_labels[j]) >= options.colors.size())
      throw Output_error(path, which + ", but only " + internal::count_text(options.colors.size(), "colour") +
                                   " are given");
  }

  auto number = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t nv = 0;
  for(vertex_descriptor v : vertices(tm))
    put(number, v, nv++);

  out << "ply\nformat " << (options.binary ? "binary_little_endian" : "ascii") << " 1.0\n"
      << "comment diffuv labelled regions: face colour = region, face label = region number\n"
      << "element vertex " << nv << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << nf << "\nproperty list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int label\nend_header\n";
  auto put_bytes = [&](std::uint64_t bits, int n) { // little-endian, whatever the host
    for(int i = 0; i < n; ++i)
      out.put(static_cast<char>((bits >> (8 * i)) & 0xff));
  };
  for(vertex_descriptor v : vertices(tm)) {
    const auto& p = get(vpm, v);
    const double xyz[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int c = 0; c < 3; ++c) {
      if(options.binary) {
        std::uint64_t bits;
        std::memcpy(&bits, &xyz[c], 8);
        put_bytes(bits, 8);
      } else {
        internal::write_shortest(out, xyz[c]);
        out << (c < 2 ? ' ' : '\n');
      }
    }
  }
  std::size_t j = 0;
  std::vector<std::size_t> corners;
  for(auto f : faces(tm)) {
    corners.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      corners.push_back(get(number, v));
    if(corners.size() > 255)
      throw Output_error(path, "face " + std::to_string(j) + " has more than 255 vertices");
    const int label = face_labels[j++];
    const Color rgb = options.colors.empty() ? label_color(label) : options.colors[static_cast<std::size_t>(label)];
    if(options.binary) {
      put_bytes(corners.size(), 1);
      for(std::size_t c : corners)
        put_bytes(c, 4);
      for(unsigned char c : {rgb.r, rgb.g, rgb.b})
        put_bytes(c, 1);
      put_bytes(static_cast<std::uint32_t>(label), 4);
    } else {
      out << corners.size();
      for(std::size_t c : corners)
        out << ' ' << c;
      out << ' ' << int(rgb.r) << ' ' << int(rgb.g) << ' ' << int(rgb.b) << ' ' << label << '\n';
    }
  }
}

/// Same as above, into the file `path` through `Atomic_output_file`.
/// \throws Output_error naming `path`
template <class TriangleMesh, class VertexPointMap>
void write_labelled_ply(const std::string& path, const TriangleMesh& tm, VertexPointMap vpm,
                        const std::vector<int>& face_labels, const Labelled_ply_options& options = {})
{
  Atomic_output_file file(path);
  write_labelled_ply(file.stream(), tm, vpm, face_labels, options, path);
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_IO_LABELS_H
