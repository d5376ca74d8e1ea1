// Tests of the diffuv tool as a user runs it: exit codes, the one-line
// errors, and that a failure writes nothing.
#include "test_data.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
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

class Tool : public ::testing::Test {
protected:
  void SetUp() override
  {
    dir_ = fs::temp_directory_path() /
           ("diffuv_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Tool_run run(const std::string& args)
  {
    const std::string cmd = std::string(DIFFUV_TOOL_PATH) + " " + args + " >" + (dir_ / "stdout").string() + " 2>" +
                            (dir_ / "stderr").string();
    const int status = std::system(cmd.c_str());
    return Tool_run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "stdout"), slurp(dir_ / "stderr")};
  }
  std::string write(const std::string& name, const std::string& content)
  {
    std::ofstream(dir_ / name) << content;
    return (dir_ / name).string();
  }
  fs::path out_dir() const { return dir_ / "out"; }

  fs::path dir_;
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
      {"param " + data_path("meshes/cow.off"),
       "diffuv: error: " + data_path("meshes/cow.off") + ": the mesh is closed (no boundary), not a topological disc"},
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

TEST_F(Tool, AnOutputPathThatIsAFileIsRefused)
{
  const std::string file = write("taken", "not a folder");
  const Tool_run r = run("param " + data_path("meshes/nefertiti.off") + " -o " + file);
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.err, "diffuv: error: cannot write " + file + ": exists and is not a directory\n");
  EXPECT_EQ(slurp(file), "not a folder");
}

} // namespace
