// diffuv: per-vertex colours in and out of PLY and OFF files — what a
// correspondence carries from one mesh to the other and shows on the result.
#ifndef DIFFUV_IO_VERTEX_COLORS_H
#define DIFFUV_IO_VERTEX_COLORS_H

#include <diffuv/core/color.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/internal/number_format.h>
#include <diffuv/io/internal/read_paint.h>
#include <diffuv/io/labels.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

namespace diffuv {

/// Reads the per-vertex colours of a PLY (red/green/blue, integer 0-255 or
/// float 0-1) or text OFF (`COFF`) file, one per point of the file in file order.
/// \returns an empty vector if the file has no vertex colours (and for OBJ, STL,
///          binary OFF files)
/// \throws Input_error naming `path`: "cannot open file", a malformed file, a
///         colour component out of range
inline std::vector<Color> read_vertex_colors(const std::string& path)
{
  const Mesh_format format = mesh_format(path);
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  if(ec || std::filesystem::is_directory(path, ec) || !std::ifstream(path, std::ios::binary))
    throw Input_error(path, 0, "cannot open file");
  internal::Paint_file file;
  if(format == Mesh_format::ply) file = internal::read_ply_paint(path, std::string(), file_size);
  else if(format == Mesh_format::off) file = internal::read_off_paint(path);
  else return {};
  if(file.vertices.color_name.empty()) return {};
  return internal::colors_of(path, file.vertices);
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

#endif // DIFFUV_IO_VERTEX_COLORS_H
