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
//
// The pieces are in io/internal/: the OFF, OBJ and PLY readers (one pass
// that reads the soup as CGAL's readers would, finds the lines of OFF and
// OBJ and what CGAL's PLY reader would not survive), the checks of the
// polygon soup, and its triangulation.
#ifndef DIFFUV_IO_READ_MESH_H
#define DIFFUV_IO_READ_MESH_H

#include <diffuv/core/error.h>
#include <diffuv/io/internal/file_bytes.h>
#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/obj_scanner.h>
#include <diffuv/io/internal/off_scanner.h>
#include <diffuv/io/internal/ply_scanner.h>
#include <diffuv/io/internal/polygon_soup_checks.h>
#include <diffuv/io/internal/repair_polygon_soup.h>
#include <diffuv/io/internal/triangulate_polygons.h>

#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace diffuv {

/// What `read_triangle_mesh()` read and what it changed.
struct Mesh_read_report {
  std::size_t vertices = 0;              ///< points of the file = the first vertices of the mesh, in the same order (copies of split points follow)
  std::size_t faces_in_file = 0;         ///< polygons of the file
  std::size_t polygons_triangulated = 0; ///< polygons of more than three vertices split into triangles
  std::size_t faces = 0;                 ///< triangles of the mesh
  std::size_t degenerate_faces = 0;      ///< triangles of zero area (collinear or coinciding corners)
  std::size_t isolated_vertices = 0;     ///< points used by no face (or merged into another), kept so that indices stay those of the file
  /// The polygon of the file each face comes from: `faces` entries, one per
  /// face of the mesh in the order of `faces(mesh)`. The triangles cut from a
  /// polygon all map to it, so per-polygon data of the file (labels, colours)
  /// can be carried to the triangles.
  std::vector<std::size_t> file_face;
  /// What was repaired (`Mesh_read_options::repair`); all zero when nothing was.
  Mesh_repair_report repair;
  /// Without the repair only: border points that lie exactly where another
  /// border point lies, borders the repair would have stitched (an unwelded
  /// export read as it is).
  std::size_t coinciding_border_points = 0;
  /// Empty unless the repair stitched borders: for each point of the file,
  /// the vertex its faces use (itself, or the coinciding point it was merged
  /// into; the merged point stays as an isolated vertex).
  std::vector<std::size_t> vertex_of_point;
  /// Empty unless the repair split non-manifold points: for each vertex of
  /// the mesh, the point of the file it is (vertices past the file's points
  /// are copies).
  std::vector<std::size_t> point_of_vertex;
  /// False where `read_painted_labels()` can find no region in the file: an
  /// OBJ or STL file, or an OFF file without a colour (no `C` in its header,
  /// no colour on any vertex or face line). A caller can then skip that
  /// second read of the file (on a 1M-vertex OFF file, most of a second).
  bool may_hold_regions = true;

  /// The vertex of the mesh that stands for point `i` of the file.
  std::size_t vertex_of(std::size_t i) const { return i < vertex_of_point.size() ? vertex_of_point[i] : i; }
  /// The point of the file that vertex `v` of the mesh is (or copies).
  std::size_t point_of(std::size_t v) const { return v < point_of_vertex.size() ? point_of_vertex[v] : v; }
};

/// How `read_triangle_mesh()` treats a file that is not a manifold,
/// consistently oriented mesh.
struct Mesh_read_options {
  /// Repair what can be repaired without moving a point (see
  /// `read_triangle_mesh()`); false refuses such a file, naming the problem.
  bool repair = true;
};

/// The formats of mesh files that `read_triangle_mesh()` reads.
enum class Mesh_format { off, obj, ply, stl };

/// Returns the format named by the extension of `path`, in any case.
/// \throws Input_error naming `path`: "the file name has no extension
///   (expected .off, .obj, .ply or .stl)", "unknown mesh file extension
///   \".xyz\" (expected .off, .obj, .ply or .stl)"
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

namespace internal {

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

} // namespace internal

