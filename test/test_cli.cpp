// Tests of the diffuv tool as a user runs it: exit codes, the one-line
// errors, and that a failure writes nothing.
#include "test_data.h"

#include <diffuv/core/color.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <set>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using diffuv_test::data_path;

struct Tool_run {
  int code;
  std::string out, err;
};

std::string slurp(const fs::path& p)
{
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

#ifndef DIFFUV_TOOL_PATH
// Built without the tool (DIFFUV_BUILD_TOOL=OFF, as scripts/sanitize.sh does):
// these tests are skipped there and run in the normal build.
#define DIFFUV_TOOL_PATH ""
#define DIFFUV_NO_TOOL 1
#endif

class Tool : public diffuv_test::Temp_dir_test {
protected:
  void SetUp() override
  {
    Temp_dir_test::SetUp();
#ifdef DIFFUV_NO_TOOL
    GTEST_SKIP() << "built without the diffuv tool (DIFFUV_BUILD_TOOL=OFF)";
#endif
  }
  Tool_run run(const std::string& args)
  {
    const std::string cmd = std::string(DIFFUV_TOOL_PATH) + " " + args + " >" + (dir_ / "stdout").string() + " 2>" +
                            (dir_ / "stderr").string();
    const int status = std::system(cmd.c_str());
    return Tool_run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "stdout"), slurp(dir_ / "stderr")};
  }
  fs::path out_dir() const { return dir_ / "out"; }
};

