// Tests of `diffuv param`: the uv table, OBJ and pictures it writes, patches
// that cannot be mapped, --strict, --threads.
#include "test_cli_tool.h"

#include <diffuv/io/read_obj_charts.h>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace diffuv_cli_test;

TEST_F(Tool, NefertitiWithSquareCornersLandsOnTheUnitSquare)
{
  const Tool_run r = run("param " + nefertiti_with_square_corners() + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("299 vertices, 562 faces"), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "nefertiti.uv.csv");
  ASSERT_EQ(rows.size(), 300u); // header + one row per vertex (one patch)
  EXPECT_EQ(rows[0], (std::vector<std::string>{"vertex", "patch", "u", "v"}));
  for(std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 4u);
    const double u = std::stod(rows[i][2]), v = std::stod(rows[i][3]);
    EXPECT_GE(u, 0.);
    EXPECT_LE(u, 1.);
    EXPECT_GE(v, 0.);
    EXPECT_LE(v, 1.);
  }
  // square_corners.selection.txt lists 133 8 0 287: 133 is at (0,0), the
  // others counter-clockwise along the border.
  auto uv_of = [&](std::size_t vertex) { return std::make_pair(std::stod(rows[vertex + 1][2]), std::stod(rows[vertex + 1][3])); };
  EXPECT_EQ(uv_of(133), std::make_pair(0., 0.));
  std::vector<std::pair<double, double>> others = {uv_of(8), uv_of(0), uv_of(287)};
  std::sort(others.begin(), others.end());
  EXPECT_EQ(others, (std::vector<std::pair<double, double>>{{0., 1.}, {1., 0.}, {1., 1.}}));

  const std::string obj = slurp(out_dir() / "nefertiti.obj");
  std::size_t v = 0, f = 0, vt = 0;
  std::stringstream ss(obj);
  std::string line;
  while(std::getline(ss, line)) {
    if(line.rfind("v ", 0) == 0) ++v;
    if(line.rfind("vt ", 0) == 0) ++vt;
    if(line.rfind("f ", 0) == 0) ++f;
  }
  EXPECT_EQ(v, 299u);
  EXPECT_EQ(vt, 299u); // one chart: one vt per vertex
  EXPECT_EQ(f, 562u);
}

