// diffuv: what a scan of a mesh file finds (the line of each element, the
// first problem), and the messages that every reader of a mesh file shares.
#ifndef DIFFUV_IO_INTERNAL_MESH_SCAN_H
#define DIFFUV_IO_INTERNAL_MESH_SCAN_H

#include <diffuv/internal/message_text.h>

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// Where the vertices and faces of a text mesh file are, and the first
/// problem met when reading it the way CGAL reads it. CGAL's readers answer
/// only true or false; the scan turns a `false` into a line and a reason,
/// and gives the line of an element named in a later check (the OFF and OBJ
/// readers fill it as they read). Lines count from 1; 0 means unknown.
struct Text_mesh_scan {
  std::vector<std::size_t> vertex_line;
  std::vector<std::size_t> face_line;
  std::size_t error_line = 0;
  std::string error; ///< empty if no problem was found
  /// (text OFF, scanned whole) the header announces vertex colours (`C`), or
  /// some vertex or face has colour numbers: what `read_off_paint()` reads
  bool colors = false;
};

/// The points and polygons of a mesh file, as read.
struct Polygon_soup {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool complete = false; ///< false: the file ended or broke off before all were read, or CGAL's reader would refuse it
};

/// The lines of a file's elements, scanned on first use: only error
/// messages need them.
class Line_locator {
public:
  /// `scanner` scans the file (an empty scan for a format without lines).
  explicit Line_locator(std::function<Text_mesh_scan()> scanner) : scanner_(std::move(scanner)) {}

  const Text_mesh_scan& scan()
  {
    if(!scanned_) {
      scan_ = scanner_();
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
  std::function<Text_mesh_scan()> scanner_;
  Text_mesh_scan scan_;
  bool scanned_ = false;
};

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
         count_text(nb_vertices, "vertex", "vertices") + ")";
}

inline std::string non_finite_message(std::size_t vertex)
{
  return "vertex " + std::to_string(vertex) + " has a coordinate that is NaN or infinite";
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_MESH_SCAN_H
