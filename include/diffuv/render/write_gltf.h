// diffuv: a textured mesh as a binary glTF 2.0 file (GLB), through tinygltf.
//
// glTF is what three.js, Blender and game engines load. Its attributes are
// per vertex, so a vertex on a seam (one (u,v) in each chart) becomes one
// glTF vertex per distinct (u,v), as in the OBJ writer (output/write_obj.h).
// The file is self-contained: the buffer holds positions, normals, texture
// coordinates, indices and the PNG texture itself.
//
// Needs Debian's libtinygltf-dev (link `TinyGLTF::TinyGLTF`, which also
// brings its JSON and image code); the rest of diffuv does not.
#ifndef DIFFUV_RENDER_WRITE_GLTF_H
#define DIFFUV_RENDER_WRITE_GLTF_H

#include <diffuv/io/atomic_file.h>
#include <diffuv/render/render_mesh.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace diffuv {

/// What `write_glb()` puts beside the mesh.
struct Gltf_options {
  /// The texture as PNG file bytes (e.g. from `write_png()` into a string
  /// stream), embedded in the file; empty: no texture, the textured faces
  /// get a plain white material.
  std::string png;
  std::string name = "diffuv";  ///< the mesh's and the node's name
  /// The mesh's up axis. glTF's is +y: for z (or x) up the node is turned
  /// (-90 degrees about x, or 90 about z) so that viewers show the mesh
  /// upright; the vertex data stay the mesh's own coordinates.
  Up_axis up = Up_axis::y;
};

namespace internal {

// Appends `values` to the buffer, 4-byte aligned, as a new buffer view.
template <class T>
int append_buffer_view(tinygltf::Model& model, const std::vector<T>& values, int target)
{
  auto& data = model.buffers[0].data;
  data.resize((data.size() + 3) / 4 * 4, 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  const std::size_t at = data.size();
  data.resize(at + view.byteLength);
  if(view.byteLength > 0) std::memcpy(data.data() + at, values.data(), view.byteLength);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size() - 1);
}

inline int add_accessor(tinygltf::Model& model, int view, int component_type, int type, std::size_t count)
{
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size() - 1);
}

} // namespace internal

