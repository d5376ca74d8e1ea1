// diffuv: a textured mesh as a Wavefront OBJ file.
//
// CGAL's OBJ writer ignores texture coordinates, and a parameterization
// with seams needs them per face corner: a vertex on a seam has one (u,v) in
// each chart. This writer emits one `vt` per distinct (vertex, uv) pair and
// `f v/vt ...` faces, keeping the vertices in the order of the mesh so that
// vertex i of the OBJ file is vertex i of the input mesh.
#ifndef DIFFUV_OUTPUT_WRITE_OBJ_H
#define DIFFUV_OUTPUT_WRITE_OBJ_H

#include <diffuv/core/error.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/internal/number_format.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <iomanip>
#include <ostream>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace diffuv {

/// Writes `tm` with per-corner texture coordinates in OBJ format to `out`.
///
/// The file holds, in this order: `mtllib` (if `mtllib` is not empty), one
/// `v` line per vertex in the order of `vertices(tm)` (shortest exact form),
/// one `vt` line per distinct (vertex, uv) pair in the order the faces first
/// use it (shortest exact form), `usemtl` (if `material` is not empty), and
/// one `f v/vt v/vt v/vt` line per face in the order of `faces(tm)`, with
/// 1-based indices. The corners of a face are the targets of the halfedges
/// of `halfedges_around_face(halfedge(f, tm), tm)`, so the orientation of
/// the mesh is kept. Two uv of one vertex are the same `vt` only if they are
/// exactly equal. A face with a corner whose uv is NaN or infinite (a face in
/// no chart) is written as `f v v v`, without texture coordinates.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
///         (faces with more than three corners are written as they are)
/// \tparam VertexPointMap a `ReadablePropertyMap` from `vertex_descriptor`
///         to a 3D point with `x()`, `y()`, `z()`
/// \tparam CornerUvMap a `ReadablePropertyMap` from `halfedge_descriptor`
///         to a 2D point with `x()`, `y()`: the uv of the corner `target(h)` in `face(h)`
/// \param out the stream to write to
/// \param tm the mesh
/// \param vpm the positions of the vertices of `tm`
/// \param corner_uv the uv of every corner of every face of `tm`
/// \param mtllib the material library to reference, e.g. "parameterization.mtl"
/// \param material the material used by the faces, e.g. "checkerboard"
template <class TriangleMesh, class VertexPointMap, class CornerUvMap>
void write_obj(std::ostream& out,
               const TriangleMesh& tm,
               VertexPointMap vpm,
               CornerUvMap corner_uv,
               const std::string& mtllib = "",
               const std::string& material = "")
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  static_assert(std::is_convertible<vertex_descriptor, typename boost::property_traits<VertexPointMap>::key_type>::value,
                "write_obj: VertexPointMap must be keyed by the vertex_descriptor of TriangleMesh");
  static_assert(std::is_convertible<halfedge_descriptor, typename boost::property_traits<CornerUvMap>::key_type>::value,
                "write_obj: CornerUvMap must be keyed by the halfedge_descriptor of TriangleMesh");

  // Position of each vertex in vertices(tm): the internal index of a
  // Surface_mesh has gaps after removals, the OBJ numbering must not.
  std::unordered_map<vertex_descriptor, std::size_t> vertex_number;
  vertex_number.reserve(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm))
    vertex_number.emplace(v, vertex_number.size());

  // The vt of each vertex so far; a vertex has one per chart it is in,
  // so a linear search is short.
  struct Uv { double u, v; std::size_t number; };
  std::vector<std::vector<Uv>> uvs_of_vertex(vertex_number.size());
  std::vector<std::pair<double, double>> vt;   // in file order
  std::vector<std::size_t> corners;            // (v, vt) pairs, face after face
  std::vector<std::size_t> face_sizes;
  constexpr std::size_t no_vt = static_cast<std::size_t>(-1);

  for(face_descriptor f : faces(tm)) {
    std::size_t size = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const std::size_t vn = vertex_number.at(target(h, tm));
      const auto uv = get(corner_uv, h);
      const double u = CGAL::to_double(uv.x());
      const double v = CGAL::to_double(uv.y());
      if(!std::isfinite(u) || !std::isfinite(v)) { // no uv here (a face in no chart)
        corners.push_back(vn);
        corners.push_back(no_vt);
        ++size;
        continue;
      }
      std::size_t tn = vt.size();
      bool found = false;
      for(const Uv& known : uvs_of_vertex[vn]) {
        if(known.u == u && known.v == v) {
          tn = known.number;
          found = true;
          break;
        }
      }
      if(!found) {
        uvs_of_vertex[vn].push_back(Uv{u, v, tn});
        vt.emplace_back(u, v);
      }
      corners.push_back(vn);
      corners.push_back(tn);
      ++size;
    }
    face_sizes.push_back(size);
  }

  internal::Text_writer text(out);
  if(!mtllib.empty()) text.put("mtllib ").put(mtllib).put('\n');

  // Shortest exact form: input coordinates come back as they were written.
  for(vertex_descriptor v : vertices(tm)) {
    const auto& p = get(vpm, v);
    text.put("v ").number(CGAL::to_double(p.x())).put(' ').number(CGAL::to_double(p.y())).put(' ');
    text.number(CGAL::to_double(p.z())).put('\n');
  }
  for(const auto& [u, v] : vt) text.put("vt ").number(u).put(' ').number(v).put('\n');

  if(!material.empty()) text.put("usemtl ").put(material).put('\n');

  std::size_t c = 0;
  for(std::size_t size : face_sizes) {
    // A face with a corner without uv is written without texture coordinates.
    bool textured = true;
    for(std::size_t k = 0; k < size; ++k) textured = textured && corners[c + 2 * k + 1] != no_vt;
    text.put('f');
    for(std::size_t k = 0; k < size; ++k, c += 2) {
      text.put(' ').number(corners[c] + 1);
      if(textured) text.put('/').number(corners[c + 1] + 1);
    }
    text.put('\n');
  }
  text.flush();
}

