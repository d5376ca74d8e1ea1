// diffuv: region labels from a label file, the paper's user-painted regions
// (one patch each) written as one integer per polygon of the mesh file, and
// per-polygon labels carried to the triangles of the mesh.
//
// Labels painted in the mesh file itself are read by `read_painted_labels()`
// (painted_labels.h); `write_face_labels()` (output/write_labels.h) writes a
// label file.
#ifndef DIFFUV_IO_READ_LABELS_H
#define DIFFUV_IO_READ_LABELS_H

#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/io/read_mesh.h>

#include <charconv>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace diffuv {
namespace internal {

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

} // namespace diffuv

#endif // DIFFUV_IO_READ_LABELS_H
