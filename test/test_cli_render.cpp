// Tests of `diffuv render`: the picture alone, its size, its options.
#include "test_cli_tool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace diffuv_cli_test;

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

} // namespace
