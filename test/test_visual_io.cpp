// Tests of the visual outputs in include/diffuv/io: the SVG uv layout
// (write_svg.h) and the checkerboard texture, PNG and MTL writers
// (write_texture.h).
//
// Expectations are independent of the writers: the SVG is parsed by Python's
// xml.etree (a real XML parser) and its polygons compared with the atlas; the
// PNG is decoded by stb_image (not the encoder's code); flipped and degenerate
// triangles are made by hand on a flat grid.
#include "test_data.h"

#include <diffuv/output/write_svg.h>
#include <diffuv/output/write_obj.h>
#include <diffuv/render/texture.h>
#include <diffuv/parameterization/parameterize_disc.h>

// The decoder, for the round trip only: a static copy in this file.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using diffuv_test::Mesh;
using diffuv_test::Point_2;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using face_descriptor = boost::graph_traits<Mesh>::face_descriptor;
using Atlas = diffuv::Uv_atlas<Mesh>;

class VisualIo : public diffuv_test::Temp_dir_test {
protected:
  /// Parses the SVG file `svg` with Python's xml.etree and returns what it
  /// found, one key per line of the script's output (a parse error fails the test).
  std::map<std::string, std::string> inspect_svg(const std::string& svg)
  {
    const std::string script = write("inspect.py", R"(import sys, xml.etree.ElementTree as ET
ns = '{http://www.w3.org/2000/svg}'
root = ET.parse(sys.argv[1]).getroot()
polys = list(root.iter(ns + 'polygon'))
print('root', root.tag)
print('viewBox', len(root.get('viewBox', '').split()))
print('polygons', len(polys))
print('red', sum(1 for p in polys if p.get('fill') == '#e02020'))
print('orange', sum(1 for p in polys if p.get('fill') == '#ff9900'))
print('plain', sum(1 for p in polys if p.get('fill') is None))
print('polylines', len(list(root.iter(ns + 'polyline'))))
for l in root.iter(ns + 'polyline'):
    print(l.get('class'), len(l.get('points').split()))
print('texts', len(list(root.iter(ns + 'text'))))
print('first_polygon', polys[0].get('points') if polys else '')
)");
    const std::string result = path("inspect.txt");
    const std::string command = "python3 '" + script + "' '" + svg + "' > '" + result + "' 2> '" + path("inspect.err") + "'";
    const int rc = std::system(command.c_str());
    std::ifstream err(path("inspect.err"));
    std::stringstream err_text;
    err_text << err.rdbuf();
    EXPECT_EQ(rc, 0) << "xml.etree could not parse " << svg << ":\n" << err_text.str();
    std::map<std::string, std::string> found;
    std::ifstream in(result);
    std::string line;
    while(std::getline(in, line)) {
      const auto space = line.find(' ');
      if(space != std::string::npos) found[line.substr(0, space)] = line.substr(space + 1);
    }
    return found;
  }
};

// An atlas of a flat nx x ny grid with uv = (x, y), after `edit` changes the uv.
template <class Edit>
void grid_atlas(const Mesh& grid, Atlas& atlas, Edit edit)
{
  std::vector<vertex_descriptor> vs(vertices(grid).begin(), vertices(grid).end());
  std::vector<Point_2> uv;
  for(vertex_descriptor v : vs) uv.emplace_back(grid.point(v).x(), grid.point(v).y());
  edit(uv);
  atlas.add_chart(std::vector<face_descriptor>(faces(grid).begin(), faces(grid).end()), vs, uv);
}