std::vector<std::vector<std::string>> read_csv(const fs::path& p)
{
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(p);
  std::string line;
  while(std::getline(in, line)) {
    std::vector<std::string> row;
    std::stringstream ss(line);
    std::string cell;
    while(std::getline(ss, cell, ',')) row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

TEST_F(Tool, NefertitiWithSquareCornersLandsOnTheUnitSquare)
{
  const Tool_run r = run("param " + data_path("meshes/nefertiti.off") + " --corners " +
                    data_path("selections/square_corners.selection.txt") + " -o " + out_dir().string());
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

TEST_F(Tool, HelpDescribesTheCommand)
{
  const Tool_run r = run("param --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--corners"), std::string::npos);
  EXPECT_NE(r.out.find("counter-clockwise"), std::string::npos);
  const Tool_run top = run("--help");
  EXPECT_EQ(top.code, 0);
  EXPECT_NE(top.out.find("param"), std::string::npos);
}

TEST_F(Tool, NoSubcommandOrUnknownOptionIsAUsageError)
{
  EXPECT_EQ(run("").code, 2);
  const Tool_run r = run("param --no-such-option");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--no-such-option"), std::string::npos);
}

// Bad input: one line on stderr naming the file and the reason, exit 1, no output.
struct Bad_case {
  std::string args;
  std::string expected_error; // the whole stderr line
};

TEST_F(Tool, BadInputGivesOneClearLineAndWritesNothing)
{
  const std::string mesh = data_path("meshes/nefertiti.off");
  const std::string missing = (dir_ / "missing.off").string();
  const std::string three = write("three.selection.txt", "133 8 0\n");
  const std::string five = write("five.selection.txt", "133 8 0 287 1\n");
  const std::string range = write("range.selection.txt", "133 8 0 5000\n");
  const std::string inner = write("inner.selection.txt", "133 8 0 150\n");
  const std::string twice = write("twice.selection.txt", "133 8 8 287\n");
  const std::string junk = write("junk.selection.txt", "133 eight 0 287\n");

  const std::vector<Bad_case> cases = {
      {"param " + missing, "diffuv: error: " + missing + ": cannot open file"},
      {"param " + data_path("meshes/cow.off") + " --corners " + data_path("selections/square_corners.selection.txt"),
       "diffuv: error: " + data_path("meshes/cow.off") + ": the mesh is closed (no boundary), not a topological disc"},
      {"param " + (dir_ / "mesh.off").string() + "x",
       "diffuv: error: " + (dir_ / "mesh.off").string() + "x: unknown mesh file extension \".offx\" (expected .off, .obj, .ply or .stl)"},
      {"param " + dir_.string(), "diffuv: error: " + dir_.string() + ": is a directory, not a mesh file"},
      {"param " + mesh + " --labels " + three,
       "diffuv: error: " + three + ": the file has 3 labels, the mesh has 562 faces"},
      {"param " + mesh + " --corners " + three,
       "diffuv: error: " + three + ":1: exactly four corner vertices are needed (3 given)"},
      {"param " + mesh + " --corners " + five,
       "diffuv: error: " + five + ":1: exactly four corner vertices are needed (5 given)"},
      {"param " + mesh + " --corners " + range,
       "diffuv: error: " + range + ":1: vertex index 5000 is out of range (the mesh has 299 vertices)"},
      {"param " + mesh + " --corners " + inner,
       "diffuv: error: " + inner + ":1: a corner vertex is not on the boundary of the mesh (corner #4 listed): vertices 133 8 0 150"},
      {"param " + mesh + " --corners " + twice,
       "diffuv: error: " + twice + ":1: a corner vertex is given twice (corners #2 and #3 listed): vertices 133 8 8 287"},
      {"param " + mesh + " --corners " + (dir_ / "nothere.txt").string(),
       "diffuv: error: " + (dir_ / "nothere.txt").string() + ": cannot open file"},
  };
  for(const Bad_case& c : cases) {
    const Tool_run r = run(c.args + " -o " + out_dir().string());
    EXPECT_EQ(r.code, 1) << c.args;
    EXPECT_EQ(r.err, c.expected_error + "\n") << c.args;
    EXPECT_FALSE(fs::exists(out_dir())) << c.args << ": an output was written";
  }
  const Tool_run j = run("param " + mesh + " --corners " + junk + " -o " + out_dir().string());
  EXPECT_EQ(j.code, 1);
  EXPECT_NE(j.err.find(junk + ":1:"), std::string::npos) << j.err;
  EXPECT_NE(j.err.find("eight"), std::string::npos) << j.err;
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(Tool, NoSubcommandOrUnknownCommandOrEmptyOutput)
{
  const Tool_run unknown = run("bogus");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_EQ(unknown.err, "diffuv: error: unknown command 'bogus' (commands: param, render, segment, compare, correspond, measure; see diffuv --help)\n");
  const Tool_run empty = run("param " + data_path("meshes/nefertiti.off") + " -o ''");
  EXPECT_EQ(empty.code, 2);
  EXPECT_NE(empty.err.find("the output folder name is empty"), std::string::npos) << empty.err;
  const Tool_run version = run("--version");
  EXPECT_EQ(version.code, 0);
  EXPECT_NE(version.out.find("diffuv"), std::string::npos);
}

TEST_F(Tool, OutputsNeverReplaceTheInput)
{
  fs::copy_file(data_path("meshes/nefertiti.off"), dir_ / "nefertiti.off");
  // The mesh written as OFF stays; but an OBJ input in the output folder would be replaced.
  const std::string obj = write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
  const std::string before = slurp(obj);
  const Tool_run r = run("param " + obj + " -o " + dir_.string());
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("would replace the input file"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(obj), before);
  EXPECT_FALSE(fs::exists(dir_ / "plain.uv.csv"));
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

// --threads changes nothing but the time; the summary says how long each
// stage took.
TEST_F(Tool, ThreadsGiveTheSameFilesAndStagesAreTimed)
{
  std::string tables[2];
  for(int k = 0; k < 2; ++k) {
    const std::string dir = (out_dir() / std::to_string(k)).string();
    const Tool_run r = run("param " + data_path("meshes/man.off") + " --threads " + (k == 0 ? "1" : "2") + " -o " + dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("\nstages: read "), std::string::npos) << r.out;
    for(const char* stage : {", patches ", ", map ", ", measure ", ", write "})
      EXPECT_NE(r.out.find(stage), std::string::npos) << stage << " in " << r.out;
    tables[k] = slurp(fs::path(dir) / "man.uv.csv");
  }
  EXPECT_GT(tables[0].size(), 1000u);
  EXPECT_EQ(tables[0], tables[1]);
  const Tool_run bad = run("param " + data_path("meshes/man.off") + " --threads -1 -o " + out_dir().string());
  EXPECT_EQ(bad.code, 2) << bad.err;
  const Tool_run render = run("render " + data_path("meshes/cow.off") + " --threads 1 -o " + (out_dir() / "r").string());
  EXPECT_EQ(render.code, 0) << render.err;
}

TEST_F(Tool, SegmentWritesPatchesThatReadBackAsLabelsAndAsPaint)
{
  const Tool_run seg = run("segment " + data_path("meshes/cow.off") + " -o " + out_dir().string());
  ASSERT_EQ(seg.code, 0) << seg.err;
  const fs::path labels = out_dir() / "cow.patches.txt";
  const fs::path ply = out_dir() / "cow.patches.ply";
  ASSERT_TRUE(fs::exists(labels));
  ASSERT_TRUE(fs::exists(ply));

  // The label file as --labels: the same patches come back (same count, none cut or split).
  const Tool_run with_labels = run("param " + data_path("meshes/cow.off") + " --labels " + labels.string() + " -o " +
                                   (dir_ / "a").string());
  ASSERT_EQ(with_labels.code, 0) << with_labels.err;
  EXPECT_NE(with_labels.out.find("(the regions, kept whole)"), std::string::npos) << with_labels.out;
  EXPECT_TRUE(slurp(dir_ / "a" / "cow.patches.txt") == slurp(labels));

  // The coloured PLY as the mesh: its painted regions are used, same patches.
  const Tool_run painted = run("param " + ply.string() + " -o " + (dir_ / "b").string());
  ASSERT_EQ(painted.code, 0) << painted.err;
  EXPECT_NE(painted.out.find("painted"), std::string::npos) << painted.out;
  EXPECT_TRUE(slurp(dir_ / "b" / "cow.patches.patches.txt") == slurp(labels)); // output named after the PLY
}

// Issue #5: a face left flat by its sides that no corners can mend (a small
// patch of anchor with more ears than corners) goes to a neighbouring patch;
// --keep-flat-triangles keeps it (and says nothing).
TEST_F(Tool, SegmentHandsFlatFacesToANeighbourUnlessKept)
{
  const std::string anchor = data_path("meshes/anchor.off");
  const Tool_run handed = run("segment " + anchor + " -o " + (dir_ / "a").string());
  ASSERT_EQ(handed.code, 0) << handed.err;
  const auto clause = handed.out.find(" handed to a neighbour");
  ASSERT_NE(clause, std::string::npos) << handed.out;
  const auto noun = handed.out.rfind(" flat triangle", clause);
  ASSERT_NE(noun, std::string::npos) << handed.out;
  const std::size_t count = std::stoul(handed.out.substr(handed.out.rfind(' ', noun - 1) + 1));
  EXPECT_GT(count, 0u);
  const Tool_run kept = run("segment " + anchor + " --keep-flat-triangles -o " + (dir_ / "b").string());
  ASSERT_EQ(kept.code, 0) << kept.err;
  EXPECT_EQ(kept.out.find("handed"), std::string::npos) << kept.out;

  // The two label files differ in exactly the faces handed.
  std::istringstream a(slurp(dir_ / "a" / "anchor.patches.txt")), b(slurp(dir_ / "b" / "anchor.patches.txt"));
  std::string la, lb;
  std::size_t lines = 0, different = 0;
  while(std::getline(a, la) && std::getline(b, lb)) {
    ++lines;
    different += la != lb;
  }
  EXPECT_EQ(lines, 1050u);
  EXPECT_EQ(different, count);
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
  EXPECT_NE(strict.err.find(file + ": the mesh has several boundary loops"), std::string::npos) << strict.err;
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
  EXPECT_NE(strict.err.find(" patches cannot be parameterized; the first: the boundary has fewer than four vertices"),
            std::string::npos) << strict.err;
  EXPECT_FALSE(fs::exists(out_dir()));

  const std::string lone = write("lone.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const Tool_run none = run("param " + lone + " -o " + out_dir().string());
  EXPECT_EQ(none.code, 1);
  EXPECT_EQ(none.err, "diffuv: error: " + lone +
                          ": 1 of 1 patches cannot be parameterized; the first: the boundary has fewer than four vertices (patch 0)\n");
  EXPECT_FALSE(fs::exists(out_dir()));
}

TEST_F(Tool, PatchesOfAPolygonMeshReadBackAsLabels)
{
  // cube_quad.off has quads: patches.txt has one line per quad, the file's faces.
  const Tool_run seg = run("segment " + data_path("meshes/cube_quad.off") + " -o " + out_dir().string());
  ASSERT_EQ(seg.code, 0) << seg.err;
  const fs::path labels = out_dir() / "cube_quad.patches.txt";
  std::ifstream in(labels);
  std::size_t lines = 0;
  for(std::string l; std::getline(in, l);) ++lines;
  EXPECT_EQ(lines, 6u);
  const Tool_run param = run("param " + data_path("meshes/cube_quad.off") + " --labels " + labels.string() + " -o " +
                             (dir_ / "p").string());
  EXPECT_EQ(param.code, 0) << param.err;
}

TEST_F(Tool, RenderWritesOnlyThePictureWithAHeatMap)
{
  const Tool_run r = run("render " + data_path("meshes/three_peaks.off") + " --color angle --view top --size 320x240 -o " +
                         out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> written;
  for(const auto& e : fs::directory_iterator(out_dir())) written.push_back(e.path().filename().string());
  EXPECT_EQ(written, std::vector<std::string>{"three_peaks.png"});
  const std::string png = slurp(out_dir() / "three_peaks.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  // IHDR: width and height, big-endian, at bytes 16..23.
  auto be32 = [&](std::size_t at) {
    return (std::uint32_t(std::uint8_t(png[at])) << 24) | (std::uint32_t(std::uint8_t(png[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(png[at + 2])) << 8) | std::uint32_t(std::uint8_t(png[at + 3]));
  };
  EXPECT_EQ(be32(16), 320u);
  EXPECT_EQ(be32(20), 240u);
  fs::remove_all(out_dir());
  for(const char* args : {" --size 12", " --azimuth nan", " --elevation 30", " --view sideways", " --color red"}) {
    const Tool_run bad = run("render " + data_path("meshes/three_peaks.off") + args + " -o " + out_dir().string());
    EXPECT_EQ(bad.code, 2) << args;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << args << ": " << bad.err;
    EXPECT_FALSE(fs::exists(out_dir())) << args;
  }
}

TEST_F(Tool, AnOutputPathThatIsAFileIsRefused)
{
  const std::string file = write("taken", "not a folder");
  const Tool_run r = run("param " + data_path("meshes/nefertiti.off") + " -o " + file);
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.err, "diffuv: error: cannot write " + file + ": exists and is not a directory\n");
  EXPECT_EQ(slurp(file), "not a folder");
}

} // namespace

namespace {

TEST_F(Tool, CompareRunsEveryMethodOnTheSamePatches)
{
  const Tool_run r = run("compare " + data_path("meshes/nefertiti.off") + " --corners " +
                         data_path("selections/square_corners.selection.txt") + " --runs 1 -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  for(const char* method : {"diffuv ", "tutte ", "mean_value ", "authalic ", "conformal ", "lscm ", "arap "}) {
    const auto at = r.out.find(std::string("\n") + method);
    ASSERT_NE(at, std::string::npos) << method << r.out;
    const std::string row = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
    EXPECT_EQ(row.substr(row.size() - 3), "yes") << row; // every method is one-to-one on nefertiti
    EXPECT_TRUE(fs::exists(out_dir() / ("nefertiti." + std::string(method, std::strlen(method) - 1) + ".obj")));
  }
  // The paper's raw method folds with these corners; the default does not.
  const Tool_run raw = run("compare " + data_path("meshes/nefertiti.off") + " --corners " +
                           data_path("selections/square_corners.selection.txt") + " --runs 1 --methods diffuv-graph-raw,diffuv");
  ASSERT_EQ(raw.code, 0) << raw.err;
  EXPECT_NE(raw.out.find("diffuv-graph-raw"), std::string::npos);
  EXPECT_NE(raw.out.find(" no\n"), std::string::npos) << raw.out;
}

TEST_F(Tool, CompareSumsOverThePatchesOfAClosedMesh)
{
  const Tool_run r = run("compare " + data_path("meshes/cow.off") + " --runs 1 --methods diffuv,tutte");
  ASSERT_EQ(r.code, 0) << r.err;
  // The four-sided layout: hundreds of patches (6 Voronoi cells would give 24).
  const auto patches_at = r.out.find(" patches;");
  ASSERT_NE(patches_at, std::string::npos) << r.out;
  EXPECT_GT(std::stoul(r.out.substr(r.out.rfind(' ', patches_at - 1) + 1)), 100u) << r.out;
  // diffuv's row: no flipped triangle and no overlap (the few degenerate uv
  // triangles are faces of small fallback patches with three vertices on one
  // side, which Tutte's map flattens too; see doc/layout.md).
  const auto at = r.out.find("\ndiffuv ");
  ASSERT_NE(at, std::string::npos);
  std::istringstream row(r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1));
  std::string method;
  double time_ms = 0;
  int failed = -1, flipped = -1, degenerate = -1, overlaps = -1;
  row >> method >> time_ms >> failed >> flipped >> degenerate >> overlaps;
  EXPECT_EQ(failed, 0) << r.out;
  EXPECT_EQ(flipped, 0) << r.out;
  EXPECT_EQ(overlaps, 0) << r.out;
  EXPECT_LE(degenerate, 5) << r.out;
}

TEST_F(Tool, CompareRefusesUnknownOrRepeatedMethods)
{
  for(const char* methods : {"bogus", "tutte,tutte", "diffuv-foo", ""}) {
    const Tool_run r = run("compare " + data_path("meshes/nefertiti.off") + " --methods '" + methods + "'");
    EXPECT_EQ(r.code, 2) << methods << r.err;
    EXPECT_NE(r.err.find("--methods"), std::string::npos) << r.err;
  }
}

// ---- diffuv correspond -------------------------------------------------------

// Cow written as OFF (A), and a copy with vertices and faces shuffled, each face
// listed from a random corner, rotated, scaled by 2 and moved (B), with the
// face labels of `diffuv segment` carried over. Optionally B has vertex colours.
class Correspond : public Tool {
protected:
  void SetUp() override
  {
    Tool::SetUp();
    if(IsSkipped()) return;  // built without the tool
    const auto& m = diffuv_test::cgal_mesh("cow.off");
    nv_ = num_vertices(m);
    std::ostringstream a;
    a.precision(17);
    a << "OFF\n" << nv_ << ' ' << num_faces(m) << " 0\n";
    for(auto v : vertices(m)) a << m.point(v).x() << ' ' << m.point(v).y() << ' ' << m.point(v).z() << '\n';
    std::vector<std::array<std::size_t, 3>> faces_a;
    for(auto f : faces(m)) {
      std::array<std::size_t, 3> t{};
      int k = 0;
      for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++] = v.idx();
      faces_a.push_back(t);
      a << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    a_ = write("a.off", a.str());
    // Region-sized labels, as a user paints them: the Voronoi layout's patches.
    const Tool_run seg = run("segment " + a_ + " --layout voronoi -o " + path("seg"));
    ASSERT_EQ(seg.code, 0) << seg.err;
    std::vector<int> labels;
    std::ifstream in(path("seg") + "/a.patches.txt");
    for(int l; in >> l;) labels.push_back(l);
    ASSERT_EQ(labels.size(), faces_a.size());

    std::mt19937 rng(17);
    std::vector<std::size_t> vperm(nv_), fperm(faces_a.size());
    std::iota(vperm.begin(), vperm.end(), 0);
    std::iota(fperm.begin(), fperm.end(), 0);
    std::shuffle(vperm.begin(), vperm.end(), rng); // B's vertex k is A's vertex vperm[k]
    std::shuffle(fperm.begin(), fperm.end(), rng); // B's face k is A's face fperm[k]
    copy_of_.assign(nv_, 0);
    for(std::size_t k = 0; k < nv_; ++k) copy_of_[vperm[k]] = k;
    b_points_.resize(nv_);
    for(std::size_t k = 0; k < nv_; ++k) {
      const auto& p = m.point(Mesh_vertex(static_cast<std::uint32_t>(vperm[k])));
      b_points_[k] = {{-2. * p.y() + 5., 2. * p.x(), 2. * p.z() - 3.}}; // a quarter turn, twice the size
    }
    for(std::size_t k = 0; k < fperm.size(); ++k) {
      const auto& t = faces_a[fperm[k]];
      const std::size_t start = rng() % 3;
      b_faces_.push_back({{copy_of_[t[start]], copy_of_[t[(start + 1) % 3]], copy_of_[t[(start + 2) % 3]]}});
      b_labels_.push_back(labels[fperm[k]]);
    }
    labels_a_ = path("seg") + "/a.patches.txt";
  }

  std::string write_b(bool colors, const std::string& name = "b.off")
  {
    std::ostringstream b;
    b.precision(17);
    b << (colors ? "COFF\n" : "OFF\n") << nv_ << ' ' << b_faces_.size() << " 0\n";
    for(std::size_t k = 0; k < nv_; ++k) {
      b << b_points_[k][0] << ' ' << b_points_[k][1] << ' ' << b_points_[k][2];
      if(colors) b << ' ' << k % 256 << " 50 200 255";
      b << '\n';
    }
    for(const auto& t : b_faces_) b << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    return write(name, b.str());
  }
  std::string write_labels(const std::vector<int>& labels, const std::string& name)
  {
    std::ostringstream out;
    for(int l : labels) out << l << '\n';
    return write(name, out.str());
  }

  using Mesh_vertex = diffuv_test::Mesh::Vertex_index;
  std::size_t nv_ = 0;
  std::string a_, labels_a_;
  std::vector<std::size_t> copy_of_;                 // A's vertex -> B's vertex
  std::vector<std::array<double, 3>> b_points_;
  std::vector<std::array<std::size_t, 3>> b_faces_;  // as listed in b.off
  std::vector<int> b_labels_;
};

TEST_F(Correspond, ShuffledMovedCopyMapsEveryVertexOntoItsCopy)
{
  const std::string b = write_b(false);
  const std::string labels_b = write_labels(b_labels_, "b.labels.txt");
  const Tool_run r = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " + labels_b +
                         " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("vertices mapped: " + std::to_string(nv_) + " of " + std::to_string(nv_)), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("regions matched: "), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "correspondence.csv");
  ASSERT_EQ(rows.size(), nv_ + 1);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"vertex", "face", "b0", "b1", "b2", "x", "y", "z"}));
  double worst_point = 0, worst_weights = 0;
  for(std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 8u) << i;
    EXPECT_EQ(std::stoul(rows[i][0]), i - 1);
    const auto& truth = b_points_[copy_of_[i - 1]];
    const std::size_t face = std::stoul(rows[i][1]);
    ASSERT_LT(face, b_faces_.size());
    for(int k = 0; k < 3; ++k) {
      worst_point = std::max(worst_point, std::abs(std::stod(rows[i][5 + k]) - truth[k]));
      // b0..b2 weight the face's vertices in the order b.off lists them.
      double x = 0;
      for(int c = 0; c < 3; ++c) x += std::stod(rows[i][2 + c]) * b_points_[b_faces_[face][c]][k];
      worst_weights = std::max(worst_weights, std::abs(x - std::stod(rows[i][5 + k])));
    }
  }
  EXPECT_LT(worst_point, 1e-9);
  EXPECT_LT(worst_weights, 1e-9);
  EXPECT_TRUE(fs::exists(out_dir() / "transfer.ply"));
  EXPECT_TRUE(fs::exists(out_dir() / "reference.ply"));
}

// B's vertex colours land on A's vertices (each maps onto its copy), and
// --values rows are interpolated the same way.
TEST_F(Correspond, ColorsAndValuesAreCarriedToA)
{
  const std::string b = write_b(true, "b_colored.off");
  const std::string labels_b = write_labels(b_labels_, "b.labels.txt");
  std::ostringstream values;
  for(std::size_t k = 0; k < nv_; ++k) values << k << ' ' << 0.5 * k << '\n';
  const std::string values_file = write("values.txt", values.str());
  const Tool_run r = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " + labels_b +
                         " --values " + values_file + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("B's vertex colours"), std::string::npos) << r.out;
  std::ifstream ply(out_dir() / "transfer.ply");
  std::string line;
  while(std::getline(ply, line) && line != "end_header") {}
  for(std::size_t i = 0; i < nv_; ++i) {
    double x, y, z;
    int red, green, blue;
    ASSERT_TRUE(ply >> x >> y >> z >> red >> green >> blue);
    EXPECT_EQ(red, static_cast<int>(copy_of_[i] % 256)) << i;
    EXPECT_EQ(green, 50);
    EXPECT_EQ(blue, 200);
  }
  std::ifstream out(out_dir() / "values.txt");
  std::getline(out, line); // comment
  for(std::size_t i = 0; i < nv_; ++i) {
    double first, second;
    ASSERT_TRUE(out >> first >> second);
    // The image's barycentric coordinates are exact to ~1e-9 (a point located in uv).
    EXPECT_NEAR(first, double(copy_of_[i]), 1e-8 * nv_);
    EXPECT_NEAR(second, 0.5 * copy_of_[i], 1e-8 * nv_);
  }
  // A values file with the wrong number of rows is refused, naming the file.
  const std::string short_file = write("short.txt", "1\n2\n");
  const Tool_run bad = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " + labels_b +
                           " --values " + short_file + " -o " + path("bad_out"));
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("short.txt: the file has 2 rows, mesh B has " + std::to_string(nv_) + " vertices"),
            std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(path("bad_out")));
}

