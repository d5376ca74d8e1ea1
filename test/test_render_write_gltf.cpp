// Tests of the glTF writer (render/write_gltf.h): a GLB read back with
// tinygltf's own reader gives the mesh's points, faces and texture
// coordinates, one glTF vertex per distinct (vertex, uv), and the texture.
#include "test_data.h"

#include <diffuv/render/texture.h>
#include <diffuv/render/write_gltf.h>

#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace {

using Uv_point = CGAL::Simple_cartesian<double>::Point_2;
using Gltf_mesh = diffuv_test::Mesh;
using Gltf_halfedge = Gltf_mesh::Halfedge_index;

// An n x n grid of squares split into triangles, in the plane z = 0, with
// two charts: the left half and the right half, the right one moved by
// (2, 0) so that the middle column of vertices has two uv.
struct Grid {
  Gltf_mesh mesh;
  Gltf_mesh::Property_map<Gltf_halfedge, Uv_point> uv;
};

Grid two_chart_grid(int n)
{
  Grid g;
  std::vector<Gltf_mesh::Vertex_index> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) v.push_back(g.mesh.add_vertex(diffuv_test::Point_3(i, j, 0)));
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const auto a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1], c = v[(j + 1) * (n + 1) + i + 1],
                 d = v[(j + 1) * (n + 1) + i];
      g.mesh.add_face(a, b, c);
      g.mesh.add_face(a, c, d);
    }
  g.uv = g.mesh.add_property_map<Gltf_halfedge, Uv_point>("h:uv").first;
  for(auto f : faces(g.mesh)) {
    double cx = 0;
    for(auto w : vertices_around_face(halfedge(f, g.mesh), g.mesh)) cx += g.mesh.point(w).x() / 3;
    const bool right = cx > n / 2.;
    for(auto h : halfedges_around_face(halfedge(f, g.mesh), g.mesh)) {
      const auto& p = g.mesh.point(target(h, g.mesh));
      g.uv[h] = Uv_point(p.x() / n / 4 + (right ? 0.5 : 0.), p.y() / n);
    }
  }
  return g;
}

tinygltf::Model read_back(const std::string& bytes)
{
  tinygltf::TinyGLTF reader;
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = reader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned int>(bytes.size()));
  EXPECT_TRUE(ok) << err;
  EXPECT_TRUE(err.empty()) << err;
  return model;
}

// The accessor's elements as doubles (float or unsigned int components).
std::vector<double> accessor_values(const tinygltf::Model& m, int index)
{
  const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(index));
  const tinygltf::BufferView& view = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const unsigned char* data = m.buffers.at(static_cast<std::size_t>(view.buffer)).data.data() + view.byteOffset + a.byteOffset;
  const std::size_t components = a.type == TINYGLTF_TYPE_VEC3 ? 3 : a.type == TINYGLTF_TYPE_VEC2 ? 2 : 1;
  std::vector<double> out;
  for(std::size_t i = 0; i < a.count * components; ++i) {
    if(a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
      float x;
      std::memcpy(&x, data + 4 * i, 4);
      out.push_back(x);
    } else {
      std::uint32_t x;
      std::memcpy(&x, data + 4 * i, 4);
      out.push_back(x);
    }
  }
  return out;
}

} // namespace