TEST_F(VisualIo, NefertitiSvgParsesWithOnePolygonPerFaceAndExactUv)
{
  const Mesh& mesh = diffuv_test::cgal_mesh("nefertiti.off");
  ASSERT_EQ(num_faces(mesh), 562u);
  Atlas atlas(mesh);
  diffuv::Four_sides<vertex_descriptor> sides;
  diffuv::Disc_parameterization_report<Mesh> disc_report;
  ASSERT_TRUE(diffuv::parameterize_disc(mesh, mesh.points(), {}, atlas, {}, &disc_report).ok());
  sides = disc_report.sides;

  const std::string svg = path("nefertiti.svg");
  diffuv::write_uv_layout_svg(svg, atlas, 0, &sides);
  auto found = inspect_svg(svg);
  EXPECT_EQ(found["root"], "{http://www.w3.org/2000/svg}svg");
  EXPECT_EQ(found["viewBox"], "4");
  EXPECT_EQ(found["polygons"], "562");
  EXPECT_EQ(std::stoul(found["plain"]) + std::stoul(found["red"]) + std::stoul(found["orange"]), 562u);
  EXPECT_EQ(found["polylines"], "4");
  // Each side has a point per vertex (all are in the one chart).
  EXPECT_EQ(found["side_u1"], std::to_string(sides.u1.size()));
  EXPECT_EQ(found["side_u2"], std::to_string(sides.u2.size()));
  EXPECT_EQ(found["side_v1"], std::to_string(sides.v1.size()));
  EXPECT_EQ(found["side_v2"], std::to_string(sides.v2.size()));
  EXPECT_EQ(found["texts"], "5"); // the counts and four legend entries

  // The first polygon holds the exact uv of the chart's first triangle.
  std::istringstream points(found["first_polygon"]);
  const auto& chart = atlas.chart(0);
  for(int k = 0; k < 3; ++k) {
    std::string pair;
    ASSERT_TRUE(static_cast<bool>(points >> pair));
    const auto comma = pair.find(',');
    ASSERT_NE(comma, std::string::npos) << pair;
    EXPECT_EQ(std::strtod(pair.substr(0, comma).c_str(), nullptr), chart.uv[chart.triangles[0][k]].x());
    EXPECT_EQ(std::strtod(pair.substr(comma + 1).c_str(), nullptr), chart.uv[chart.triangles[0][k]].y());
  }

  // The stream overload writes the same text as the file overload.
  std::ostringstream text;
  diffuv::write_uv_layout_svg(text, atlas, 0, &sides);
  std::ifstream file(svg);
  std::stringstream file_text;
  file_text << file.rdbuf();
  EXPECT_EQ(text.str(), file_text.str());

  // Without sides: no polylines and no legend.
  diffuv::write_uv_layout_svg(svg, atlas, 0);
  found = inspect_svg(svg);
  EXPECT_EQ(found["polygons"], "562");
  EXPECT_EQ(found["polylines"], "0");
  EXPECT_EQ(found["texts"], "1");
}

TEST_F(VisualIo, OneFlippedTriangleIsRedOneDegenerateIsOrange)
{
  const Mesh grid = diffuv_test::make_grid(3, 3); // 18 faces
  // Corner (3,0) is in one face only, (2/3,0) (1,0) (1,1/3): moving it above
  // the line through the two others flips that face. Corner (0,3) is in one
  // face only, (0,2/3) (1/3,1) (0,1): moving it onto (0,2/3) collapses it.
  auto flip_one = [](std::vector<Point_2>& uv) {
    uv[diffuv_test::grid_vertex(3, 3, 0)] = Point_2(0.7, 0.3);
    uv[diffuv_test::grid_vertex(3, 0, 3)] = uv[diffuv_test::grid_vertex(3, 0, 2)];
  };
  {
    Atlas atlas(grid);
    grid_atlas(grid, atlas, flip_one);
    const std::string svg = path("flipped.svg");
    diffuv::write_uv_layout_svg(svg, atlas, 0);
    auto found = inspect_svg(svg);
    EXPECT_EQ(found["polygons"], "18");
    EXPECT_EQ(found["red"], "1");
    EXPECT_EQ(found["orange"], "1");
    EXPECT_EQ(found["plain"], "16");
  }
  {
    // The whole chart mirrored: most faces are now clockwise, the one face
    // that was flipped is counter-clockwise and is the only red one.
    Atlas atlas(grid);
    grid_atlas(grid, atlas, [&](std::vector<Point_2>& uv) {
      flip_one(uv);
      for(Point_2& p : uv) p = Point_2(1. - p.x(), p.y());
    });
    const std::string svg = path("mirrored.svg");
    diffuv::write_uv_layout_svg(svg, atlas, 0);
    auto found = inspect_svg(svg);
    EXPECT_EQ(found["red"], "1");
    EXPECT_EQ(found["orange"], "1");
  }
  {
    // The untouched grid: nothing is red or orange.
    Atlas atlas(grid);
    grid_atlas(grid, atlas, [](std::vector<Point_2>&) {});
    std::ostringstream out;
    diffuv::write_uv_layout_svg(out, atlas, 0);
    EXPECT_EQ(out.str().find("#e02020"), std::string::npos);
    EXPECT_EQ(out.str().find("#ff9900"), std::string::npos);
    EXPECT_NE(out.str().find("18 faces, 0 flipped, 0 degenerate"), std::string::npos);
  }
}

