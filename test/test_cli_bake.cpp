// Tests of `diffuv bake`: the baked texture read back from the written files
// (the OBJ's texture coordinates, the glTF's embedded image decoded by
// tinygltf), and bad input.
#include "test_cli_tool.h"

#include <diffuv/io/read_obj_charts.h>
#include <diffuv/io/read_vertex_colors.h>
#include <diffuv/render/render_mesh.h>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace diffuv_cli_test;

// The glTF file's texture, decoded (RGB), and the PNG bytes it embeds.
struct Glb_texture {
  diffuv::Image image;
  std::string png;
};

Glb_texture glb_texture(const fs::path& glb)
{
  tinygltf::TinyGLTF reader;
  tinygltf::Model m;
  std::string err, warn;
  Glb_texture t;
  if(!reader.LoadBinaryFromFile(&m, &err, &warn, glb.string()) || m.images.size() != 1) {
    ADD_FAILURE() << "cannot read " << glb << ": " << err;
    return t;
  }
  const tinygltf::Image& image = m.images[0];
  t.image = diffuv::Image(image.width, image.height);
  for(int i = 0; i < image.width * image.height; ++i)
    for(int k = 0; k < 3; ++k)
      t.image.rgb[std::size_t(3 * i + k)] = image.image[std::size_t(image.component * i + k)];
  const auto& view = m.bufferViews.at(std::size_t(image.bufferView));
  const auto& bytes = m.buffers.at(std::size_t(view.buffer)).data;
  t.png.assign(bytes.begin() + std::ptrdiff_t(view.byteOffset), bytes.begin() + std::ptrdiff_t(view.byteOffset + view.byteLength));
  return t;
}

// Issue #22's target: the vertex colours of `diffuv correspond`'s
// transfer.ply, baked, then read from the texture (bilinear) at each of the
// OBJ's texture coordinates of the vertex, come back within 1/255 on at least
// 99 % of the vertices.
TEST_F(Tool, BakedVertexColoursOfTransferPlyReadBackAtTheVertices)
{
  ASSERT_EQ(run("segment " + data_path("meshes/elephant.off") + " -o " + path("seg")).code, 0);
  const Tool_run c = run("correspond " + path("seg/elephant.patches.ply") + " " + data_path("meshes/refined_elephant.off") +
                         " --transfer-labels -o " + path("corr"));
  ASSERT_EQ(c.code, 0) << c.err;
  const Tool_run r = run("bake " + path("corr/transfer.ply") + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // the smooth colours are data, not regions: no warning that they are not taken as regions
  EXPECT_EQ(files_in(out_dir()), (std::vector<std::string>{"transfer.colors.png", "transfer.glb", "transfer.mtl",
                                                           "transfer.obj", "transfer.png"}));
  EXPECT_NE(slurp(out_dir() / "transfer.mtl").find("map_Kd transfer.colors.png"), std::string::npos);
  const Glb_texture texture = glb_texture(out_dir() / "transfer.glb");
  EXPECT_EQ(texture.png, slurp(out_dir() / "transfer.colors.png"));
  ASSERT_EQ(texture.image.width, 1024);

  const std::vector<diffuv::Color> colors = diffuv::read_vertex_colors(path("corr/transfer.ply"));
  const diffuv::Obj_charts obj = diffuv::read_obj_charts((out_dir() / "transfer.obj").string());
  ASSERT_EQ(obj.positions.size(), colors.size());
  EXPECT_EQ(obj.faces_without_uv, 0u);
  std::vector<char> wrong(colors.size(), 0);
  for(std::size_t t = 0; t < obj.triangles.size(); ++t)
    for(std::size_t k = 0; k < 3; ++k) {
      const auto& st = obj.texcoords[obj.triangle_uv[t][k]];
      const diffuv::Rgb got = diffuv::sample_bilinear(texture.image, st[0], st[1]);
      const diffuv::Rgb want = diffuv::to_rgb(colors[obj.triangles[t][k]]);
      for(std::size_t i = 0; i < 3; ++i)
        if(std::abs(got[i] - want[i]) > 1. / 255 + 1e-9) wrong[obj.triangles[t][k]] = 1;
    }
  const auto bad = std::count(wrong.begin(), wrong.end(), 1);
  EXPECT_LE(double(bad), 0.01 * double(colors.size())) << bad << " of " << colors.size() << " vertices";
  EXPECT_NE(r.out.find("read back at the vertices (bilinear): "), std::string::npos) << r.out;
  EXPECT_EQ(png_size(out_dir() / "transfer.png"), (std::pair<std::uint32_t, std::uint32_t>(800, 600)));
}

// Normals of CGAL's refined elephant baked onto the elephant through the
// closest points: read at the vertices, the texture holds unit vectors that
// point the way the elephant's faces around them do.
TEST_F(Tool, NormalsFromAnotherMeshByClosestPoint)
{
  const Tool_run r = run("bake " + data_path("meshes/elephant.off") + " --from " + data_path("meshes/refined_elephant.off") +
                         " --what normals --resolution 512 -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("from the closest points of"), std::string::npos) << r.out;
  const Glb_texture texture = glb_texture(out_dir() / "elephant.glb");
  ASSERT_EQ(texture.image.width, 512);
  const diffuv::Obj_charts obj = diffuv::read_obj_charts((out_dir() / "elephant.obj").string());
  std::size_t corners = 0, agree = 0, unit = 0;
  for(std::size_t t = 0; t < obj.triangles.size(); ++t) {
    const auto& a = obj.positions[obj.triangles[t][0]];
    const auto& b = obj.positions[obj.triangles[t][1]];
    const auto& c = obj.positions[obj.triangles[t][2]];
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(!(nn > 0.)) continue;
    for(std::size_t k = 0; k < 3; ++k) {
      const auto& st = obj.texcoords[obj.triangle_uv[t][k]];
      const diffuv::Rgb c8 = diffuv::sample_bilinear(texture.image, st[0], st[1]);
      const double m[3] = {2. * c8[0] - 1., 2. * c8[1] - 1., 2. * c8[2] - 1.};
      const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
      unit += std::abs(length - 1.) <= 0.05 ? 1 : 0;  // not where crowded vertices mix their normals in a texel
      ++corners;
      agree += (m[0] * n[0] + m[1] * n[1] + m[2] * n[2]) / (length * nn) > 0. ? 1 : 0;
    }
  }
  EXPECT_GT(corners, 10000u);
  EXPECT_GT(double(agree), 0.97 * double(corners));
  EXPECT_GT(double(unit), 0.99 * double(corners));
}

// Bad input: a clear message, the right exit code, no output folder.
TEST_F(Tool, BakeRefusesWhatItCannotBake)
{
  struct Case {
    std::string args;
    int code;
    std::string says;
  };
  const std::string cow = data_path("meshes/cow.off");
  write("three.txt", "1\n2\n3\n");
  // cow moved by twice its size: not the same object in the same place.
  {
    const diffuv_test::File_soup soup = diffuv_test::parse_off(cow);
    std::ostringstream moved;
    moved << "OFF\n" << soup.points.size() << ' ' << soup.faces.size() << " 0\n";
    for(const auto& p : soup.points) moved << p[0] + 2. << ' ' << p[1] << ' ' << p[2] << '\n';
    for(const auto& f : soup.faces) moved << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
    write("moved.off", moved.str());
  }
  write("values.txt", "1 2\n");
  const std::vector<Case> cases = {
      {"bake " + cow, 1, "has no vertex or face colours"},
      {"bake " + cow + " --what labels", 1, "has no regions to bake"},
      {"bake " + cow + " --what values", 2, "values needs --values FILE"},
      {"bake " + cow + " --values " + path("three.txt"), 1, "the file has 3 rows"},
      {"bake " + cow + " --values " + path("missing.txt"), 1, "cannot open file"},
      {"bake " + cow + " --values " + path("three.txt") + " --what normals", 2, "does not go with --what normals"},
      {"bake " + cow + " --what normals --from " + path("missing.off"), 1, "missing.off"},
      {"bake " + cow + " --what normals --resolution 16", 2, "do not fit in 16 x 16 texels"},
      {"bake " + cow + " --what normals --from " + path("moved.off"), 1, "does not lie on"},
      {"bake " + cow + " --what paint", 2, "--what"},
      {"bake", 2, "mesh is required"},
  };
  for(const Case& c : cases) {
    const Tool_run r = run(c.args + " -o " + out_dir().string());
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out_dir())) << c.args;
  }
}

