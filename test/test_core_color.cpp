// Tests of include/diffuv/core/color.h: the colour type (its order is the
// ranking of painted colours) and the label palette.
#include <diffuv/core/color.h>

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <vector>

namespace {

using diffuv::Color;

TEST(Color, ComparedChannelByChannelRedFirst)
{
  EXPECT_EQ((Color{1, 2, 3}), (Color{1, 2, 3}));
  EXPECT_NE((Color{1, 2, 3}), (Color{1, 2, 4}));
  EXPECT_LT((Color{0, 255, 255}), (Color{1, 0, 0}));
  EXPECT_LT((Color{1, 0, 255}), (Color{1, 1, 0}));
  EXPECT_LT((Color{1, 1, 0}), (Color{1, 1, 1}));
  EXPECT_FALSE((Color{1, 1, 1}) < (Color{1, 1, 1}));
  EXPECT_EQ(Color(), (Color{0, 0, 0}));
  std::ostringstream text;
  text << Color{255, 0, 7};
  EXPECT_EQ(text.str(), "(255,0,7)");
}

TEST(LabelsPalette, WellSeparatedThenDistinct)
{
  EXPECT_EQ(diffuv::label_color(0), (Color{31, 119, 180}));
  EXPECT_EQ(diffuv::label_color(3), (Color{214, 39, 40}));
  EXPECT_EQ(diffuv::label_color(19), (Color{158, 218, 229}));
  std::set<Color> seen;
  const int n = 1 << 17;
  for(int label = 0; label < n; ++label)
    seen.insert(diffuv::label_color(label));
  EXPECT_EQ(seen.size(), std::size_t(n));
}

} // namespace