TEST(WriteGltf, AGridReadsBackWithItsSeamAndTexture)
{
  const int n = 4;
  const Grid g = two_chart_grid(n);
  std::ostringstream png;
  ASSERT_TRUE(diffuv::write_png(png, 32, 16, std::vector<unsigned char>(32 * 16 * 3, 200)));
  diffuv::Gltf_options options;
  options.png = png.str();
  std::ostringstream out;
  ASSERT_TRUE(diffuv::write_glb(out, g.mesh, g.mesh.points(), g.uv, options));
  const tinygltf::Model m = read_back(out.str());
  ASSERT_EQ(m.meshes.size(), 1u);
  ASSERT_EQ(m.meshes[0].primitives.size(), 1u);  // every face has a uv
  const tinygltf::Primitive& p = m.meshes[0].primitives[0];
  ASSERT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
  const auto position = accessor_values(m, p.attributes.at("POSITION"));
  const auto normal = accessor_values(m, p.attributes.at("NORMAL"));
  const auto texcoord = accessor_values(m, p.attributes.at("TEXCOORD_0"));
  const auto index = accessor_values(m, p.indices);
  // (n+1)^2 vertices, and the middle column twice (one uv in each chart).
  const std::size_t count = position.size() / 3;
  EXPECT_EQ(count, static_cast<std::size_t>((n + 1) * (n + 1) + (n + 1)));
  ASSERT_EQ(texcoord.size(), 2 * count);
  ASSERT_EQ(index.size(), 3 * num_faces(g.mesh));
  // Each glTF triangle is a face of the grid, with the face's uv (v flipped:
  // glTF's texture origin is the top left).
  std::map<std::array<double, 6>, std::array<double, 6>> uv_of_face;  // corner points -> corner uv, from the smallest point
  auto key = [](std::array<std::array<double, 2>, 3> xy, std::array<std::array<double, 2>, 3> st) {
    std::size_t first = 0;
    for(std::size_t k = 1; k < 3; ++k)
      if(xy[k] < xy[first]) first = k;
    std::array<double, 6> a{}, b{};
    for(std::size_t k = 0; k < 3; ++k) {
      a[2 * k] = xy[(first + k) % 3][0];
      a[2 * k + 1] = xy[(first + k) % 3][1];
      b[2 * k] = st[(first + k) % 3][0];
      b[2 * k + 1] = st[(first + k) % 3][1];
    }
    return std::make_pair(a, b);
  };
  for(auto f : faces(g.mesh)) {
    std::array<std::array<double, 2>, 3> xy{}, st{};
    std::size_t k = 0;
    for(auto h : halfedges_around_face(halfedge(f, g.mesh), g.mesh)) {
      xy[k] = {g.mesh.point(target(h, g.mesh)).x(), g.mesh.point(target(h, g.mesh)).y()};
      st[k] = {g.uv[h].x(), 1. - g.uv[h].y()};
      ++k;
    }
    const auto [a, b] = key(xy, st);
    uv_of_face[a] = b;
  }
  std::set<std::array<double, 6>> seen;
  for(std::size_t t = 0; t < index.size() / 3; ++t) {
    std::array<std::array<double, 2>, 3> xy{}, st{};
    for(std::size_t k = 0; k < 3; ++k) {
      const auto i = static_cast<std::size_t>(index[3 * t + k]);
      ASSERT_LT(i, count);
      EXPECT_EQ(position[3 * i + 2], 0.);
      xy[k] = {position[3 * i], position[3 * i + 1]};
      st[k] = {texcoord[2 * i], texcoord[2 * i + 1]};
      EXPECT_NEAR(normal[3 * i + 2], 1., 1e-6);  // the faces turn counter-clockwise seen from +z
    }
    const auto [a, b] = key(xy, st);
    ASSERT_TRUE(uv_of_face.count(a)) << "triangle " << t << " is no face of the grid";
    EXPECT_TRUE(seen.insert(a).second) << "triangle " << t << " twice";
    for(std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(b[k], uv_of_face[a][k], 1e-6) << "triangle " << t;
  }
  // POSITION carries its bounds; the texture is the PNG given, decoded by tinygltf.
  const auto& bounds = m.accessors[static_cast<std::size_t>(p.attributes.at("POSITION"))];
  EXPECT_EQ(bounds.minValues, (std::vector<double>{0., 0., 0.}));
  EXPECT_EQ(bounds.maxValues, (std::vector<double>{double(n), double(n), 0.}));
  ASSERT_EQ(p.material, 0);
  ASSERT_EQ(m.materials[0].pbrMetallicRoughness.baseColorTexture.index, 0);
  ASSERT_EQ(m.textures.size(), 1u);
  ASSERT_EQ(m.images.size(), 1u);
  EXPECT_EQ(m.images[0].mimeType, "image/png");
  EXPECT_EQ(m.images[0].width, 32);
  EXPECT_EQ(m.images[0].height, 16);
  // glTF is y-up: a z-up mesh's node is turned -90 degrees about x, so that
  // (x, y, z) is seen at (x, z, -y); the vertex data stay as they were.
  ASSERT_EQ(m.nodes.size(), 1u);
  EXPECT_TRUE(m.nodes[0].rotation.empty());
  options.up = diffuv::Up_axis::z;
  std::ostringstream z_up;
  ASSERT_TRUE(diffuv::write_glb(z_up, g.mesh, g.mesh.points(), g.uv, options));
  const tinygltf::Model turned = read_back(z_up.str());
  const double h = std::sqrt(0.5);
  ASSERT_EQ(turned.nodes.at(0).rotation.size(), 4u);
  EXPECT_NEAR(turned.nodes[0].rotation[0], -h, 1e-12);
  EXPECT_NEAR(turned.nodes[0].rotation[3], h, 1e-12);
  EXPECT_EQ(accessor_values(turned, turned.meshes[0].primitives[0].attributes.at("POSITION")), position);
}

using WriteGltfFile = diffuv_test::Temp_dir_test;

TEST_F(WriteGltfFile, FacesWithoutUvGoToAPrimitiveWithoutTexture)
{
  Grid g = two_chart_grid(2);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto f0 = *faces(g.mesh).begin();
  for(auto h : halfedges_around_face(halfedge(f0, g.mesh), g.mesh)) g.uv[h] = Uv_point(nan, nan);
  std::ostringstream out;
  ASSERT_TRUE(diffuv::write_glb(out, g.mesh, g.mesh.points(), g.uv));
  const tinygltf::Model m = read_back(out.str());
  ASSERT_EQ(m.meshes.at(0).primitives.size(), 2u);
  const auto& textured = m.meshes[0].primitives[0];
  const auto& plain = m.meshes[0].primitives[1];
  EXPECT_EQ(accessor_values(m, textured.indices).size(), 3 * (num_faces(g.mesh) - 1));
  EXPECT_EQ(accessor_values(m, plain.indices).size(), 3u);
  EXPECT_EQ(plain.attributes.count("TEXCOORD_0"), 0u);
  EXPECT_EQ(plain.material, -1);
  EXPECT_TRUE(m.images.empty());  // no PNG given: a plain material
  // The file on disk is written whole or not at all.
  diffuv::write_glb(path("grid.glb"), g.mesh, g.mesh.points(), g.uv);
  std::ifstream in(path("grid.glb"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes, out.str());
  EXPECT_THROW(diffuv::write_glb("/nonexistent-folder/grid.glb", g.mesh, g.mesh.points(), g.uv), diffuv::Output_error);
}
