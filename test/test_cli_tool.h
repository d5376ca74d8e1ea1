// Tests of the diffuv tool as a user runs it (test_cli_*.cpp): the tool run
// in a fresh folder, its exit code, stdout and stderr, and small meshes.
#ifndef DIFFUV_TEST_CLI_TOOL_H
#define DIFFUV_TEST_CLI_TOOL_H

#include "test_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <utility>
#include <vector>

namespace diffuv_cli_test {

namespace fs = std::filesystem;
using diffuv_test::data_path;

struct Tool_run {
  int code;
  std::string out, err;
};

inline std::string slurp(const fs::path& p)
{
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// The width and height of the PNG file `p`, from its IHDR chunk (big-endian
/// at bytes 16 and 20); {0, 0} if it does not start as a PNG file does.
inline std::pair<std::uint32_t, std::uint32_t> png_size(const fs::path& p)
{
  const std::string png = slurp(p);
  if(png.size() < 24 || png.substr(0, 8) != std::string("\x89PNG\r\n\x1a\n", 8)) return {0, 0};
  auto be32 = [&](std::size_t at) {
    return (std::uint32_t(std::uint8_t(png[at])) << 24) | (std::uint32_t(std::uint8_t(png[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(png[at + 2])) << 8) | std::uint32_t(std::uint8_t(png[at + 3]));
  };
  return {be32(16), be32(20)};
}

/// The names of the files in folder `p`, sorted.
inline std::vector<std::string> files_in(const fs::path& p)
{
  std::vector<std::string> names;
  for(const auto& e : fs::directory_iterator(p)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

#ifndef DIFFUV_TOOL_PATH
// Built without the tool (DIFFUV_BUILD_TOOL=OFF, as scripts/sanitize.sh does):
// these tests are skipped there and run in the normal build.
#define DIFFUV_TOOL_PATH ""
#define DIFFUV_NO_TOOL 1
#endif

/// A fixture that runs the tool with a fresh folder of its own.
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

/// CGAL's nefertiti.off and its square corners, as arguments of a command.
inline std::string nefertiti_with_square_corners()
{
  return data_path("meshes/nefertiti.off") + " --corners " + data_path("selections/square_corners.selection.txt");
}

inline std::vector<std::vector<std::string>> read_csv(const fs::path& p)
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

// A 3x3-vertex grid: vertices 0..8 row by row, 8 triangles; 4 is the only inner vertex.
const std::string grid_points = "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n";
const std::string grid_faces = "3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 3 4 7\n3 3 7 6\n3 4 5 8\n3 4 8 7\n";
const std::string grid_off = "OFF\n9 8 0\n" + grid_points + grid_faces;

// Two 3x3 grids side by side, the second one's indices shifted by 9.
inline std::string two_grids()
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

} // namespace diffuv_cli_test

#endif // DIFFUV_TEST_CLI_TOOL_H
