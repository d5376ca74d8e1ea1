// Tests of the diffuv tool's answers to mistakes: usage errors, bad inputs
// (the catalogue of doc/robustness.md), outputs that cannot be written; the
// one line on stderr, the exit code, and that a failure writes nothing.
#include "test_cli_tool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace diffuv_cli_test;

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
  EXPECT_EQ(unknown.err, "diffuv: error: unknown command 'bogus' (commands: param, render, segment, compare, correspond, measure, bake, serve; see diffuv --help)\n");
  const Tool_run empty = run("param " + data_path("meshes/nefertiti.off") + " -o ''");
  EXPECT_EQ(empty.code, 2);
  EXPECT_NE(empty.err.find("the output folder name is empty"), std::string::npos) << empty.err;
  const Tool_run version = run("--version");
  EXPECT_EQ(version.code, 0);
  EXPECT_NE(version.out.find("diffuv"), std::string::npos);
}

// A value the tool cannot use is refused, not ignored (issue #19): a usage
// error on one line, nothing written.
TEST_F(Tool, ValuesTheToolCannotUseAreRefused)
{
  const std::string mesh = write("m.off", grid_off);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"render " + mesh + " --size 800x600x3", "--size: expects WxH"},  // was drawn at 800x600
      {"render " + mesh + " --size 800x", "--size: expects WxH"},
      {"render " + mesh + " --view top --azimuth 10", "--view excludes --azimuth"},  // --view was ignored
      {"param " + mesh + " --azimuth 10 --view front", "--view excludes --azimuth"},
      {"correspond " + mesh + ' ' + mesh + " --labels-b " + mesh + " --transfer-labels",  // --transfer-labels was ignored
       "--labels-b excludes --transfer-labels"},
      {"param " + mesh + " --no-split-caps", "--no-split-caps: applies to --layout voronoi only"},  // was ignored
      {"param " + mesh + " --patches abc", "expects a whole number from 1 to 100000, not 'abc'"},  // was "not in range"
      {"render " + mesh + " --azimuth 500", "expects a number from -360 to 360, not '500'"},
      {"segment " + mesh + " --layout quads --no-split-caps", "--no-split-caps: applies to --layout voronoi only"},
      {"param " + mesh + " --corners c.selection.txt --patches 5", "--corners: maps the disc as one patch: --patches does not apply"},
      {"compare " + mesh + " --corners c.selection.txt --patches 5", "--corners: maps the disc as one patch: --patches does not apply"},
  };
  for(const auto& [args, reason] : cases) {
    const Tool_run r = run(args + " -o " + out_dir().string());
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("diffuv: error: ", 0), 0u) << args << ": " << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out_dir())) << args;
  }
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

TEST_F(Tool, AnOutputPathThatIsAFileIsRefused)
{
  const std::string file = write("taken", "not a folder");
  const Tool_run r = run("param " + data_path("meshes/nefertiti.off") + " -o " + file);
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.err, "diffuv: error: cannot write " + file + ": exists and is not a directory\n");
  EXPECT_EQ(slurp(file), "not a folder");
}

// ---- The catalogue of bad inputs (doc/robustness.md) ----------------------------