TEST_F(VisualIo, SvgRejectsBadArgumentsAndMissingFolders)
{
  const Mesh grid = diffuv_test::make_grid(2, 2);
  Atlas atlas(grid);
  grid_atlas(grid, atlas, [](std::vector<Point_2>&) {});
  std::ostringstream out;
  EXPECT_THROW(diffuv::write_uv_layout_svg(out, atlas, 1), std::out_of_range);
  EXPECT_THROW(diffuv::write_uv_layout_svg(out, atlas, 0, nullptr, 0), std::invalid_argument);
  EXPECT_THROW(diffuv::write_uv_layout_svg(path("missing/uv.svg"), atlas, 0), diffuv::Output_error);
  EXPECT_FALSE(fs::exists(path("missing")));
  // A failed write leaves no file behind.
  EXPECT_THROW(diffuv::write_uv_layout_svg(path("uv.svg"), atlas, 3), std::out_of_range);
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(VisualIo, CheckerTextureAlternatesWithAGrid)
{
  const int size = 512, cells = 8, cell = size / cells;
  const std::vector<unsigned char> rgb = diffuv::checker_texture(size, cells);
  ASSERT_EQ(rgb.size(), static_cast<std::size_t>(size * size * 3));
  auto pixel = [&](int x, int y) {
    const unsigned char* p = &rgb[3 * (static_cast<std::size_t>(y) * size + x)];
    return diffuv::Color{p[0], p[1], p[2]};
  };
  const diffuv::Color light{235, 235, 225}, dark{50, 90, 170}, grid{20, 20, 20};
  // The two cell colours contrast (a difference of over 100 in each of R and G).
  EXPECT_GT(light.r - dark.r, 100);
  EXPECT_GT(light.g - dark.g, 100);
  // Every cell centre, alternating from a light top-left cell.
  for(int j = 0; j < cells; ++j)
    for(int i = 0; i < cells; ++i)
      EXPECT_EQ(pixel(i * cell + cell / 2, j * cell + cell / 2), (i + j) % 2 == 0 ? light : dark)
          << "cell " << i << ", " << j;
  // Thin grid lines: on the border of the image and of every cell, not beside them.
  EXPECT_EQ(pixel(0, 0), grid);
  EXPECT_EQ(pixel(size - 1, 100), grid);
  EXPECT_EQ(pixel(100, size - 1), grid);
  EXPECT_EQ(pixel(cell, cell / 2), grid);
  EXPECT_EQ(pixel(cell - 1, cell / 2), grid);
  EXPECT_EQ(pixel(cell - 2, cell / 2), light);
  EXPECT_EQ(pixel(cell + 1, cell / 2), dark);
  EXPECT_EQ(pixel(1, cell / 2), light);

  // Cells that do not divide the size, and bad arguments.
  EXPECT_EQ(diffuv::checker_texture(100, 3).size(), 100u * 100u * 3u);
  EXPECT_THROW(diffuv::checker_texture(4, 0), std::invalid_argument);
  EXPECT_THROW(diffuv::checker_texture(4, 5), std::invalid_argument);
}

// Decodes a PNG held in memory with stb_image as RGB: (width, height, channels in the file, pixels).
struct Decoded_png {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> rgb;
};
Decoded_png decode_png(const std::string& bytes)
{
  Decoded_png d;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                                              &d.width, &d.height, &d.channels, 3);
  if(data == nullptr) {
    ADD_FAILURE() << stbi_failure_reason();
    return d;
  }
  d.rgb.assign(data, data + static_cast<std::size_t>(d.width) * d.height * 3);
  stbi_image_free(data);
  return d;
}