TEST_F(Correspond, MissingLabelsSayHowToProvideThem)
{
  const std::string b = write_b(false);
  // A command-line mistake points at the command's own help.
  const Tool_run usage = run("correspond " + a_ + ' ' + b + " --bogus");
  EXPECT_EQ(usage.code, 2);
  EXPECT_NE(usage.err.find("(see diffuv correspond --help)"), std::string::npos) << usage.err;

  const Tool_run none = run("correspond " + a_ + ' ' + b + " -o " + out_dir().string());
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.err.find("a.off: the mesh has no region labels"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("--labels-a"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("diffuv segment"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(out_dir()));

  const Tool_run only_a = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " -o " + out_dir().string());
  EXPECT_EQ(only_a.code, 1);
  EXPECT_NE(only_a.err.find("b.off: the mesh has no region labels"), std::string::npos) << only_a.err;
  EXPECT_NE(only_a.err.find("--transfer-labels"), std::string::npos) << only_a.err;
  EXPECT_FALSE(fs::exists(out_dir()));

  // B on top of A (not moved): its labels can come from A's nearest faces.
  std::ostringstream on_top;
  on_top.precision(17);
  const auto& m = diffuv_test::cgal_mesh("cow.off");
  on_top << "OFF\n" << nv_ << ' ' << b_faces_.size() << " 0\n";
  std::vector<std::size_t> original_of(nv_);
  for(std::size_t i = 0; i < nv_; ++i) original_of[copy_of_[i]] = i;
  for(std::size_t k = 0; k < nv_; ++k) {
    const auto& p = m.point(Mesh_vertex(static_cast<std::uint32_t>(original_of[k])));
    on_top << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for(const auto& t : b_faces_) on_top << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  const std::string b_on_top = write("b_on_top.off", on_top.str());
  const Tool_run transferred = run("correspond " + a_ + ' ' + b_on_top + " --labels-a " + labels_a_ +
                                   " --transfer-labels -o " + out_dir().string());
  ASSERT_EQ(transferred.code, 0) << transferred.err;
  EXPECT_NE(transferred.out.find("labels of A's nearest faces"), std::string::npos) << transferred.out;
  EXPECT_NE(transferred.out.find("vertices mapped: " + std::to_string(nv_) + " of"), std::string::npos) << transferred.out;
}

// A label that only one mesh has is reported, and its vertices get face -1.
TEST_F(Correspond, LabelsInOneMeshOnlyAreReported)
{
  const std::string b = write_b(false);
  std::vector<int> renamed = b_labels_;
  for(int& l : renamed) if(l == 0) l = 1000;
  const std::string labels_b = write_labels(renamed, "b.labels.txt");
  const Tool_run r = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " + labels_b +
                         " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("labels only in A (not mapped): 0\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("labels only in B (nothing maps there): 1000\n"), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "correspondence.csv");
  std::size_t unmapped = 0;
  for(std::size_t i = 1; i < rows.size(); ++i)
    if(rows[i][1] == "-1") ++unmapped;
  EXPECT_GT(unmapped, 50u);
  EXPECT_LT(unmapped, nv_ / 2);

  // No label in common: an error, nothing written.
  std::vector<int> disjoint = b_labels_;
  for(int& l : disjoint) l += 5000;
  const Tool_run none = run("correspond " + a_ + ' ' + b + " --labels-a " + labels_a_ + " --labels-b " +
                            write_labels(disjoint, "disjoint.txt") + " -o " + path("none_out"));
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.err.find("no patch of A pairs with a patch of B"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(path("none_out")));
}

// Regions painted on both meshes: A as `diffuv segment` writes it (palette
// colours and a label property), B painted with the same colours only (another
// file, another numbering): the colours name the same regions.
TEST_F(Correspond, PaintedRegionsPairByColor)
{
  std::ostringstream b;
  b.precision(17);
  b << "OFF\n" << nv_ << ' ' << b_faces_.size() << " 0\n";
  for(std::size_t k = 0; k < nv_; ++k) b << b_points_[k][0] << ' ' << b_points_[k][1] << ' ' << b_points_[k][2] << '\n';
  for(std::size_t k = 0; k < b_faces_.size(); ++k) {
    const auto c = diffuv::label_color(b_labels_[k]);
    b << "3 " << b_faces_[k][0] << ' ' << b_faces_[k][1] << ' ' << b_faces_[k][2] << ' ' << int(c.r) << ' '
      << int(c.g) << ' ' << int(c.b) << '\n';
  }
  const std::string painted_b = write("b_painted.off", b.str());
  const Tool_run r = run("correspond " + path("seg") + "/a.patches.ply " + painted_b + " -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("vertices mapped: " + std::to_string(nv_) + " of " + std::to_string(nv_)), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("labels only in"), std::string::npos) << r.out;
  const auto rows = read_csv(out_dir() / "correspondence.csv");
  ASSERT_EQ(rows.size(), nv_ + 1);
  double worst = 0;
  for(std::size_t i = 1; i < rows.size(); ++i)
    for(int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(std::stod(rows[i][5 + k]) - b_points_[copy_of_[i - 1]][k]));
  EXPECT_LT(worst, 1e-9);
}

} // namespace

// ---- The catalogue of bad inputs (doc/robustness.md) ----------------------------
namespace {

// One test per kind of bad input a user brings: the exact stderr they see, the
// exit code, and whether anything was written. Inputs that diffuv can still use
// (holes, several components, polygons, ...) give a result and say what they met.

// A 3x3-vertex grid: vertices 0..8 row by row, 8 triangles; 4 is the only inner vertex.
const std::string grid_points = "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n";
const std::string grid_faces = "3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 3 4 7\n3 3 7 6\n3 4 5 8\n3 4 8 7\n";
const std::string grid_off = "OFF\n9 8 0\n" + grid_points + grid_faces;

// An n x n-vertex grid without the quads listed (x, y): holes.
std::string grid_with_holes(int n, const std::set<std::pair<int, int>>& holes, double x0 = 0)
{
  std::ostringstream points, faces;
  std::size_t count = 0;
  for(int y = 0; y < n; ++y)
    for(int x = 0; x < n; ++x) points << x + x0 << ' ' << y << " 0\n";
  for(int y = 0; y + 1 < n; ++y)
    for(int x = 0; x + 1 < n; ++x) {
      if(holes.count({x, y})) continue;
      const int a = y * n + x, b = a + 1, c = a + n, d = c + 1;
      faces << "3 " << a << ' ' << b << ' ' << d << "\n3 " << a << ' ' << d << ' ' << c << '\n';
      count += 2;
    }
  return "OFF\n" + std::to_string(n * n) + ' ' + std::to_string(count) + " 0\n" + points.str() + faces.str();
}

// Two 3x3 grids side by side, the second one's indices shifted by 9.
std::string two_grids()
{
  std::ostringstream s;
  s << "OFF\n18 16 0\n" << grid_points;
  for(int i = 0; i < 9; ++i) s << 5 + i % 3 << ' ' << i / 3 << " 0\n";
  s << grid_faces;
  std::istringstream faces(grid_faces);
  int k, a, b, c;
  while(faces >> k >> a >> b >> c) s << "3 " << a + 9 << ' ' << b + 9 << ' ' << c + 9 << '\n';
  return s.str();
}

struct Catalogue_entry {
  std::string name;
  std::vector<std::pair<std::string, std::string>> files; // written to the test folder first
  std::string args;         // "{d}" stands for the test folder
  int code;                 // the exit code
  std::string err;          // the whole stderr, "{d}" as above
  std::string out_has = {}; // a piece of stdout (results only)
};

std::ostream& operator<<(std::ostream& os, const Catalogue_entry& e) { return os << e.name; }

const std::vector<Catalogue_entry>& catalogue()
{
  const std::string m = "param {d}/m.off";
  static const std::vector<Catalogue_entry> entries = {
      // Mesh files
      {"empty_file", {{"m.off", ""}}, m, 1, "diffuv: error: {d}/m.off: the file is empty\n"},
      {"truncated_off_in_the_points", {{"m.off", "OFF\n9 8 0\n0 0 0\n1 0 0\n2 0\n"}}, m, 1,
       "diffuv: error: {d}/m.off:2: not a valid OFF file (the header announces 9 vertices and 8 faces, more than the "
       "26 bytes of the file can hold)\n"},
      {"truncated_off_in_the_faces", {{"m.off", "OFF\n9 8 0\n" + grid_points + "3 0 1 4\n3 0 4 3\n3 1 2 5\n"}}, m, 1,
       "diffuv: error: {d}/m.off: not a valid OFF file (the file ends before face 3 of 8)\n"},
      {"nan_coordinate", {{"m.off", "OFF\n9 8 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\nnan 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n" + grid_faces}},
       m, 1, "diffuv: error: {d}/m.off:7: vertex 4 has a coordinate that is NaN or infinite\n"},
      {"infinite_coordinate", {{"m.off", "OFF\n9 8 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 -inf 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n" + grid_faces}},
       m, 1, "diffuv: error: {d}/m.off:7: vertex 4 has a coordinate that is NaN or infinite\n"},
      {"huge_coordinates", {{"m.off", "OFF\n9 8 0\n0 0 0\n1e70 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n" + grid_faces}},
       m, 1, "diffuv: error: {d}/m.off:4: vertex 1 has a coordinate of 1e+70, too large to compute with (beyond 1e60): "
             "rescale the mesh\n"},
      {"tiny_mesh", {{"m.off", "OFF\n9 8 0\n0 0 0\n1e-70 0 0\n2e-70 0 0\n0 1e-70 0\n1e-70 1e-70 0\n2e-70 1e-70 0\n"
                               "0 2e-70 0\n1e-70 2e-70 0\n2e-70 2e-70 0\n" + grid_faces}},
       m, 1, "diffuv: error: {d}/m.off: the mesh is too small to compute with (it spans 2e-70, under 1e-60): rescale the mesh\n"},
      {"zero_area_faces", // the inner vertex moved onto vertex 1: two triangles collapse
       {{"m.off", "OFF\n9 8 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 0 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n" + grid_faces}}, m, 0,
       "diffuv: warning: {d}/m.off: 2 faces have zero area; their (u,v) triangles may be flat (column degen)\n",
       "9 vertices, 8 faces, 2 zero-area faces\n"},
      {"duplicate_vertices_not_welded", // vertex 9 repeats vertex 4; the right half of the grid uses it
       {{"m.off", "OFF\n10 8 0\n" + grid_points + "1 1 0\n3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 9\n3 3 4 7\n3 3 7 6\n3 9 5 8\n3 9 8 7\n"}},
       m, 1,
       "diffuv: error: {d}/m.off: non-manifold edge or vertex, or inconsistent orientation (the faces around vertex 1 "
       "form 2 separate fans); vertices 4 and 9 have the same position: the mesh may need welding\n"},
      {"non_manifold_edge", {{"m.off", "OFF\n10 10 0\n" + grid_points + "1 -1 1\n" + grid_faces + "3 1 0 9\n3 0 1 9\n"}}, m, 1,
       "diffuv: error: {d}/m.off:22: non-manifold edge or vertex, or inconsistent orientation (faces 0 and 9 both go "
       "from vertex 0 to vertex 1)\n"},
      {"non_manifold_vertex", // a second grid cell touching the first at vertex 8 only
       {{"m.off", "OFF\n12 10 0\n" + grid_points + "3 3 0\n2 3 0\n3 2 0\n" + grid_faces + "3 8 11 9\n3 8 9 10\n"}}, m, 1,
       "diffuv: error: {d}/m.off: non-manifold edge or vertex, or inconsistent orientation (the faces around vertex 8 "
       "form 2 separate fans)\n"},
      {"mesh_with_holes", {{"m.off", grid_with_holes(6, {{1, 1}, {3, 3}})}}, m, 0, "",
       "36 vertices, 46 faces\n"},
      {"several_components", {{"m.off", two_grids()}}, m, 0, "", "2 components, 2 whole discs"},
      {"isolated_vertices", {{"m.off", "OFF\n11 8 0\n" + grid_points + "9 9 9\n8 8 8\n" + grid_faces}}, m, 0, "",
       "11 vertices, 8 faces, 2 isolated vertices (in no face: no (u,v))\n1 patch, fmm distances: the whole disc"},
      {"polygon_faces", {{"m.off", "OFF\n9 4 0\n" + grid_points + "4 0 1 4 3\n4 1 2 5 4\n4 3 4 7 6\n4 4 5 8 7\n"}}, m, 0,
       "", "9 vertices, 8 faces (4 polygons triangulated)\n"},
      // Label files
      {"labels_wrong_count", {{"m.off", grid_off}, {"l.txt", "0\n0\n1\n"}}, m + " --labels {d}/l.txt", 1,
       "diffuv: error: {d}/l.txt: the file has 3 labels, the mesh has 8 faces\n"},
      {"labels_negative", {{"m.off", grid_off}, {"l.txt", "0\n0\n-1\n1\n1\n1\n1\n1\n"}}, m + " --labels {d}/l.txt", 1,
       "diffuv: error: {d}/l.txt:3: label -1 is negative; labels are non-negative integers\n"},
      {"labels_not_integers", {{"m.off", grid_off}, {"l.txt", "0\n0\n1.5\n1\n1\n1\n1\n1\n"}}, m + " --labels {d}/l.txt", 1,
       "diffuv: error: {d}/l.txt:3: \"1.5\" is not an integer label\n"},
      {"labels_huge", {{"m.off", grid_off}, {"l.txt", "0\n0\n99999999999\n1\n1\n1\n1\n1\n"}}, m + " --labels {d}/l.txt", 1,
       "diffuv: error: {d}/l.txt:3: label 99999999999 is out of range\n"},
      // Corner files (the grid's border vertices are all but 4)
      {"corners_out_of_range", {{"m.off", grid_off}, {"c.txt", "0 2 8 9\n"}}, m + " --corners {d}/c.txt", 1,
       "diffuv: error: {d}/c.txt:1: vertex index 9 is out of range (the mesh has 9 vertices)\n"},
      {"corners_duplicated", {{"m.off", grid_off}, {"c.txt", "0 2 2 6\n"}}, m + " --corners {d}/c.txt", 1,
       "diffuv: error: {d}/c.txt:1: a corner vertex is given twice (corners #2 and #3 listed): vertices 0 2 2 6\n"},
      {"corners_not_on_the_border", {{"m.off", grid_off}, {"c.txt", "0 2 4 6\n"}}, m + " --corners {d}/c.txt", 1,
       "diffuv: error: {d}/c.txt:1: a corner vertex is not on the boundary of the mesh (corner #3 listed): vertices 0 2 4 6\n"},
      {"corners_fewer_than_four", {{"m.off", grid_off}, {"c.txt", "0 2 8\n"}}, m + " --corners {d}/c.txt", 1,
       "diffuv: error: {d}/c.txt:1: exactly four corner vertices are needed (3 given)\n"},
      // Output paths
      {"output_folder_cannot_be_created", {{"m.off", grid_off}}, "param {d}/m.off -o /proc/diffuv-out", 3,
       "diffuv: error: cannot write /proc/diffuv-out: cannot create the directory (No such file or directory)\n"},
      {"output_path_is_a_file", {{"m.off", grid_off}, {"taken", "x\n"}}, "param {d}/m.off -o {d}/taken", 3,
       "diffuv: error: cannot write {d}/taken: exists and is not a directory\n"},
      {"output_path_under_a_file", {{"m.off", grid_off}, {"taken", "x\n"}}, "param {d}/m.off -o {d}/taken/out", 3,
       "diffuv: error: cannot write {d}/taken/out: cannot create the directory (Not a directory)\n"},
  };
  return entries;
}

std::string with_folder(std::string s, const std::string& folder)
{
  for(std::size_t at; (at = s.find("{d}")) != std::string::npos;) s.replace(at, 3, folder);
  return s;
}

class BadInput : public Tool, public ::testing::WithParamInterface<Catalogue_entry> {};

TEST_P(BadInput, GivesTheCataloguedAnswer)
{
  const Catalogue_entry& e = GetParam();
  for(const auto& [name, content] : e.files) write(name, content);
  std::string args = with_folder(e.args, dir_.string());
  if(args.find(" -o ") == std::string::npos) args += " -o " + out_dir().string();
  const Tool_run r = run(args);
  EXPECT_EQ(r.code, e.code) << r.err;
  EXPECT_EQ(r.err, with_folder(e.err, dir_.string()));
  if(e.code == 0) {
    EXPECT_NE(r.out.find(e.out_has), std::string::npos) << r.out;
    const auto rows = read_csv(out_dir() / "m.uv.csv");
    EXPECT_GT(rows.size(), 1u);
    for(const auto& row : rows)
      for(const auto& cell : row) EXPECT_EQ(cell.find("nan"), std::string::npos) << e.name;
  } else {
    EXPECT_FALSE(fs::exists(out_dir())) << "an output was written";
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInput, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<Catalogue_entry>& info) { return info.param.name; });

// An existing output folder is written into: diffuv's files are replaced (each
// atomically), anything else in it is kept.
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

} // namespace
