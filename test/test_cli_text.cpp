// Unit tests of what the diffuv tool says and parses, without running it:
// picture sizes, lists of methods, output names, the data folder, tables,
// patch names and counts (src/cli/command_line.h, src/cli/table.h,
// diffuv/patches/patch_names.h, diffuv/internal/message_text.h).
#include "test_data.h"

#include "cli/command_line.h"
#include "cli/table.h"

#include <diffuv/internal/message_text.h>
#include <diffuv/patches/patch_names.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using diffuv_cli::Table;

TEST(CliText, SizeIsTwoWholeNumbersJoinedByAnX)
{
  EXPECT_EQ(diffuv_cli::parse_size("800x600"), std::make_optional(std::make_pair(800, 600)));
  EXPECT_EQ(diffuv_cli::parse_size("16x8192"), std::make_optional(std::make_pair(16, 8192)));
  for(const char* bad : {"800x600x3", "800x600x", "800x", "x600", "800", "", " 800x600", "800x600 ", "800 x600",
                         "+800x600", "-800x600", "800x6e2", "800.0x600", "15x600", "800x8193", "99999999999x600"})
    EXPECT_EQ(diffuv_cli::parse_size(bad), std::nullopt) << '"' << bad << '"';
}

// A number option's text is checked before it is converted: what is not a
// number is not called "out of range".
TEST(CliText, NumbersAreCheckedAsTextWithTheReason)
{
  using diffuv_cli::range_problem;
  for(const char* good : {"1", "100000", "42", "+7"}) EXPECT_EQ(range_problem(good, 1, 100000, true), "") << good;
  EXPECT_EQ(range_problem("abc", 1, 100000, true), "expects a whole number from 1 to 100000, not 'abc'");
  for(const char* bad : {"0", "-3", "100001", "1e3", "2.5", "", " 5", "5 ", "5x", "99999999999999999999999"})
    EXPECT_NE(range_problem(bad, 1, 100000, true), "") << '"' << bad << '"';
  EXPECT_EQ(range_problem("-12.5", -360, 360, false), "");
  EXPECT_EQ(range_problem("1e2", -360, 360, false), "");
  for(const char* bad : {"500", "nan", "inf", "1e999", "ten", "-360.5"})
    EXPECT_EQ(range_problem(bad, -360, 360, false), std::string("expects a number from -360 to 360, not '") + bad + "'") << bad;
}

TEST(CliText, ListItemsLoseTheSpacesAroundThem)
{
  using List = std::vector<std::string>;
  EXPECT_EQ(diffuv_cli::split_list("tutte, lscm"), (List{"tutte", "lscm"}));
  EXPECT_EQ(diffuv_cli::split_list(" diffuv ,\tarap\t"), (List{"diffuv", "arap"}));
  EXPECT_EQ(diffuv_cli::split_list("tutte"), (List{"tutte"}));
  EXPECT_EQ(diffuv_cli::split_list(""), List{});
  EXPECT_EQ(diffuv_cli::split_list("tutte,,lscm"), (List{"tutte", "", "lscm"})); // for the caller to refuse
  EXPECT_EQ(diffuv_cli::split_list("tutte, ,lscm"), (List{"tutte", "", "lscm"}));
}

TEST(CliText, AnOutputIsNamedOnce)
{
  using diffuv_cli::output_name;
  EXPECT_EQ(output_name("data/cow.off", ".obj"), "cow.obj");
  EXPECT_EQ(output_name("data/cow.off", ".patches.txt"), "cow.patches.txt");
  EXPECT_EQ(output_name("seg/cow.patches.ply", ".patches.txt"), "cow.patches.txt"); // not cow.patches.patches.txt
  EXPECT_EQ(output_name("seg/cow.patches.ply", ".patches.ply"), "cow.patches.ply");
  EXPECT_EQ(output_name("seg/cow.patches.ply", ".obj"), "cow.patches.obj");
  EXPECT_EQ(output_name("seg/cow.patches.ply", ".patch3.svg"), "cow.patches.patch3.svg"); // ".patch" is not ".patches"
  EXPECT_EQ(output_name("m.uv.off", ".uv.csv"), "m.uv.csv");
  EXPECT_EQ(output_name("patches.off", ".patches.txt"), "patches.patches.txt"); // the stem itself stays
  EXPECT_EQ(output_name("cowpatches.off", ".patches.txt"), "cowpatches.patches.txt"); // parts end at dots
  EXPECT_EQ(output_name("a.b.off", ".b.c.d"), "a.b.c.d");
}

