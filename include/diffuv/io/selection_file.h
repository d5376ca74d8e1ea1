// diffuv: CGAL's selection files (`*.selection.txt`).
//
// CGAL's Polyhedron demo and its Surface_mesh_parameterization examples store
// a selection as three lines: the indices of the selected vertices, of the
// selected faces, and pairs of vertex indices for the selected edges. diffuv
// uses the first line only (corner or source vertices); indices count from 0
// in the order of the mesh's vertices, which is the order of the mesh file
// when the mesh was read by `read_triangle_mesh()`.
#ifndef DIFFUV_IO_SELECTION_FILE_H
#define DIFFUV_IO_SELECTION_FILE_H

#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>

#include <boost/graph/graph_traits.hpp>

#include <charconv>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace diffuv {

/// Reads the vertex indices on the first line of a CGAL selection file, in
/// the order of the file.
///
/// Other lines (face and edge selections) are ignored. Indices are not
/// checked against a mesh here, and a repeated index is kept: the caller
/// knows what it needs (see `selection_vertices()`).
/// \param path the file
/// \returns the indices, at least one
/// \throws Input_error naming `path`: line 0 if the file cannot be opened;
///         line 1 if the first line holds no index, or a token that is not a
///         non-negative integer, or one too large for `std::size_t`
inline std::vector<std::size_t> read_selection_file(const std::string& path)
{
  std::error_code ec;
  if(std::filesystem::is_directory(path, ec))
    throw Input_error(path, 0, "is a directory, not a selection file");
  std::ifstream in(path);
  if(!in)
    throw Input_error(path, 0, "cannot open file");

  std::string line;
  std::getline(in, line); // an empty file leaves `line` empty
  internal::drop_byte_order_mark(line);

  std::vector<std::size_t> indices;
  std::istringstream tokens(line);
  std::string token;
  while(tokens >> token) {
    std::size_t value = 0;
    const char* first = token.data();
    const char* last = first + token.size();
    // For an unsigned type from_chars accepts digits only (no sign, no
    // space), which is exactly what an index is.
    const auto [end, ec] = std::from_chars(first, last, value);
    if(ec == std::errc::result_out_of_range)
      throw Input_error(path, 1, "vertex index " + token + " is too large");
    if(ec != std::errc() || end != last)
      throw Input_error(path, 1, "\"" + internal::printable(token) + "\" is not a vertex index (a non-negative integer)");
    indices.push_back(value);
  }
  if(indices.empty())
    throw Input_error(path, 1, "no vertex index on the first line");
  return indices;
}

/// Returns the vertices of `tm` selected by `indices`, in the order of
/// `indices`: index `i` is the `i`-th vertex of `vertices(tm)`.
///
/// \tparam VertexListGraph a model of `VertexListGraph` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, ...)
/// \param tm the mesh the selection refers to
/// \param indices vertex indices, e.g. from `read_selection_file()`
/// \param path the selection file, named in the error
/// \throws Input_error(path, 1, ...) if an index is not below `num_vertices(tm)`
template <class VertexListGraph>
std::vector<typename boost::graph_traits<VertexListGraph>::vertex_descriptor>
selection_vertices(const VertexListGraph& tm, const std::vector<std::size_t>& indices, const std::string& path)
{
  using vertex_descriptor = typename boost::graph_traits<VertexListGraph>::vertex_descriptor;
  // Position in vertices(tm), not the vertex index map: a Surface_mesh with
  // removed vertices keeps gaps in its indices.
  std::vector<vertex_descriptor> by_position;
  for(vertex_descriptor v : vertices(tm))
    by_position.push_back(v);

  std::vector<vertex_descriptor> selected;
  selected.reserve(indices.size());
  for(std::size_t i : indices) {
    if(i >= by_position.size())
      throw Input_error(path, 1, "vertex index " + std::to_string(i) + " is out of range (the mesh has " +
                                 internal::count_text(by_position.size(), "vertex", "vertices") + ")");
    selected.push_back(by_position[i]);
  }
  return selected;
}

} // namespace diffuv

#endif // DIFFUV_IO_SELECTION_FILE_H