TEST(IndexedPng, CheckerPngHoldsTheCheckerTexturesPixels)
{
  // Cells that divide the size and cells that do not, one cell, one pixel per cell,
  // and the size diffuv param writes (1024 pixels, squares of 16).
  for(const auto& [size, cells] : std::vector<std::pair<int, int>>{{1024, 64}, {512, 8}, {100, 3}, {33, 33}, {7, 1}, {1, 1}}) {
    std::ostringstream out;
    ASSERT_TRUE(diffuv::write_checker_png(out, size, cells));
    const Decoded_png back = decode_png(out.str());
    EXPECT_EQ(back.width, size);
    EXPECT_EQ(back.height, size);
    EXPECT_EQ(back.rgb, diffuv::checker_texture(size, cells)) << size << " pixels, " << cells << " cells";
  }
  std::ostringstream out;
  EXPECT_THROW(diffuv::write_checker_png(out, 4, 5), std::invalid_argument);
  EXPECT_THROW(diffuv::write_checker_png(out, 4, 0), std::invalid_argument);
  EXPECT_TRUE(out.str().empty()); // nothing written before the arguments are checked
}

TEST(IndexedPng, EveryBitDepthRoundTripsThroughStbImage)
{
  // Palettes needing 1, 2, 4 and 8 bits; a width that is not a multiple of 8
  // (the last byte of each row is partly padding); random indices, rows
  // repeated now and then (a repeated row is packed once).
  std::mt19937 random(7);
  const int w = 37, h = 23;
  for(std::size_t colours : {1u, 2u, 3u, 4u, 5u, 16u, 17u, 256u}) {
    std::vector<diffuv::Color> palette;
    for(std::size_t i = 0; i < colours; ++i)
      palette.push_back({static_cast<unsigned char>(random() % 256), static_cast<unsigned char>(random() % 256),
                         static_cast<unsigned char>(random() % 256)});
    std::vector<std::vector<unsigned char>> rows(h, std::vector<unsigned char>(w));
    for(int y = 0; y < h; ++y)
      for(int x = 0; x < w; ++x) rows[y][x] = y % 5 == 4 ? rows[y - 1][x] : static_cast<unsigned char>(random() % colours);
    std::ostringstream out;
    ASSERT_TRUE(diffuv::write_indexed_png(out, w, h, palette, [&](int y, unsigned char* indices) {
      std::copy(rows[y].begin(), rows[y].end(), indices);
    }));
    const Decoded_png back = decode_png(out.str());
    ASSERT_EQ(back.width, w);
    ASSERT_EQ(back.height, h);
    for(int y = 0; y < h; ++y)
      for(int x = 0; x < w; ++x) {
        const unsigned char* p = &back.rgb[3 * (static_cast<std::size_t>(y) * w + x)];
        ASSERT_EQ((diffuv::Color{p[0], p[1], p[2]}), palette[rows[y][x]]) << colours << " colours, pixel " << x << ", " << y;
      }
  }
  // Bad arguments: no colours, too many, an index beyond the palette, no
  // pixels; a callback that throws. Nothing is written in any of them.
  std::ostringstream out;
  auto zeros = [](int, unsigned char* indices) { std::fill(indices, indices + 4, 0); };
  EXPECT_THROW(diffuv::write_indexed_png(out, 4, 4, {}, zeros), std::invalid_argument);
  EXPECT_THROW(diffuv::write_indexed_png(out, 4, 4, std::vector<diffuv::Color>(257), zeros), std::invalid_argument);
  EXPECT_THROW(diffuv::write_indexed_png(out, 0, 4, std::vector<diffuv::Color>(2), zeros), std::invalid_argument);
  EXPECT_THROW(diffuv::write_indexed_png(out, 4, 4, std::vector<diffuv::Color>(2),
                                         [](int y, unsigned char* indices) { std::fill(indices, indices + 4, y == 2 ? 2 : 1); }),
               std::invalid_argument);
  EXPECT_THROW(diffuv::write_indexed_png(out, 4, 4, std::vector<diffuv::Color>(2),
                                         [](int y, unsigned char*) { if(y == 3) throw std::runtime_error("row 3"); }),
               std::runtime_error);
  EXPECT_TRUE(out.str().empty());
}