/// Reads a polygon mesh file (OFF, OBJ, PLY or STL, by extension, in any
/// case) into a triangle mesh whose vertex i is the i-th point of the file.
///
/// The file is read as a polygon soup (OFF, OBJ and PLY by diffuv's readers,
/// which give what CGAL's readers give; STL by CGAL's) and checked
/// before the mesh is built: at least one face; finite coordinates; faces of
/// at least three vertex indices, in range.
///
/// Then, with `options.repair` (the default), what would keep the soup from
/// being a manifold, consistently oriented mesh is repaired without moving a
/// point or renumbering the file's points, each repair counted in
/// `report.repair`: border edges that coincide in pairs are stitched (the
/// unwelded seam; their points merged into the one of smallest index, the
/// other left as an isolated vertex: `vertex_of_point`); faces that use a
/// point twice, and faces that repeat another's points, are dropped; faces
/// are oriented consistently per component (most of its faces keep their
/// orientation); non-manifold points (vertices where faces meet in several
/// fans, ends of edges of three or more faces) get a copy per extra fan,
/// appended after the file's points (`point_of_vertex`). A surface that
/// cannot be oriented (a Moebius strip) is refused. Without `options.repair`
/// the soup must be all that already (faces of distinct vertex indices, a
/// manifold, consistently oriented polygon mesh), else it is refused.
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
///     parentheses when it is known
///   - "the file has no face"
///   - "vertex I has a coordinate that is NaN or infinite"
///   - "vertex I has a coordinate of X, too large to compute with (beyond 1e60): rescale the mesh",
///     "the mesh is too small to compute with (it spans X, under 1e-60): rescale the mesh"
///   - "face J has vertex index X, out of range (the file has N vertices)"
///   - "face J has only K vertices"
///   - with `options.repair`: "the surface is not orientable (like a Moebius
///     strip): faces J and K disagree on the direction of the edge between vertices I and L, ...",
///     "non-manifold edge or vertex left after repair (...)", "the file has
///     no face that uses three distinct points"
///   - without: "face J uses vertex I twice", "non-manifold edge or vertex, or
///     inconsistent orientation (...)", with "; vertices I and K have the
///     same position: the mesh may need welding" when two used points coincide
///   - "face J cannot be triangulated without a second edge between vertices I and K"
///   - "the polygons of the file cannot be cut into triangles"
template <class TriangleMesh>
Mesh_read_report read_triangle_mesh(const std::string& path, TriangleMesh& mesh,
                                    const Mesh_read_options& options = Mesh_read_options())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  namespace fs = std::filesystem;
  using Vertex_point_map = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type;
  using Point = typename boost::property_traits<Vertex_point_map>::value_type;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Polygon = std::vector<std::size_t>;

  std::error_code dir_ec;
  if(fs::is_directory(path, dir_ec))
    throw Input_error(path, 0, "is a directory, not a mesh file");
  const Mesh_format format = mesh_format(path);
  const std::string name = internal::format_name(format);

  std::error_code ec;
  if(fs::is_directory(path, ec) || !std::ifstream(path, std::ios::binary))
    throw Input_error(path, 0, "cannot open file");
  const std::uintmax_t file_size = fs::file_size(path, ec);
  if(ec)
    throw Input_error(path, 0, "cannot open file");
  if(file_size == 0)
    throw Input_error(path, 0, "the file is empty");

  // OFF, OBJ and PLY are read in one pass of diffuv's own readers, which
  // give the soup (and the lines of its elements in OFF and OBJ); STL is
  // read with CGAL's reader.
  internal::Polygon_soup soup;
  internal::Text_mesh_scan text_scan;
  if(format != Mesh_format::stl) {
    internal::File_bytes bytes;
    if(!bytes.open(path))
      throw Input_error(path, 0, "cannot open file");
    if(format == Mesh_format::obj) {
      // An OBJ file CGAL accepts may still have an index out of range, which
      // the checks below report in file order with the other problems.
      text_scan = internal::scan_obj(bytes.view(), soup);
    } else {
      text_scan = format == Mesh_format::off ? internal::scan_off(bytes.view(), false, &soup)
                                             : internal::scan_ply(bytes.view(), file_size, soup);
      if(!text_scan.error.empty())
        throw Input_error(path, text_scan.error_line, text_scan.error);
    }
  }
  const bool may_hold_regions = format == Mesh_format::ply || (format == Mesh_format::off && text_scan.colors);

  // The lines of elements, for messages: only the text formats have them.
  internal::Line_locator locate([&]() -> internal::Text_mesh_scan { return std::move(text_scan); });

  // CGAL's STL reader prints to std::cerr unless told not to.
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  bool read = false;
  try {
    if(format == Mesh_format::stl) {
      read = CGAL::IO::read_STL(path, points, polygons, CGAL::parameters::verbose(false));
    } else {
      read = soup.complete;
      points.reserve(soup.points.size());
      for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
      polygons = std::move(soup.polygons);
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

  // CGAL's OBJ reader lets the index one past the last vertex through; the
  // OBJ scan quotes the index as written.
  std::vector<bool> used =
    internal::check_polygon_soup(path, points, polygons, locate, format == Mesh_format::obj, options.repair);

  Mesh_read_report report;
  report.may_hold_regions = may_hold_regions;
  report.vertices = points.size();
  report.faces_in_file = polygons.size();
  internal::Soup_repair_map repaired;
  if(!options.repair) {
    bool manifold = false;
    report.coinciding_border_points = internal::coinciding_border_points<std::size_t>(points, polygons, manifold);
  } else {
    repaired = internal::repair_polygon_soup(path, points, polygons, locate, report.repair);
    if(report.repair.points_merged > 0) report.vertex_of_point = std::move(repaired.vertex_of_point);
    if(report.repair.vertex_copies > 0) report.point_of_vertex = std::move(repaired.point_of_vertex);
    if(report.repair.any()) {
      used.assign(points.size(), false);
      for(const auto& polygon : polygons)
        for(std::size_t v : polygon) used[v] = true;
    }
  }
  report.isolated_vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
  report.file_face = internal::triangulate_polygons(path, points, polygons, locate, mesh, repaired.file_polygon);
  report.polygons_triangulated = static_cast<std::size_t>(
      std::count_if(polygons.begin(), polygons.end(), [](const auto& polygon) { return polygon.size() > 3; }));
  report.faces = static_cast<std::size_t>(num_faces(mesh));
  for(face_descriptor f : faces(mesh))
    if(PMP::is_degenerate_triangle_face(f, mesh))
      ++report.degenerate_faces;
  return report;
}

} // namespace diffuv

#endif // DIFFUV_IO_READ_MESH_H
