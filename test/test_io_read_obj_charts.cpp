// Tests of read_obj_charts() (io/read_obj_charts.h): the charts of an OBJ
// atlas, and bad files reported with their line.
#include "test_data.h"

#include <diffuv/io/read_obj_charts.h>

#include <fstream>
#include <string>

namespace {
using namespace diffuv_test;
}  // namespace

TEST(ObjCharts, ChartsAreFacesJoinedBySharedTextureCoordinates)
{
  // Two triangles sharing an edge with the same vt at both ends: one chart;
  // a third across an edge whose vt differ (a seam): another chart.
  const std::string path = testing::TempDir() + "diffuv_charts.obj";
  {
    std::ofstream out(path);
    out << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0\nvt 0.5 1\nvt 1 0\n"
           "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 2/5 5/7 3/6\n";
  }
  const diffuv::Obj_charts obj = diffuv::read_obj_charts(path);
  ASSERT_EQ(obj.triangles.size(), 3u);
  EXPECT_EQ(obj.number_of_charts, 2u);
  EXPECT_EQ(obj.chart[0], obj.chart[1]);
  EXPECT_NE(obj.chart[0], obj.chart[2]);
  // Groups keep charts apart even where vt are shared.
  {
    std::ofstream out(path);
    out << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
           "g a\nf 1/1 2/2 3/3\ng b\nf 1/1 3/3 4/4\n";
  }
  EXPECT_EQ(diffuv::read_obj_charts(path).number_of_charts, 2u);
  std::remove(path.c_str());
}

TEST(ObjCharts, BadFilesAreReportedWithTheirLine)
{
  const std::string path = testing::TempDir() + "diffuv_bad.obj";
  auto reason = [&](const std::string& text) {
    {
      std::ofstream out(path);
      out << text;
    }
    try {
      diffuv::read_obj_charts(path);
    } catch(const diffuv::Input_error& e) {
      return std::to_string(e.line()) + ": " + e.reason();
    }
    return std::string("no error");
  };
  EXPECT_EQ(reason("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 4/1\n"), "5: face corner '4/1': no vertex with that index");
  EXPECT_EQ(reason("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n"), "5: face corner '2/2': no texture coordinate with that index");
  EXPECT_EQ(reason("v 0 0 zero\n"), "1: vertex coordinate 'zero' is not a finite number");
  EXPECT_EQ(reason("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "0: no face with texture coordinates (f v/vt ...)");
  EXPECT_EQ(reason("v 0 0 0\nf 1 1\n"), "2: a face needs three corners or more");
  std::remove(path.c_str());
  try {
    diffuv::read_obj_charts(path);
    ADD_FAILURE() << "a missing file was read";
  } catch(const diffuv::Input_error& e) {
    EXPECT_EQ(e.reason(), "cannot open file");
  }
}