// stb_image checks neither the chunks' CRCs nor zlib's checksum: walk the
// file's chunks, check each CRC, and inflate the IDAT data with zlib into the
// expected rows (filter byte 0, indices packed from the high bits). The image
// is random and 8-bit, so its compressed data spans several IDAT chunks.
TEST(IndexedPng, ChunksCarryTheirCrcsAndTheRowsInflateExactly)
{
  std::mt19937 random(11);
  const int w = 600, h = 600;
  std::vector<diffuv::Color> palette(256);
  for(std::size_t i = 0; i < palette.size(); ++i) palette[i] = {static_cast<unsigned char>(i), 0, static_cast<unsigned char>(255 - i)};
  std::vector<unsigned char> indices(static_cast<std::size_t>(w) * h);
  for(auto& i : indices) i = static_cast<unsigned char>(random() % 256);
  std::ostringstream out;
  ASSERT_TRUE(diffuv::write_indexed_png(out, w, h, palette, [&](int y, unsigned char* row) {
    std::copy(indices.begin() + static_cast<std::ptrdiff_t>(y) * w, indices.begin() + static_cast<std::ptrdiff_t>(y + 1) * w, row);
  }));
  const std::string png = out.str();
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  auto be32 = [&](std::size_t at) {
    return (static_cast<std::uint32_t>(static_cast<unsigned char>(png[at])) << 24) |
           (static_cast<std::uint32_t>(static_cast<unsigned char>(png[at + 1])) << 16) |
           (static_cast<std::uint32_t>(static_cast<unsigned char>(png[at + 2])) << 8) |
           static_cast<std::uint32_t>(static_cast<unsigned char>(png[at + 3]));
  };
  std::vector<std::string> types;
  std::string idat;
  for(std::size_t at = 8; at < png.size();) {
    ASSERT_LE(at + 12, png.size());
    const std::size_t length = be32(at);
    ASSERT_LE(at + 12 + length, png.size());
    const std::string type = png.substr(at + 4, 4);
    const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(png.data() + at + 4), static_cast<uInt>(4 + length));
    EXPECT_EQ(be32(at + 8 + length), static_cast<std::uint32_t>(crc)) << "CRC of chunk " << types.size() << " (" << type << ")";
    if(type == "IDAT") idat += png.substr(at + 8, length);
    types.push_back(type);
    at += 12 + length;
  }
  ASSERT_GE(types.size(), 5u);
  EXPECT_EQ(types.front(), "IHDR");
  EXPECT_EQ(types[1], "PLTE");
  EXPECT_EQ(types.back(), "IEND");
  EXPECT_GT(std::count(types.begin(), types.end(), "IDAT"), 1); // 360 KB of random indices: several 64 KB blocks
  std::vector<unsigned char> rows(static_cast<std::size_t>(w + 1) * h + 1);
  uLongf size = static_cast<uLongf>(rows.size());
  ASSERT_EQ(uncompress(rows.data(), &size, reinterpret_cast<const Bytef*>(idat.data()), static_cast<uLong>(idat.size())), Z_OK);
  ASSERT_EQ(size, static_cast<uLongf>(w + 1) * h);
  for(int y = 0; y < h; ++y) {
    const unsigned char* r = &rows[static_cast<std::size_t>(y) * (w + 1)];
    ASSERT_EQ(r[0], 0) << "filter byte of row " << y;
    ASSERT_TRUE(std::equal(r + 1, r + 1 + w, indices.begin() + static_cast<std::ptrdiff_t>(y) * w)) << "row " << y;
  }
}