/// Same as above, into the file `path`, through `Atomic_output_file`: on
/// error, an existing file at `path` is left as it was.
/// \throws Output_error naming `path` if the file cannot be created or written
template <class TriangleMesh, class VertexPointMap, class CornerUvMap>
void write_obj(const std::string& path, const TriangleMesh& tm, VertexPointMap vpm, CornerUvMap corner_uv,
               const std::string& mtllib = "", const std::string& material = "")
{
  Atomic_output_file file(path);
  write_obj(file.stream(), tm, vpm, corner_uv, mtllib, material);
  file.commit();
}

/// Writes an OBJ material library (MTL) with one material `material` whose
/// diffuse colour is the image `texture_file`:
/// `newmtl`, `Ka 1 1 1`, `Kd 1 1 1` (the texture is not darkened), `Ks 0 0 0`,
/// `d 1`, `illum 1`, `map_Kd <texture_file>`.
///
/// \param out the stream to write to
/// \param material the material's name, as given to `write_obj()`; no white space
/// \param texture_file the image, usually relative to the MTL file's folder; no line break
/// \throws std::invalid_argument if `material` is empty or has white space, or
///         `texture_file` is empty or has a line break
inline void write_mtl(std::ostream& out, const std::string& material, const std::string& texture_file)
{
  if(material.empty() || material.find_first_of(" \t\r\n\f\v") != std::string::npos)
    throw std::invalid_argument("write_mtl: the material name must be one word: \"" + material + "\"");
  if(texture_file.empty() || texture_file.find_first_of("\r\n") != std::string::npos)
    throw std::invalid_argument("write_mtl: the texture file name must be one line");
  out << "# written by diffuv\n"
      << "newmtl " << material << '\n'
      << "Ka 1 1 1\n"
      << "Kd 1 1 1\n"
      << "Ks 0 0 0\n"
      << "d 1\n"
      << "illum 1\n"
      << "map_Kd " << texture_file << '\n';
}

/// Same as above, into the file `path`, through `Atomic_output_file`.
/// \throws std::invalid_argument as above (nothing is written)
/// \throws Output_error naming `path` if the file cannot be created or written
inline void write_mtl(const std::string& path, const std::string& material, const std::string& texture_file)
{
  Atomic_output_file file(path);
  write_mtl(file.stream(), material, texture_file);
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_OUTPUT_WRITE_OBJ_H