// Values: a per-vertex scalar (here each point's x) baked as grey, lowest
// black and highest white, read back at the vertices like colours.
TEST_F(Tool, BakeValuesAsGrey)
{
  const std::string cow = data_path("meshes/cow.off");
  const diffuv_test::File_soup soup = diffuv_test::parse_off(cow);
  std::string values = "# x of each point\n";
  double low = soup.points[0][0], high = low;
  for(const auto& p : soup.points) {
    values += std::to_string(p[0]) + "\n";
    low = std::min(low, p[0]);
    high = std::max(high, p[0]);
  }
  const Tool_run r = run("bake " + cow + " --values " + write("x.txt", values) + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out_dir() / "cow.values.png"));
  const diffuv::Image image = glb_texture(out_dir() / "cow.glb").image;
  const diffuv::Obj_charts obj = diffuv::read_obj_charts((out_dir() / "cow.obj").string());
  std::vector<char> wrong(soup.points.size(), 0);
  for(std::size_t t = 0; t < obj.triangles.size(); ++t)
    for(std::size_t k = 0; k < 3; ++k) {
      const auto& st = obj.texcoords[obj.triangle_uv[t][k]];
      const diffuv::Rgb got = diffuv::sample_bilinear(image, st[0], st[1]);
      EXPECT_EQ(got[0], got[1]);
      EXPECT_EQ(got[1], got[2]);
      const double want = std::round(255. * (std::stod(std::to_string(soup.points[obj.triangles[t][k]][0])) - low) /
                                     (high - low)) / 255.;
      if(std::abs(got[0] - want) > 1. / 255 + 1e-9) wrong[obj.triangles[t][k]] = 1;
    }
  // cow's squeezed charts crowd some vertices within a texel (see BakeTexture.VertexColoursReadBackAtTheVertices).
  EXPECT_LE(double(std::count(wrong.begin(), wrong.end(), 1)), 0.15 * double(wrong.size()));
}

} // namespace