// The OBJ's charts are packed side by side into one texture (issue #22):
// read back, every texture coordinate lies in [0,1]^2, the charts' boxes are
// pairwise apart by at least the gutters, and the summary says how much of
// the texture they cover. --stacked draws them all from the origin instead.
TEST_F(Tool, TheObjChartsArePackedIntoOneTexture)
{
  const Tool_run r = run("param " + data_path("meshes/cow.off") + " --texture-size 512 --gutter 3 -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto covered_share = [](const std::string& out, const std::string& packer) {
    const std::string said = " charts packed into 512 x 512 texels (gutter 3, " + packer + "): ";
    const std::size_t at = out.find(said);
    return at == std::string::npos ? -1. : std::stod(out.substr(at + said.size()));
  };
  const double covered = covered_share(r.out, "shelves");
  EXPECT_GT(covered, 50.) << r.out;
  EXPECT_LT(covered, 100.);
  // stb's skyline, kept for comparison, leaves more of the texture empty;
  // an unknown packer is refused.
  const Tool_run skyline = run("param " + data_path("meshes/cow.off") +
                               " --texture-size 512 --gutter 3 --packer skyline --outputs obj -o " +
                               (out_dir() / "skyline").string());
  ASSERT_EQ(skyline.code, 0) << skyline.err;
  EXPECT_GT(covered_share(skyline.out, "skyline"), 50.) << skyline.out;
  EXPECT_LT(covered_share(skyline.out, "skyline"), covered);
  const Tool_run unknown = run("param " + data_path("meshes/cow.off") + " --packer best -o " +
                               (out_dir() / "unknown").string());
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("--packer"), std::string::npos) << unknown.err;
  const diffuv::Obj_charts obj = diffuv::read_obj_charts((out_dir() / "cow.obj").string());
  ASSERT_GT(obj.number_of_charts, 10u);
  std::vector<std::array<double, 4>> box(obj.number_of_charts, {1e9, 1e9, -1e9, -1e9}); // texels
  for(std::size_t t = 0; t < obj.triangles.size(); ++t)
    for(std::size_t k : obj.triangle_uv[t]) {
      const auto& q = obj.texcoords[k];
      ASSERT_TRUE(q[0] >= 0 && q[0] <= 1 && q[1] >= 0 && q[1] <= 1) << q[0] << ' ' << q[1];
      auto& b = box[obj.chart[t]];
      b = {std::min(b[0], 512 * q[0]), std::min(b[1], 512 * q[1]), std::max(b[2], 512 * q[0]), std::max(b[3], 512 * q[1])};
    }
  // The OBJ's charts are its connected pieces of texture coordinates: the
  // packed ones never touch, so each is one patch's chart, a gutter (3
  // texels) from any other and half of one from the texture's edges.
  for(std::size_t a = 0; a < box.size(); ++a) {
    EXPECT_GE(std::min(box[a][0], box[a][1]), 1.5 - 1e-6) << "chart " << a;
    EXPECT_LE(std::max(box[a][2], box[a][3]), 512 - 1.5 + 1e-6) << "chart " << a;
    for(std::size_t b = a + 1; b < box.size(); ++b) {
      const double gap = std::max({box[b][0] - box[a][2], box[a][0] - box[b][2], box[b][1] - box[a][3], box[a][1] - box[b][3]});
      EXPECT_GE(gap, 3. - 1e-6) << "charts " << a << " and " << b;
    }
  }

  const Tool_run stacked = run("param " + data_path("meshes/cow.off") + " --stacked -o " + (out_dir() / "stacked").string());
  ASSERT_EQ(stacked.code, 0) << stacked.err;
  EXPECT_EQ(stacked.out.find("charts packed"), std::string::npos) << stacked.out;
  const diffuv::Obj_charts on_top = diffuv::read_obj_charts((out_dir() / "stacked" / "cow.obj").string());
  std::size_t from_origin = 0;
  for(std::size_t t = 0; t < on_top.triangles.size(); ++t)
    for(std::size_t k : on_top.triangle_uv[t]) from_origin += on_top.texcoords[k][0] == 0 && on_top.texcoords[k][1] == 0;
  EXPECT_GT(from_origin, 100u); // every chart has a corner at (0,0)

  // Packing's options with charts that are not packed: a usage error.
  for(const char* both : {"--stacked --texture-size 64", "--unit-squares --gutter 3", "--unit-squares --stacked"}) {
    const Tool_run refused = run("param " + data_path("meshes/cow.off") + " " + both + " -o " + (out_dir() / "both").string());
    EXPECT_EQ(refused.code, 2) << both;
    EXPECT_NE(refused.err.find("excludes"), std::string::npos) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(out_dir() / "both"));
  }

  // Gutters the texture cannot hold: a usage error naming the options.
  const Tool_run tight = run("param " + data_path("meshes/cow.off") + " --texture-size 16 -o " + (out_dir() / "tight").string());
  EXPECT_EQ(tight.code, 2) << tight.err;
  EXPECT_NE(tight.err.find("raise --texture-size or lower --gutter"), std::string::npos) << tight.err;
  EXPECT_FALSE(std::filesystem::exists(out_dir() / "tight"));
}