// One test per kind of bad input a user brings: the exact stderr they see, the
// exit code, and whether anything was written. Inputs that diffuv can still use
// (holes, several components, polygons, ...) give a result and say what they met.

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
      {"one_zero_area_face", // the inner vertex moved onto the middle of edge 0-1: one triangle collapses
       {{"m.off", "OFF\n9 8 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n0.5 0 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n" + grid_faces}}, m, 0,
       "diffuv: warning: {d}/m.off: 1 face has zero area; its (u,v) triangle may be flat (column degen)\n",
       "9 vertices, 8 faces, 1 zero-area face\n"},
      {"duplicate_vertices_not_welded_strict", // vertex 9 repeats vertex 4; the right half of the grid uses it
       {{"m.off", "OFF\n10 8 0\n" + grid_points + "1 1 0\n3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 9\n3 3 4 7\n3 3 7 6\n3 9 5 8\n3 9 8 7\n"}},
       m + " --strict-input", 1,
       "diffuv: error: {d}/m.off: non-manifold edge or vertex, or inconsistent orientation (the faces around vertex 1 "
       "form 2 separate fans); vertices 4 and 9 have the same position: the mesh may need welding\n"},
      {"unwelded_seam_strict", // the right column of cells uses copies 9, 10, 11 of the middle points 1, 4, 7
       {{"m.off", "OFF\n12 8 0\n" + grid_points + "1 0 0\n1 1 0\n1 2 0\n3 0 1 4\n3 0 4 3\n3 9 2 5\n3 9 5 10\n"
                  "3 3 4 7\n3 3 7 6\n3 10 5 8\n3 10 8 11\n"}},
       m + " --strict-input", 0,
       "diffuv: warning: {d}/m.off: 3 border points lie where another border point lies: the mesh may need welding "
       "(reading stitches such borders unless --strict-input)\n",
       "12 vertices, 8 faces\n"},
      {"non_manifold_edge_strict", {{"m.off", "OFF\n10 10 0\n" + grid_points + "1 -1 1\n" + grid_faces + "3 1 0 9\n3 0 1 9\n"}},
       m + " --strict-input", 1,
       "diffuv: error: {d}/m.off:22: non-manifold edge or vertex, or inconsistent orientation (faces 0 and 9 both go "
       "from vertex 0 to vertex 1)\n"},
      {"non_manifold_vertex_strict", // a second grid cell touching the first at vertex 8 only
       {{"m.off", "OFF\n12 10 0\n" + grid_points + "3 3 0\n2 3 0\n3 2 0\n" + grid_faces + "3 8 11 9\n3 8 9 10\n"}},
       m + " --strict-input", 1,
       "diffuv: error: {d}/m.off: non-manifold edge or vertex, or inconsistent orientation (the faces around vertex 8 "
       "form 2 separate fans)\n"},
      // The same files repaired (the default): a result, the repair on the summary's second line.
      {"duplicate_vertices_not_welded",
       {{"m.off", "OFF\n10 8 0\n" + grid_points + "1 1 0\n3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 9\n3 3 4 7\n3 3 7 6\n3 9 5 8\n3 9 8 7\n"}},
       m, 0, "", "10 vertices, 8 faces\nrepaired: 1 coinciding point merged (borders stitched; a merged point has no (u,v) of its own) (--strict-input turns repairs off)\n"},
      {"unwelded_seam",
       {{"m.off", "OFF\n12 8 0\n" + grid_points + "1 0 0\n1 1 0\n1 2 0\n3 0 1 4\n3 0 4 3\n3 9 2 5\n3 9 5 10\n"
                  "3 3 4 7\n3 3 7 6\n3 10 5 8\n3 10 8 11\n"}},
       m, 0, "",
       "12 vertices, 8 faces\nrepaired: 3 coinciding points merged (borders stitched; a merged point has no (u,v) of "
       "its own) (--strict-input turns repairs off)\n"},
      {"non_manifold_edge", {{"m.off", "OFF\n10 10 0\n" + grid_points + "1 -1 1\n" + grid_faces + "3 1 0 9\n3 0 1 9\n"}}, m, 0,
       "", "\nrepaired: 1 duplicate face dropped (--strict-input turns repairs off)\n"},
      {"non_manifold_edge_of_three_faces",
       {{"m.off", "OFF\n11 10 0\n" + grid_points + "1 -1 1\n1 -1 -1\n" + grid_faces + "3 1 0 9\n3 0 1 10\n"}}, m, 0,
       "diffuv: warning: 2 of 3 patches cannot be parameterized (see the table); their faces have no (u,v)\n",
       "11 vertices, 10 faces\nrepaired: 1 non-manifold edge cut, 2 non-manifold vertices split (4 copies added) "
       "(--strict-input turns repairs off)\n3 patches"},
      {"non_manifold_vertex",
       {{"m.off", "OFF\n12 10 0\n" + grid_points + "3 3 0\n2 3 0\n3 2 0\n" + grid_faces + "3 8 11 9\n3 8 9 10\n"}}, m, 0, "",
       "12 vertices, 10 faces\nrepaired: 1 non-manifold vertex split (1 copy added) (--strict-input turns repairs off)\n"},
      {"moebius_strip", // three quads, the last joined to the first with a half twist
       {{"m.off", "OFF\n6 6 0\n1.5 0 0\n2.5 0 0\n-0.875 1.516 -0.433\n-1.125 1.949 0.433\n-1.125 -1.949 -0.433\n"
                  "-0.875 -1.516 0.433\n3 0 1 3\n3 0 3 2\n3 2 3 5\n3 2 5 4\n3 4 5 0\n3 4 0 1\n"}}, m, 1,
       "diffuv: error: {d}/m.off:14: the surface is not orientable (like a Moebius strip): faces 0 and 5 disagree on the "
       "direction of the edge between vertices 0 and 1, and no choice of orientations makes every face agree with its "
       "neighbours\n"},
      {"moebius_strip_strict",
       {{"m.off", "OFF\n6 6 0\n1.5 0 0\n2.5 0 0\n-0.875 1.516 -0.433\n-1.125 1.949 0.433\n-1.125 -1.949 -0.433\n"
                  "-0.875 -1.516 0.433\n3 0 1 3\n3 0 3 2\n3 2 3 5\n3 2 5 4\n3 4 5 0\n3 4 0 1\n"}}, m + " --strict-input", 1,
       "diffuv: error: {d}/m.off:14: non-manifold edge or vertex, or inconsistent orientation (faces 0 and 5 both go from "
       "vertex 0 to vertex 1)\n"},
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

// correspond warns of zero-area faces as param does, once per mesh, and maps.
TEST_F(Tool, CorrespondWarnsOfZeroAreaFacesOnEitherMesh)
{
  // The inner vertex moved onto vertex 1: two triangles collapse.
  write("flat.off", "OFF\n9 8 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 0 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n" + grid_faces);
  write("grid.off", "OFF\n9 8 0\n" + grid_points + grid_faces);
  write("l.txt", "0\n0\n0\n0\n0\n0\n0\n0\n");
  const std::string d = dir_.string();
  const Tool_run both = run("correspond " + d + "/flat.off " + d + "/flat.off --labels-a " + d +
                            "/l.txt --transfer-labels -o " + out_dir().string());
  EXPECT_EQ(both.code, 0) << both.err;
  const std::string warning = "diffuv: warning: " + d + "/flat.off: 2 faces have zero area; their (u,v) triangles may be flat\n";
  EXPECT_EQ(both.err, warning + warning);
  EXPECT_EQ(read_csv(out_dir() / "correspondence.csv").size(), 10u);  // a header and 9 vertices
  const Tool_run clean = run("correspond " + d + "/grid.off " + d + "/flat.off --labels-a " + d +
                             "/l.txt --transfer-labels -o " + out_dir().string());
  EXPECT_EQ(clean.code, 0) << clean.err;
  EXPECT_EQ(clean.err, warning);  // B only
}

} // namespace