/// Writes `tm` with per-corner texture coordinates as a binary glTF 2.0 file
/// (GLB) to `out`.
///
/// One node, one mesh with up to two triangle primitives: the faces whose
/// corners all have a finite uv (with TEXCOORD_0 and a material whose base
/// colour is the texture), and the others (no texture coordinates, the
/// default material). Each vertex of `tm` becomes one glTF vertex per
/// distinct uv it has in the faces around it; normals are the area-weighted
/// normals of the faces around each vertex of `tm` (the same on both sides of
/// a seam, so the shading shows no seam). glTF's texture origin is the
/// image's top left, so a uv (u, v) with v up is written as (u, 1 - v).
/// Faces with more than three corners are split into fans.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
/// \tparam VertexPointMap a `ReadablePropertyMap` from `vertex_descriptor` to a 3D point
/// \tparam CornerUvMap a `ReadablePropertyMap` from `halfedge_descriptor` to a
///         2D point: the uv of the corner `target(h)` in `face(h)` (v up, as in OBJ)
/// \returns whether tinygltf wrote the file (the stream's state tells whether writing succeeded)
/// \throws std::length_error if the mesh needs more than 2^32 - 1 glTF vertices
template <class TriangleMesh, class VertexPointMap, class CornerUvMap>
bool write_glb(std::ostream& out, const TriangleMesh& tm, VertexPointMap vpm, CornerUvMap corner_uv,
               const Gltf_options& options = Gltf_options())
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  static_assert(std::is_convertible<halfedge_descriptor, typename boost::property_traits<CornerUvMap>::key_type>::value,
                "write_glb: CornerUvMap must be keyed by the halfedge_descriptor of TriangleMesh");

  std::unordered_map<vertex_descriptor, std::size_t> number;
  number.reserve(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm)) number.emplace(v, number.size());
  auto point = [&](vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return std::array<double, 3>{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  // Area-weighted vertex normals: the sum of the (unnormalised) cross
  // products of the triangles of each face's fan.
  std::vector<std::array<double, 3>> normal(number.size(), {0., 0., 0.});
  std::vector<vertex_descriptor> corner;  // of one face; reused, as the vectors below
  for(face_descriptor f : faces(tm)) {
    corner.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) corner.push_back(target(h, tm));
    std::array<double, 3> n{0., 0., 0.};
    const auto a = point(corner[0]);
    for(std::size_t k = 1; k + 1 < corner.size(); ++k) {
      const auto b = point(corner[k]), c = point(corner[k + 1]);
      const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
      const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
      n[0] += uy * vz - uz * vy;
      n[1] += uz * vx - ux * vz;
      n[2] += ux * vy - uy * vx;
    }
    for(vertex_descriptor v : corner)
      for(int i = 0; i < 3; ++i) normal[number.at(v)][i] += n[i];
  }

  // glTF vertices: (vertex, uv) pairs, in the order the faces first use them.
  struct Known { float s, t; std::uint32_t index; bool textured; };
  std::vector<std::vector<Known>> known(number.size());
  std::vector<float> positions, normals, texcoords;
  std::vector<std::uint32_t> textured_indices, plain_indices;
  auto glTF_vertex = [&](vertex_descriptor v, bool textured, float s, float t) {
    const std::size_t i = number.at(v);
    for(const Known& k : known[i])
      if(k.textured == textured && (!textured || (k.s == s && k.t == t))) return k.index;
    if(positions.size() / 3 >= std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("write_glb: more than 2^32 - 1 glTF vertices");
    const auto index = static_cast<std::uint32_t>(positions.size() / 3);
    const auto p = point(v);
    const auto& n = normal[i];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for(int k = 0; k < 3; ++k) {
      positions.push_back(static_cast<float>(p[k]));
      // A vertex on no face of positive area: any unit normal will do.
      normals.push_back(length > 0 ? static_cast<float>(n[k] / length) : (k == 2 ? 1.f : 0.f));
    }
    texcoords.push_back(s);
    texcoords.push_back(t);
    known[i].push_back(Known{s, t, index, textured});
    return index;
  };
  std::vector<std::pair<vertex_descriptor, std::array<double, 2>>> corner_uvs;
  std::vector<std::uint32_t> index;
  for(face_descriptor f : faces(tm)) {
    corner_uvs.clear();
    bool textured = true;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const auto uv = get(corner_uv, h);
      const double u = CGAL::to_double(uv.x()), v = CGAL::to_double(uv.y());
      textured = textured && std::isfinite(u) && std::isfinite(v);
      corner_uvs.push_back({target(h, tm), {u, v}});
    }
    index.clear();
    for(const auto& [v, uv] : corner_uvs)
      index.push_back(textured ? glTF_vertex(v, true, static_cast<float>(uv[0]), static_cast<float>(1. - uv[1]))
                               : glTF_vertex(v, false, 0.f, 0.f));
    auto& indices = textured ? textured_indices : plain_indices;
    for(std::size_t k = 1; k + 1 < index.size(); ++k) {
      indices.push_back(index[0]);
      indices.push_back(index[k]);
      indices.push_back(index[k + 1]);
    }
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "diffuv";
  model.buffers.resize(1);
  const std::size_t count = positions.size() / 3;
  const int position_view = internal::append_buffer_view(model, positions, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int position = internal::add_accessor(model, position_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
  // POSITION needs its bounds.
  std::vector<double> lo(3, 0.), hi(3, 0.);
  for(std::size_t k = 0; k < 3 && count > 0; ++k) {
    lo[k] = hi[k] = positions[k];
    for(std::size_t i = 0; i < count; ++i) {
      lo[k] = std::min<double>(lo[k], positions[3 * i + k]);
      hi[k] = std::max<double>(hi[k], positions[3 * i + k]);
    }
  }
  model.accessors[static_cast<std::size_t>(position)].minValues = lo;
  model.accessors[static_cast<std::size_t>(position)].maxValues = hi;
  const int normal_accessor = internal::add_accessor(
      model, internal::append_buffer_view(model, normals, TINYGLTF_TARGET_ARRAY_BUFFER), TINYGLTF_COMPONENT_TYPE_FLOAT,
      TINYGLTF_TYPE_VEC3, count);

  tinygltf::Mesh mesh;
  mesh.name = options.name;
  if(!textured_indices.empty()) {
    const int uv = internal::add_accessor(
        model, internal::append_buffer_view(model, texcoords, TINYGLTF_TARGET_ARRAY_BUFFER), TINYGLTF_COMPONENT_TYPE_FLOAT,
        TINYGLTF_TYPE_VEC2, count);
    tinygltf::Material material;
    material.name = options.name;
    material.pbrMetallicRoughness.metallicFactor = 0.;  // a painted surface, not a metal
    material.pbrMetallicRoughness.roughnessFactor = 1.;
    if(!options.png.empty()) {
      tinygltf::Image image;
      image.mimeType = "image/png";
      // Image data: a buffer view without target.
      image.bufferView = internal::append_buffer_view(model, std::vector<char>(options.png.begin(), options.png.end()), 0);
      model.images.push_back(image);
      tinygltf::Sampler sampler;
      sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
      sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
      sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
      model.samplers.push_back(sampler);
      tinygltf::Texture texture;
      texture.source = 0;
      texture.sampler = 0;
      model.textures.push_back(texture);
      material.pbrMetallicRoughness.baseColorTexture.index = 0;
    }
    model.materials.push_back(material);
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = position;
    primitive.attributes["NORMAL"] = normal_accessor;
    primitive.attributes["TEXCOORD_0"] = uv;
    primitive.material = 0;
    primitive.indices = internal::add_accessor(
        model, internal::append_buffer_view(model, textured_indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, textured_indices.size());
    mesh.primitives.push_back(primitive);
  }
  if(!plain_indices.empty()) {
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = position;
    primitive.attributes["NORMAL"] = normal_accessor;
    primitive.indices = internal::add_accessor(
        model, internal::append_buffer_view(model, plain_indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, plain_indices.size());
    mesh.primitives.push_back(primitive);
  }
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = options.name;
  const double half = std::sqrt(0.5);  // sin and cos of 45 degrees
  if(options.up == Up_axis::z) node.rotation = {-half, 0., 0., half};  // (x, y, z) -> (x, z, -y)
  if(options.up == Up_axis::x) node.rotation = {0., 0., half, half};   // (x, y, z) -> (-y, x, z)
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  model.buffers[0].data.resize((model.buffers[0].data.size() + 3) / 4 * 4, 0);
  tinygltf::TinyGLTF writer;
  return writer.WriteGltfSceneToStream(&model, out, false, true);
}

/// Same as above, into the file `path`, through `Atomic_output_file`: on
/// error, an existing file at `path` is left as it was.
/// \throws Output_error naming `path` if the file cannot be created or written
template <class TriangleMesh, class VertexPointMap, class CornerUvMap>
void write_glb(const std::string& path, const TriangleMesh& tm, VertexPointMap vpm, CornerUvMap corner_uv,
               const Gltf_options& options = Gltf_options())
{
  Atomic_output_file file(path);
  if(!write_glb(file.stream(), tm, vpm, corner_uv, options)) throw Output_error(path, "glTF encoding failed");
  file.commit();
}

} // namespace diffuv

#endif // DIFFUV_RENDER_WRITE_GLTF_H