TEST_F(Tool, TheGlbFileHoldsTheObjsMeshTextureCoordinatesAndTexture)
{
  const Tool_run r = run("param " + data_path("meshes/cow.off") + " --outputs obj,glb -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("cow.glb"), std::string::npos) << r.out;
  tinygltf::TinyGLTF reader;
  tinygltf::Model m;
  std::string err, warn;
  ASSERT_TRUE(reader.LoadBinaryFromFile(&m, &err, &warn, (out_dir() / "cow.glb").string())) << err;
  const diffuv::Obj_charts obj = diffuv::read_obj_charts((out_dir() / "cow.obj").string());
  ASSERT_EQ(m.meshes.size(), 1u);
  ASSERT_EQ(m.meshes[0].primitives.size(), 1u);  // every face is in a chart
  const auto& p = m.meshes[0].primitives[0];
  // One glTF vertex per OBJ `vt` (both split a vertex per distinct uv), and
  // the same triangles: each glTF corner has its OBJ corner's point and uv
  // (v flipped: glTF's texture origin is the image's top left).
  const tinygltf::Accessor& uv = m.accessors.at(p.attributes.at("TEXCOORD_0"));
  const tinygltf::Accessor& xyz = m.accessors.at(p.attributes.at("POSITION"));
  const tinygltf::Accessor& index = m.accessors.at(p.indices);
  EXPECT_EQ(uv.count, obj.texcoords.size());
  ASSERT_EQ(index.count, 3 * obj.triangles.size());
  auto data = [&](const tinygltf::Accessor& a) {
    const auto& view = m.bufferViews.at(a.bufferView);
    return m.buffers.at(view.buffer).data.data() + view.byteOffset + a.byteOffset;
  };
  const auto* st = reinterpret_cast<const float*>(data(uv));
  const auto* points = reinterpret_cast<const float*>(data(xyz));
  const auto* corners = reinterpret_cast<const std::uint32_t*>(data(index));
  for(std::size_t t = 0; t < obj.triangles.size(); ++t)
    for(std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t i = corners[3 * t + k];
      const auto& q = obj.texcoords[obj.triangle_uv[t][k]];
      ASSERT_NEAR(st[2 * i], q[0], 1e-6) << "triangle " << t;
      ASSERT_NEAR(st[2 * i + 1], 1. - q[1], 1e-6) << "triangle " << t;
      for(std::size_t c = 0; c < 3; ++c) ASSERT_NEAR(points[3 * i + c], obj.positions[obj.triangles[t][k]][c], 1e-5);
    }
  ASSERT_EQ(m.images.size(), 1u);  // the OBJ's checker texture, in the file
  EXPECT_EQ(m.images[0].width, 1024);  // the texture the charts are packed into (--texture-size)
  std::ifstream png(out_dir() / "cow.checker.png", std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(png)), std::istreambuf_iterator<char>());
  const auto& view = m.bufferViews.at(m.images[0].bufferView);
  const auto* embedded = m.buffers.at(view.buffer).data.data() + view.byteOffset;
  EXPECT_TRUE(view.byteLength == bytes.size() && std::equal(bytes.begin(), bytes.end(), embedded));
}

