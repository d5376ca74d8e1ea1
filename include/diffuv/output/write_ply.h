// diffuv: meshes as PLY files that MeshLab and Blender show in colour: faces
// coloured and numbered by region (`write_labelled_ply()`, which
// `read_painted_labels()` reads back), or vertices coloured
// (`write_vertex_colored_ply()`, which `read_vertex_colors()` reads back).
#ifndef DIFFUV_OUTPUT_WRITE_PLY_H
#define DIFFUV_OUTPUT_WRITE_PLY_H

#include <diffuv/core/color.h>
#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/internal/number_format.h>
#include <diffuv/io/atomic_file.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace diffuv {

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

/// Writes a PLY mesh (text) with one colour per vertex (uchar red, green,
/// blue), which MeshLab and Blender show. Vertices in the order of
/// `vertices(tm)`, faces in the order of `faces(tm)`.
/// \param colors one colour per vertex, by position in `vertices(tm)`
/// \throws Output_error naming `path` if the counts differ (nothing is written then)
template <class TriangleMesh, class VertexPointMap>
void write_vertex_colored_ply(std::ostream& out, const TriangleMesh& tm, VertexPointMap vpm,
                              const std::vector<Color>& colors, const std::string& path = "the PLY output")
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const std::size_t nv = static_cast<std::size_t>(num_vertices(tm));
  if(colors.size() != nv)
    throw Output_error(path, internal::count_text(colors.size(), "vertex colour") + " for a mesh of " +
                                 std::to_string(nv) + (nv == 1 ? " vertex" : " vertices"));
  auto number = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(tm)) put(number, v, i++);

  out << "ply\nformat ascii 1.0\ncomment diffuv: vertex colours\n"
      << "element vertex " << nv << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element face " << num_faces(tm) << "\nproperty list uchar int vertex_indices\nend_header\n";
  i = 0;
  for(vertex_descriptor v : vertices(tm)) {
    const auto& p = get(vpm, v);
    internal::write_shortest(out, CGAL::to_double(p.x()));
    out << ' ';
    internal::write_shortest(out, CGAL::to_double(p.y()));
    out << ' ';
    internal::write_shortest(out, CGAL::to_double(p.z()));
    const Color& c = colors[i++];
    out << ' ' << int(c.r) << ' ' << int(c.g) << ' ' << int(c.b) << '\n';
  }
  for(auto f : faces(tm)) {
    std::vector<std::size_t> corners;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm)) corners.push_back(get(number, v));
    out << corners.size();
    for(std::size_t c : corners) out << ' ' << c;
    out << '\n';
  }
}

} // namespace diffuv

#endif // DIFFUV_OUTPUT_WRITE_PLY_H