TEST_F(VisualIo, PngRoundTripThroughStbImage)
{
  // A non-square image of varied bytes (a wrong stride or channel order shows),
  // and the checkerboard.
  const int w = 37, h = 23;
  std::vector<unsigned char> varied(static_cast<std::size_t>(w * h * 3));
  for(std::size_t i = 0; i < varied.size(); ++i) varied[i] = static_cast<unsigned char>((i * 7919 + i / 5) % 256);
  const std::vector<std::pair<std::vector<unsigned char>, std::array<int, 2>>> images = {
      {varied, {w, h}}, {diffuv::checker_texture(256, 4), {256, 256}}};
  for(const auto& [rgb, size] : images) {
    const std::string png = path("image.png");
    diffuv::write_png_file(png, size[0], size[1], rgb);
    int rw = 0, rh = 0, channels = 0;
    unsigned char* data = stbi_load(png.c_str(), &rw, &rh, &channels, 0);
    ASSERT_NE(data, nullptr) << stbi_failure_reason();
    EXPECT_EQ(rw, size[0]);
    EXPECT_EQ(rh, size[1]);
    EXPECT_EQ(channels, 3);
    const std::vector<unsigned char> back(data, data + static_cast<std::size_t>(rw) * rh * channels);
    stbi_image_free(data);
    EXPECT_EQ(back, rgb);
  }
}

TEST_F(VisualIo, PngRejectsBadImagesAndMissingFolders)
{
  const std::vector<unsigned char> rgb(4 * 4 * 3, 128);
  EXPECT_THROW(diffuv::write_png_file(path("missing/t.png"), 4, 4, rgb), diffuv::Output_error);
  EXPECT_FALSE(fs::exists(path("missing")));
  EXPECT_THROW(diffuv::write_png_file(path("t.png"), 4, 5, rgb), std::invalid_argument);
  EXPECT_THROW(diffuv::write_png_file(path("t.png"), 0, 4, rgb), std::invalid_argument);
  EXPECT_TRUE(fs::is_empty(dir_)); // no file, no temporary left
}

TEST_F(VisualIo, MtlNamesTheTexture)
{
  std::ostringstream out;
  diffuv::write_mtl(out, "checker", "nefertiti.checker.png");
  const std::string text = out.str();
  EXPECT_NE(text.find("newmtl checker\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nKd 1 1 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nmap_Kd nefertiti.checker.png\n"), std::string::npos) << text;
  // newmtl comes before the statements that describe the material.
  EXPECT_LT(text.find("newmtl"), text.find("map_Kd"));

  diffuv::write_mtl(path("m.mtl"), "checker", "nefertiti.checker.png");
  std::ifstream in(path("m.mtl"));
  std::stringstream file_text;
  file_text << in.rdbuf();
  EXPECT_EQ(file_text.str(), text);

  EXPECT_THROW(diffuv::write_mtl(out, "two words", "t.png"), std::invalid_argument);
  EXPECT_THROW(diffuv::write_mtl(out, "", "t.png"), std::invalid_argument);
  EXPECT_THROW(diffuv::write_mtl(out, "checker", "a\nb.png"), std::invalid_argument);
  EXPECT_THROW(diffuv::write_mtl(path("missing/m.mtl"), "checker", "t.png"), diffuv::Output_error);
  EXPECT_FALSE(fs::exists(path("missing")));
}

} // namespace
