// diffuv: what a mesh file paints on its vertices and faces (colours, label
// properties), read through the PLY and OFF scanners that the mesh reader
// uses, with the line of every item for messages. Both read the mapped file.
#ifndef DIFFUV_IO_INTERNAL_READ_PAINT_H
#define DIFFUV_IO_INTERNAL_READ_PAINT_H

#include <diffuv/core/color.h>
#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/io/internal/file_bytes.h>
#include <diffuv/io/internal/number_tokens.h>
#include <diffuv/io/internal/off_scanner.h>
#include <diffuv/io/internal/ply_scanner.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace diffuv {
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

/// Reads the colours and label properties of the first vertex and face
/// elements of a PLY file (text or binary), through the PLY scanner with
/// `Ply_header_rules::strict`. With `property` given, only the property of
/// that name (any case) is a candidate, and colours are not read.
/// \throws Input_error naming `path`: "not a valid PLY file (...)"
inline Paint_file read_ply_paint(const std::string& path, const std::string& property, std::uintmax_t file_size)
{
  auto fail = [&](std::size_t line, const std::string& what) {
    return Input_error(path, line, "not a valid PLY file (" + what + ")");
  };
  File_bytes bytes;
  if(!bytes.open(path))
    throw Input_error(path, 0, "cannot open file");
  Ply_header header;
  std::size_t error_line = 0, data_start = 0;
  const std::string problem =
      read_ply_header(bytes.view(), file_size, Ply_header_rules::strict, header, error_line, data_start);
  if(!problem.empty())
    throw fail(error_line, problem);
  const int format = header.format;

  Paint_file file;
  Ply_value_reader reader(bytes.view().substr(data_start), format, header.lines + 1);
  bool seen_vertex = false, seen_face = false;
  for(const Ply_element& element : header.elements) {
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
            paint->float_color[c] = is_float(t);
          }
        }
      }
      for(const std::string& name : property.empty() ? label_property_names() : std::vector<std::string>{property}) {
        const int k = find(name, false);
        if(k >= 0 && role[k] < 0) {
          const Ply_type t = element.properties[k].type;
          const bool integer_type = !is_float(t);
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
        const Ply_property& p = element.properties[k];
        auto bad = [&](const std::string& what) {
          return fail(item_line, (what.empty() ? reader.at_end() ? "the file ends in" : "cannot read" : what) +
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

/// Reads the colours of a text OFF file. Face colours are the numbers after a
/// face's vertex indices, with or without the `C` of the header (Geomview's
/// rule; MeshLab writes "OFF" with face colours); vertex colours, with `C`,
/// follow the coordinates and normals. 3 or 4 components (alpha ignored):
/// integers 0-255 if every component of the element is written as an
/// integer, else floats 0-1. Binary OFF is not read (no colours).
/// The lines are those of the OFF scanner; the counts of the header are
/// the first three words after the keyword, on as many lines as they take,
/// and the vertices start on the next line.
/// \throws Input_error naming `path`: "not a valid OFF file (...)", a bad colour
inline Paint_file read_off_paint(const std::string& path)
{
  Paint_file file;
  File_bytes bytes;
  if(!bytes.open(path))
    throw Input_error(path, 0, "cannot open file");
  Line_counting_reader in(bytes.view());
  std::size_t line = 0;
  std::vector<std::string_view> tokens;
  auto next_record = [&]() { // the words of the next line that has some
    std::string_view text;
    tokens.clear();
    if(!in.next_line(text, line)) {
      line = in.lines_begun(); // the last line of the file
      return false;
    }
    text = text.substr(0, text.find('#'));
    for(std::size_t at = 0;;) {
      while(at < text.size() && is_blank(text[at])) ++at;
      if(at == text.size()) break;
      const std::size_t end = std::min(text.size(), static_cast<std::size_t>(
          std::find_if(text.begin() + static_cast<std::ptrdiff_t>(at), text.end(), is_blank) - text.begin()));
      tokens.push_back(text.substr(at, end - at));
      at = end;
    }
    return true;
  };
  auto fail = [&](std::size_t at, const std::string& what) {
    return Input_error(path, at, "not a valid OFF file (" + what + ")");
  };

  if(!next_record())
    throw fail(0, "the file has no OFF header");
  const Off_keyword announced = off_keyword(std::string(tokens[0]));
  if(!announced.ends_with_off)
    throw fail(line, "the file does not start with an OFF header");
  if(announced.n_dimensional)
    return file; // n-dimensional OFF: no colours read
  const std::size_t h = announced.homogeneous ? 1 : 0;
  const bool has_vertex_colors = announced.colors;
  const std::size_t skip = 3 + h + (announced.normals ? 3 + h : 0);
  const std::size_t texture = announced.texture ? 2 + h : 0;
  std::vector<std::string_view> counts(tokens.begin() + 1, tokens.end());
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
      throw Input_error(path, line, item + " has " + count_text(n, "colour component") + "; expected 3 or 4");
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
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_READ_PAINT_H
