// Tests of `diffuv compare`: every method on the same patches, one table.
#include "test_cli_tool.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>

namespace {

using namespace diffuv_cli_test;

TEST_F(Tool, CompareRunsEveryMethodOnTheSamePatches)
{
  const Tool_run r = run("compare " + nefertiti_with_square_corners() + " --runs 1 -o " + out_dir().string());
  ASSERT_EQ(r.code, 0) << r.err;
  for(const char* method : {"diffuv ", "tutte ", "mean_value ", "authalic ", "conformal ", "lscm ", "arap "}) {
    const auto at = r.out.find(std::string("\n") + method);
    ASSERT_NE(at, std::string::npos) << method << r.out;
    const std::string row = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
    EXPECT_EQ(row.substr(row.size() - 3), "yes") << row; // every method is one-to-one on nefertiti
    EXPECT_TRUE(fs::exists(out_dir() / ("nefertiti." + std::string(method, std::strlen(method) - 1) + ".obj")));
  }
  // The paper's raw method folds with these corners; the default does not.
  const Tool_run raw = run("compare " + nefertiti_with_square_corners() + " --runs 1 --methods diffuv-graph-raw,diffuv");
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

// A list with spaces after its commas is the list without them (issue #19:
// "tutte, lscm" was refused, as a method named " lscm").
TEST_F(Tool, CompareMethodsMayHaveSpacesAfterTheCommas)
{
  const Tool_run r = run("compare " + nefertiti_with_square_corners() + " --runs 1 --methods 'tutte, lscm'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\ntutte "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nlscm "), std::string::npos) << r.out;
  const Tool_run empty = run("compare " + data_path("meshes/nefertiti.off") + " --methods 'tutte, ,lscm'");
  EXPECT_EQ(empty.code, 2) << empty.err;
  EXPECT_NE(empty.err.find("unknown method ''"), std::string::npos) << empty.err;
}

} // namespace