TEST_F(Tool, TheAtlasPictureIsTheTextureAtItsSize)
{
  const Tool_run r = run("param " + data_path("meshes/cow.off") + " --outputs atlas --texture-size 300 -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(png_size(out_dir() / "cow.atlas.png"), (std::pair<std::uint32_t, std::uint32_t>{300, 300}));
  EXPECT_EQ(files_in(out_dir()), std::vector<std::string>{"cow.atlas.png"});  // only what --outputs names
}

TEST_F(Tool, ClosedMeshesAreCutIntoPatchesAndEveryVertexIsMapped)
{
  const Tool_run r = run("param " + data_path("meshes/cow.off") + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("fmm distances: automatic"), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "cow.uv.csv");
  std::set<std::size_t> mapped;
  for(std::size_t i = 1; i < rows.size(); ++i) {
    mapped.insert(std::stoul(rows[i][0]));
    const double u = std::stod(rows[i][2]), v = std::stod(rows[i][3]);
    EXPECT_TRUE(u >= 0 && u <= 1 && v >= 0 && v <= 1) << rows[i][0];
  }
  EXPECT_EQ(mapped.size(), diffuv_test::cgal_mesh("cow.off").number_of_vertices());
  EXPECT_GT(rows.size() - 1, mapped.size()); // patch-border vertices have a row per patch

  // The textured OBJ and the picture.
  EXPECT_EQ(slurp(out_dir() / "cow.obj").rfind("mtllib cow.mtl\n", 0), 0u);
  EXPECT_NE(slurp(out_dir() / "cow.mtl").find("map_Kd cow.checker.png"), std::string::npos);
  for(const char* png : {"cow.png", "cow.checker.png"})
    EXPECT_EQ(slurp(out_dir() / png).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << png;
}

// --threads changes nothing but the time (with more than one, the picture is
// made on a second thread while the other files are written): every file the
// same byte for byte. The summary says how long each stage took.
TEST_F(Tool, ThreadsGiveTheSameFilesAndStagesAreTimed)
{
  const char* const written[] = {"man.uv.csv", "man.png", "man.obj", "man.glb", "man.patches.txt", "man.checker.png"};
  std::string tables[2];
  std::vector<std::string> files[2];
  for(int k = 0; k < 2; ++k) {
    const std::string dir = (out_dir() / std::to_string(k)).string();
    const Tool_run r = run("param " + data_path("meshes/man.off") + " --threads " + (k == 0 ? "1" : "2") + " -o " + dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("\nstages: read "), std::string::npos) << r.out;
    for(const char* stage : {", patches ", ", map ", ", measure ", ", write "})
      EXPECT_NE(r.out.find(stage), std::string::npos) << stage << " in " << r.out;
    tables[k] = slurp(fs::path(dir) / "man.uv.csv");
    for(const char* name : written) files[k].push_back(slurp(fs::path(dir) / name));
  }
  EXPECT_GT(tables[0].size(), 1000u);
  EXPECT_EQ(tables[0], tables[1]);
  for(std::size_t i = 0; i < files[0].size(); ++i) {
    EXPECT_GT(files[0][i].size(), 100u) << written[i];
    EXPECT_TRUE(files[0][i] == files[1][i]) << written[i] << " differs with --threads 2";
  }
  const Tool_run bad = run("param " + data_path("meshes/man.off") + " --threads -1 -o " + out_dir().string());
  EXPECT_EQ(bad.code, 2) << bad.err;
  const Tool_run render = run("render " + data_path("meshes/cow.off") + " --threads 1 -o " + (out_dir() / "r").string());
  EXPECT_EQ(render.code, 0) << render.err;
}

TEST_F(Tool, StrictReportsARegionThatIsNotADisc)
{
  // Two labels on nefertiti: a band across the middle is fine (a disc), but a
  // ring around one vertex makes the outside an annulus.
  const auto& m = diffuv_test::cgal_mesh("nefertiti.off");
  std::ostringstream labels;
  // The faces around a vertex whose neighbours are all interior: an inner disc.
  diffuv_test::Mesh::Vertex_index inner;
  for(auto v : vertices(m)) {
    bool deep = !m.is_border(v);
    for(auto w : vertices_around_target(m.halfedge(v), m)) deep = deep && !m.is_border(w);
    if(deep) { inner = v; break; }
  }
  std::set<std::size_t> ring;
  for(auto f : faces_around_target(m.halfedge(inner), m)) ring.insert(f.idx());
  for(auto f : faces(m)) labels << (ring.count(f.idx()) ? 1 : 0) << '\n';
  const std::string file = write("ring.txt", labels.str());
  const Tool_run strict = run("param " + data_path("meshes/nefertiti.off") + " --labels " + file + " --strict -o " +
                              out_dir().string());
  EXPECT_EQ(strict.code, 1) << strict.out;
  // The message names the region, not the mesh (nefertiti is a disc).
  EXPECT_NE(strict.err.find(file + ": patch 0 (label 0) has several boundary loops, not a topological disc (2 boundary loops)"),
            std::string::npos) << strict.err;
  EXPECT_FALSE(fs::exists(out_dir()));
  const Tool_run repaired = run("param " + data_path("meshes/nefertiti.off") + " --labels " + file + " -o " +
                                out_dir().string());
  EXPECT_EQ(repaired.code, 0) << repaired.err;
  EXPECT_NE(repaired.out.find("1 region not a disc (cut into cells)"), std::string::npos) << repaired.out;
}

TEST_F(Tool, APatchThatCannotBeMappedIsReportedAndTheOthersAreWritten)
{
  // nefertiti plus a separate triangle: three boundary vertices, no neighbour to merge into.
  std::ifstream in(data_path("meshes/nefertiti.off"));
  std::string header;
  std::size_t nv, nf, ne;
  in >> header >> nv >> nf >> ne;
  std::ostringstream body;
  body << in.rdbuf();
  // The triangle's three points come first, so nefertiti's face indices shift by 3.
  std::ostringstream fixed;
  fixed << "OFF\n" << nv + 3 << ' ' << nf + 1 << " 0\n5 5 5\n6 5 5\n5 6 5\n";
  std::istringstream rest(body.str());
  for(std::size_t i = 0; i < nv; ++i) { double x, y, z; rest >> x >> y >> z; fixed << x << ' ' << y << ' ' << z << '\n'; }
  for(std::size_t j = 0; j < nf; ++j) {
    std::size_t k, a, b, c;
    rest >> k >> a >> b >> c;
    fixed << "3 " << a + 3 << ' ' << b + 3 << ' ' << c + 3 << '\n';
  }
  fixed << "3 0 1 2\n";
  const std::string mesh = write("extra.off", fixed.str());

  const Tool_run partial = run("param " + mesh + " -o " + out_dir().string());
  EXPECT_EQ(partial.code, 0) << partial.err;
  // nefertiti is cut automatically (two components: not a disc); only the triangle fails.
  EXPECT_EQ(partial.err.rfind("diffuv: warning: 1 of ", 0), 0u) << partial.err;
  EXPECT_NE(partial.err.find(" patches cannot be parameterized (see the table); their faces have no (u,v)\n"),
            std::string::npos) << partial.err;
  const std::string obj = slurp(out_dir() / "extra.obj");
  EXPECT_EQ(obj.find("nan"), std::string::npos);
  EXPECT_NE(obj.find("\nf 1 2 3\n"), std::string::npos); // the lone triangle, without vt
  const auto rows = read_csv(out_dir() / "extra.uv.csv");
  std::set<std::string> mapped;
  for(std::size_t i = 1; i < rows.size(); ++i) mapped.insert(rows[i][0]);
  EXPECT_EQ(mapped.size(), nv); // nefertiti's vertices, not the triangle's 0, 1, 2
  EXPECT_EQ(mapped.count("0") + mapped.count("1") + mapped.count("2"), 0u);

  fs::remove_all(out_dir());
  const Tool_run strict = run("param " + mesh + " --strict -o " + out_dir().string());
  EXPECT_EQ(strict.code, 1);
  EXPECT_NE(strict.err.find(" patches cannot be parameterized; the first: patch 1: the boundary has fewer than four vertices"),
            std::string::npos) << strict.err;
  EXPECT_FALSE(fs::exists(out_dir()));

  const std::string lone = write("lone.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const Tool_run none = run("param " + lone + " -o " + out_dir().string());
  EXPECT_EQ(none.code, 1);
  EXPECT_EQ(none.err, "diffuv: error: " + lone +
                          ": 1 of 1 patch cannot be parameterized; the first: patch 0: the boundary has fewer than four vertices\n");
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(Tool, AnExistingOutputFolderKeepsOtherFiles)
{
  const std::string mesh = write("m.off", grid_off);
  fs::create_directories(out_dir());
  std::ofstream(out_dir() / "notes.txt") << "mine\n";
  std::ofstream(out_dir() / "m.uv.csv") << "stale\n";
  const Tool_run r = run("param " + mesh + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(out_dir() / "notes.txt"), "mine\n");
  EXPECT_EQ(slurp(out_dir() / "m.uv.csv").rfind("vertex,", 0), 0u);
}

// The lines of the table of patches: from the header to the totals.
std::vector<std::string> table_lines(const std::string& out)
{
  std::vector<std::string> lines;
  std::istringstream in(out.substr(out.find("\npatch ") + 1));
  for(std::string line; std::getline(in, line);) {
    lines.push_back(line);
    if(line.rfind("total", 0) == 0) break;
  }
  return lines;
}

// Patch names are unique, and the same as other commands print (issue #19):
// two components of one label were both "0".
TEST_F(Tool, PatchNamesAreUnique)
{
  const std::string mesh = write("two.off", two_grids());
  std::string zeros;
  for(int f = 0; f < 16; ++f) zeros += "0\n";  // one label, two components
  const std::string labels = write("zeros.txt", zeros);
  const Tool_run r = run("param " + mesh + " --labels " + labels + " --layout voronoi -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> names;
  for(const std::string& line : table_lines(r.out)) {
    std::istringstream fields(line);
    std::string patch, name;
    fields >> patch >> name;
    if(patch != "patch" && patch != "total") names.push_back(name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"0", "0#2"})) << r.out;
}

// Columns as wide as their widest entry (issue #19): a long label pushed its
// row out of line.
TEST_F(Tool, TheTableStaysAlignedForLargeValues)
{
  const std::string mesh = write("m.off", grid_off);
  const std::string labels = write("l.txt", "1234567890\n1234567890\n1234567890\n1234567890\n7\n7\n7\n7\n");
  const Tool_run r = run("param " + mesh + " --labels " + labels + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<std::string> lines = table_lines(r.out);
  ASSERT_GE(lines.size(), 3u) << r.out;
  EXPECT_NE(r.out.find(" 1234567890"), std::string::npos) << r.out;
  for(const std::string& line : lines) {
    EXPECT_EQ(line.size(), lines.front().size()) << line << "\n" << r.out;
    // Every column ends where its title ends.
    EXPECT_EQ(line.find_last_not_of(' ', lines.front().find("vertices") + 7), lines.front().find("vertices") + 7)
        << line;
  }
}

// A batch user's options (issue #20): --outputs writes only what it lists,
// --no-measure skips the measures (the table shows '-', the files are the
// same), --quiet prints nothing; values they cannot honour are refused.
TEST_F(Tool, OutputsNoMeasureAndQuietWriteOnlyWhatIsAsked)
{
  const std::string cow = data_path("meshes/cow.off");
  const Tool_run full = run("param " + cow + " -o " + (dir_ / "full").string());
  ASSERT_EQ(full.code, 0) << full.err;
  const Tool_run lean = run("param " + cow + " --outputs uv,patches --no-measure -q -o " + (dir_ / "lean").string());
  ASSERT_EQ(lean.code, 0) << lean.err;
  EXPECT_EQ(lean.out, "");
  std::vector<std::string> written;
  for(const auto& e : fs::directory_iterator(dir_ / "lean")) written.push_back(e.path().filename().string());
  std::sort(written.begin(), written.end());
  EXPECT_EQ(written, (std::vector<std::string>{"cow.patches.txt", "cow.uv.csv"}));
  EXPECT_TRUE(slurp(dir_ / "lean" / "cow.uv.csv") == slurp(dir_ / "full" / "cow.uv.csv"));
  EXPECT_TRUE(slurp(dir_ / "lean" / "cow.patches.txt") == slurp(dir_ / "full" / "cow.patches.txt"));

  // Without measures the table is there, its distortion columns empty.
  const Tool_run unmeasured = run("param " + cow + " --no-measure --outputs picture -o " + (dir_ / "pic").string());
  ASSERT_EQ(unmeasured.code, 0) << unmeasured.err;
  EXPECT_NE(unmeasured.out.find("\ntotal "), std::string::npos) << unmeasured.out;
  EXPECT_EQ(unmeasured.out.find(", measure "), std::string::npos) << unmeasured.out;
  EXPECT_NE(full.out.find(", measure "), std::string::npos) << full.out;
  EXPECT_TRUE(fs::exists(dir_ / "pic" / "cow.png"));
  EXPECT_FALSE(fs::exists(dir_ / "pic" / "cow.obj"));

  for(const std::string& bad : {std::string("--outputs obj,foo"), std::string("--outputs obj,obj"),
                                std::string("--outputs ,"), std::string("--no-measure --color area")}) {
    const Tool_run r = run("param " + cow + " " + bad + " -o " + (dir_ / "bad").string());
    EXPECT_EQ(r.code, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find(bad.substr(0, bad.find(' '))), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "bad")) << bad;
  }
}

} // namespace
