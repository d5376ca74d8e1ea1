// Tests of include/diffuv/core/color.h: the label palette.
#include <diffuv/core/color.h>

#include <gtest/gtest.h>

#include <set>

namespace {

using diffuv::Color;

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
