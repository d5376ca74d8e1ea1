// diffuv: a checked polygon soup into a triangle mesh whose vertex i is
// point i of the soup, each polygon cut into triangles that remember it.
#ifndef DIFFUV_IO_INTERNAL_TRIANGULATE_POLYGONS_H
#define DIFFUV_IO_INTERNAL_TRIANGULATE_POLYGONS_H

#include <diffuv/core/error.h>
#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/soup_to_mesh.h>

#include <CGAL/exceptions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/property_map/vector_property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

namespace diffuv {
namespace internal {

/// Gives each triangle cut from a polygon the polygon's number, through
/// `CGAL::Polygon_mesh_processing::triangulate_face()`'s visitor (which is
/// copied, hence the pointers).
template <class TriangleMesh, class PolygonMap>
struct Polygon_provenance_visitor {
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  PolygonMap* polygon_of;
  const std::size_t* polygon;

  void before_subface_creations(face_descriptor) {}
  void after_subface_created(face_descriptor f) { put(*polygon_of, f, *polygon); }
  void after_subface_creations() {}
};

/// True when `CGAL::Polygon_mesh_processing::triangulate_face()` would put
/// two corners of face `f` (more than four corners) on one point of its
/// constrained triangulation: they coincide once projected along the face
/// normal, compared with the same projection traits. CGAL then gives up
/// (returns false), except when the two are the first and the last corner,
/// which breaks a precondition of `Constrained_triangulation_2` (found by
/// fuzzing); so such faces are cut as a fan without asking CGAL.
template <class TriangleMesh>
bool polygon_corners_coincide_in_projection(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                                            const TriangleMesh& mesh)
{
  using Point = typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  const auto points = get(CGAL::vertex_point, mesh);
  const typename Kernel::Vector_3 normal = CGAL::Polygon_mesh_processing::compute_face_normal(f, mesh);
  if(normal == CGAL::NULL_VECTOR)
    return false; // triangulate_face() refuses it first
  const CGAL::Projection_traits_3<Kernel> projection(normal);
  const auto compare_x = projection.compare_x_2_object();
  const auto compare_y = projection.compare_y_2_object();
  std::vector<Point> corners;
  for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
    corners.push_back(get(points, v));
  std::sort(corners.begin(), corners.end(), [&](const Point& a, const Point& b) {
    const CGAL::Comparison_result x = compare_x(a, b);
    return x == CGAL::SMALLER || (x == CGAL::EQUAL && compare_y(a, b) == CGAL::SMALLER);
  });
  for(std::size_t k = 1; k < corners.size(); ++k)
    if(compare_x(corners[k - 1], corners[k]) == CGAL::EQUAL && compare_y(corners[k - 1], corners[k]) == CGAL::EQUAL)
      return true;
  return false;
}

/// Builds `mesh` from a soup that `check_polygon_soup()` accepted and cuts
/// each polygon of more than three vertices into triangles: with
/// `CGAL::Polygon_mesh_processing::triangulate_face()`, or as a fan from one
/// corner when that fails on a degenerate polygon (and for every polygon if
/// CGAL's triangulation leaves a corrupt mesh). No vertex is added: vertex i
/// is point i. `locate` gives the lines of messages.
/// `file_polygon`, if not empty, gives the file's number of each polygon
/// (some were dropped by the repair): messages and the result use it.
/// \returns the polygon of the file of each face, in the order of `faces(mesh)`
/// \throws Input_error naming `path`: "the polygons of the file cannot be cut
///   into triangles", "face J cannot be triangulated without a second edge
///   between vertices I and K", "vertex I is non-manifold"
template <class TriangleMesh, class Point>
std::vector<std::size_t> triangulate_polygons(const std::string& path, const std::vector<Point>& points,
                                              const std::vector<std::vector<std::size_t>>& polygons,
                                              Line_locator& locate, TriangleMesh& mesh,
                                              const std::vector<std::size_t>& file_polygon = {})
{
  const auto in_file = [&](std::size_t j) { return file_polygon.empty() ? j : file_polygon[j]; };
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  // The mesh, and the polygon of each face: triangulating a polygon of more
  // than four vertices removes its face and fills the hole, so the provenance
  // is tracked through face indices (a map that grows with the mesh).
  // An empty mesh without garbage appends vertices and faces in soup order,
  // which is what makes vertex i the file's point i.
  std::vector<vertex_descriptor> vertex_of;
  using Polygon_map = boost::vector_property_map<std::size_t, typename boost::property_map<TriangleMesh, CGAL::face_index_t>::const_type>;
  Polygon_map polygon_of(get(boost::face_index, mesh));
  auto build = [&](bool use_cdt) {
    soup_to_mesh(points, polygons, mesh);
    vertex_of.assign(vertices(mesh).begin(), vertices(mesh).end());
    const std::vector<face_descriptor> face_of(faces(mesh).begin(), faces(mesh).end());
    polygon_of = Polygon_map(static_cast<unsigned>(polygons.size()), get(boost::face_index, mesh));
    for(std::size_t j = 0; j < polygons.size(); ++j)
      put(polygon_of, face_of[j], j);
    std::size_t current_polygon = 0;
    bool asked_cgal = false;
    const Polygon_provenance_visitor<TriangleMesh, Polygon_map> provenance{&polygon_of, &current_polygon};
    for(std::size_t j = 0; j < polygons.size(); ++j) {
      if(polygons[j].size() == 3)
        continue;
      const face_descriptor f = face_of[j];
      current_polygon = j;
      // (A quad is split along one diagonal with Euler operations: always safe.)
      const bool cdt = polygons[j].size() == 4 ||
                       (use_cdt && !polygon_corners_coincide_in_projection(f, mesh));
      asked_cgal = asked_cgal || (cdt && polygons[j].size() > 4);
      bool cut = false;
      if(cdt) {
        // With assertions on (debug and fuzzing builds), the constrained
        // triangulation of a strongly non-planar polygon can fail one (found
        // by fuzzing); the release build's result is checked below. Either
        // way every polygon is then cut as a fan.
        try {
          cut = PMP::triangulate_face(f, mesh, CGAL::parameters::visitor(provenance));
        } catch(const CGAL::Failure_exception&) {
          return false;
        }
      }
      if(!cut) {
        // triangulate_face() gives up on a polygon without a normal (collinear
        // or coinciding corners), or with corners that coincide once
        // projected, before changing anything: cut a fan instead.
        const halfedge_descriptor h = halfedge(f, mesh);
        while(next(next(next(h, mesh), mesh), mesh) != h)
          put(polygon_of, face(opposite(CGAL::Euler::split_face(h, next(next(h, mesh), mesh), mesh), mesh), mesh), j);
      }
    }
    return !asked_cgal || mesh.is_valid(false);
  };
  // CGAL 5.5's constrained triangulation of a strongly non-planar polygon
  // can leave a corrupt mesh (a vertex whose halfedge does not point to it;
  // found by fuzzing, where walking around the vertex then never ended). Then
  // every polygon is cut as a fan instead, which only uses Euler operations.
  if(!build(true) && !build(false))
    throw Input_error(path, 0, "the polygons of the file cannot be cut into triangles");

  // Euler::split_face() does not look for an existing edge: a diagonal that
  // is already an edge of the mesh becomes a second, parallel edge. A
  // diagonal is an edge between two faces cut from the same polygon; of two
  // parallel diagonals, the later polygon is the one that needs a second edge.
  auto vindex = get(boost::vertex_index, mesh);
  const auto diagonal_of = [&](halfedge_descriptor h) { // its polygon, or none
    const face_descriptor f = face(h, mesh), g = face(opposite(h, mesh), mesh);
    const auto null_face = boost::graph_traits<TriangleMesh>::null_face();
    if(f == null_face || g == null_face || get(polygon_of, f) != get(polygon_of, g)) return std::size_t(-1);
    return polygons[get(polygon_of, f)].size() > 3 ? get(polygon_of, f) : std::size_t(-1);
  };
  std::size_t blamed = std::size_t(-1), a = 0, b = 0;
  for(halfedge_descriptor d : halfedges(mesh)) {
    if(diagonal_of(d) == std::size_t(-1))
      continue;
    std::size_t parallel = 0, latest = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(d, mesh))
      if(source(h, mesh) == source(d, mesh)) {
        ++parallel;
        if(diagonal_of(h) != std::size_t(-1)) latest = (std::max)(latest, diagonal_of(h));
      }
    if(parallel > 1 && latest < blamed) {
      blamed = latest;
      a = (std::min)(get(vindex, source(d, mesh)), get(vindex, target(d, mesh)));
      b = (std::max)(get(vindex, source(d, mesh)), get(vindex, target(d, mesh)));
    }
  }
  if(blamed != std::size_t(-1))
    throw Input_error(path, locate.face_line(in_file(blamed)),
                      "face " + std::to_string(in_file(blamed)) + " cannot be triangulated without a second edge between vertices " +
                          std::to_string(a) + " and " + std::to_string(b));

  // check_polygon_soup() makes this impossible; it stays as a cheap guard
  // because polygon_soup_to_polygon_mesh()'s own check is a precondition
  // that release builds drop.
  std::vector<halfedge_descriptor> non_manifold;
  PMP::non_manifold_vertices(mesh, std::back_inserter(non_manifold));
  if(!non_manifold.empty()) {
    const vertex_descriptor v = target(non_manifold.front(), mesh);
    const std::size_t i = static_cast<std::size_t>(std::find(vertex_of.begin(), vertex_of.end(), v) - vertex_of.begin());
    throw Input_error(path, 0, "vertex " + std::to_string(i) + " is non-manifold");
  }

  std::vector<std::size_t> file_face;
  file_face.reserve(static_cast<std::size_t>(num_faces(mesh)));
  for(face_descriptor f : faces(mesh))
    file_face.push_back(in_file(get(polygon_of, f)));
  return file_face;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_TRIANGULATE_POLYGONS_H
