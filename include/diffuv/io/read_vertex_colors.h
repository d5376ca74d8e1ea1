// diffuv: per-vertex colours of a PLY or OFF file — what a correspondence
// carries from one mesh to the other. `write_vertex_colored_ply()`
// (output/write_ply.h) writes them.
#ifndef DIFFUV_IO_READ_VERTEX_COLORS_H
#define DIFFUV_IO_READ_VERTEX_COLORS_H

#include <diffuv/core/color.h>
#include <diffuv/core/error.h>
#include <diffuv/io/internal/read_paint.h>
#include <diffuv/io/read_mesh.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
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

} // namespace diffuv

#endif // DIFFUV_IO_READ_VERTEX_COLORS_H
