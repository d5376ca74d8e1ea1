// diffuv: regions painted in the mesh file itself, the paper's user-painted
// regions (one patch each): per-face colours (MeshLab), an integer face
// property (PLY `label`, `quality`, ...), per-vertex labels or colours
// (Blender, the paper's vertex painting). They are numbered per polygon of
// the file, in file order; `face_labels_of_mesh()` (read_labels.h) carries
// them to the triangles of the mesh built by `read_triangle_mesh()`.
//
// Colours become labels canonically: the distinct colours of the file are
// sorted by (red, green, blue) and a colour's label is its rank. The same
// painting on two meshes gives the same labels, whatever the face order.
#ifndef DIFFUV_IO_PAINTED_LABELS_H
#define DIFFUV_IO_PAINTED_LABELS_H

#include <diffuv/core/color.h>
#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/read_paint.h>
#include <diffuv/io/read_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

namespace diffuv {

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
/// \param colors false: colours are ignored (sources 2 and 3 only)
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
inline Painted_labels read_painted_labels(const std::string& path, const std::string& property = std::string(),
                                          bool colors = true)
{
  const Mesh_format format = mesh_format(path);
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  if(ec || std::filesystem::is_directory(path, ec) || !std::ifstream(path, std::ios::binary))
    throw Input_error(path, 0, "cannot open file");
  Painted_labels result;
  internal::Paint_file file;
  if(format == Mesh_format::ply)
    file = internal::read_ply_paint(path, property, file_size);
  else if(format == Mesh_format::off && property.empty())
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
  if(colors && !faces.color_name.empty()) {
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
  if(colors && !vertices.color_name.empty())
    return use(Label_source::vertex_colors, vertices.color_name,
               to_polygons(internal::color_ranks(internal::colors_of(path, vertices), result.colors)));
  return result;
}

} // namespace diffuv

#endif // DIFFUV_IO_PAINTED_LABELS_H
