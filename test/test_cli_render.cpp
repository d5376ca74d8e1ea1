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
  EXPECT_EQ(files_in(out_dir()), std::vector<std::string>{"three_peaks.png"});
  EXPECT_EQ(png_size(out_dir() / "three_peaks.png"), (std::pair<std::uint32_t, std::uint32_t>{320, 240}));
  fs::remove_all(out_dir());
  for(const char* args : {" --size 12", " --azimuth nan", " --elevation 30", " --view sideways", " --color red"}) {
    const Tool_run bad = run("render " + data_path("meshes/three_peaks.off") + args + " -o " + out_dir().string());
    EXPECT_EQ(bad.code, 2) << args;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << args << ": " << bad.err;
    EXPECT_FALSE(fs::exists(out_dir())) << args;
  }
}

} // namespace