class CliDataFolder : public diffuv_test::Temp_dir_test {};

TEST_F(CliDataFolder, TheEnvironmentThenTheInstalledDataThenTheBuildTree)
{
  using diffuv_cli::data_folder;
  const std::filesystem::path installed = dir_ / "bin" / ".." / "share" / "diffuv";
  EXPECT_EQ(data_folder("cow.off", nullptr, installed, "/built"), "/built"); // nothing installed
  std::filesystem::create_directories(dir_ / "share" / "diffuv" / "meshes");
  std::ofstream(dir_ / "share" / "diffuv" / "meshes" / "cow.off") << "OFF\n";
  EXPECT_EQ(data_folder("cow.off", nullptr, installed, "/built"), (dir_ / "share" / "diffuv").string());
  EXPECT_EQ(data_folder("nefertiti.off", nullptr, installed, "/built"), "/built"); // not installed
  EXPECT_EQ(data_folder("cow.off", "/mine", installed, "/built"), "/mine");
  EXPECT_EQ(data_folder("cow.off", nullptr, std::filesystem::path(), "/built"), "/built");
}

// Lines of a table's text.
std::vector<std::string> lines_of(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for(std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(CliText, TableColumnsAreAsWideAsTheirWidestEntry)
{
  Table table({{"name", 6, Table::left}, {"count", 5, Table::right}, {"ok", 3, Table::right}});
  table.add_row({"a", "1", "yes"});
  // The fixed widths of printf, as long as the entries fit.
  EXPECT_EQ(table.text(), "name   count  ok\na          1 yes\n");
  table.add_row({"b", "123456789", "no"});
  table.add_row({"c", "7"}, "  failed: why");
  EXPECT_EQ(table.text(),
            "name       count  ok\n"
            "a              1 yes\n"
            "b      123456789  no\n"
            "c              7  failed: why\n");
  for(const std::string& line : lines_of(table.text()))
    if(line.find("failed") == std::string::npos) EXPECT_EQ(line.size(), 20u) << line;
  EXPECT_EQ(diffuv_cli::formatted("%8.2f|%-3s|%zu", 3.14159, "x", std::size_t(42)), "    3.14|x  |42");
  EXPECT_EQ(diffuv_cli::formatted("%s", std::string(300, 'a').c_str()).size(), 300u);
}

TEST(CliText, PatchNamesAreUnique)
{
  EXPECT_EQ(diffuv::patch_name({3, 0, 0}), "3");
  EXPECT_EQ(diffuv::patch_name({0, 1, 0}), "0.1");
  EXPECT_EQ(diffuv::patch_name({0, 1, 1}), "0.1#2");
  EXPECT_EQ(diffuv::patch_name({7, 0, 2}), "7#3");
  // Two components of label 0, each a cap split in two: 0.1, 0.2, 0.1, 0.2 before.
  diffuv::Segmentation<diffuv_test::Mesh> seg;
  seg.patch_label = {0, 0, 0, 0, 5};
  seg.patch_part = {1, 2, 1, 2, 0};
  seg.patch_faces.resize(5);
  const std::vector<std::string> names = diffuv::patch_names(seg);
  EXPECT_EQ(names, (std::vector<std::string>{"0.1", "0.2", "0.1#2", "0.2#2", "5"}));
  const auto keys = diffuv::patch_keys(seg);
  EXPECT_EQ(std::set<diffuv::Patch_key>(keys.begin(), keys.end()).size(), keys.size());
}

TEST(CliText, CountsAgreeInNumber)
{
  using diffuv::internal::count_text;
  EXPECT_EQ(count_text(1, "patch", "patches"), "1 patch");
  EXPECT_EQ(count_text(0, "patch", "patches"), "0 patches");
  EXPECT_EQ(count_text(2, "patch", "patches"), "2 patches");
  EXPECT_EQ(count_text(1, "face has", "faces have"), "1 face has");
  EXPECT_EQ(count_text(3, "face has", "faces have"), "3 faces have");
  EXPECT_EQ(count_text(1, "label"), "1 label");
  EXPECT_EQ(count_text(12, "label"), "12 labels");
}

} // namespace
