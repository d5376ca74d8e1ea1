// diffuv tool: the pictures of `param` and `render` — PNG render, SVG layouts.
#include "pictures.h"

#include <diffuv/output/write_svg.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace diffuv_cli {
namespace {

diffuv::View parse_view(const std::string& s)
{
  if(s == "front") return diffuv::View::front;
  if(s == "back") return diffuv::View::back;
  if(s == "left") return diffuv::View::left;
  if(s == "right") return diffuv::View::right;
  if(s == "top") return diffuv::View::top;
  return diffuv::View::iso;
}

} // namespace

std::pair<int, int> picture_size(const std::string& s)
{
  const auto size = parse_size(s);
  if(!size)
    throw CLI::ValidationError("--size", "expects WxH with " + std::to_string(smallest_picture_side) + " <= W, H <= " +
                                             std::to_string(largest_picture_side) + ", e.g. 800x600, not " + s);
  return *size;
}

diffuv::Up_axis up_axis(const Input_mesh& in, const Param_options& options)
{
  return options.up == "x"   ? diffuv::Up_axis::x
         : options.up == "y" ? diffuv::Up_axis::y
         : options.up == "z" ? diffuv::Up_axis::z
                             : diffuv::guess_up_axis(in.mesh, in.mesh.points());
}

diffuv::Image picture(const Input_mesh& in, const Parameterization& result, const std::vector<Chart_measure>& measures,
                      const Param_options& options)
{
  diffuv::Render_options look;
  std::tie(look.width, look.height) = picture_size(options.size);
  look.view = parse_view(options.view);
  look.up = up_axis(in, options);
  if(!std::isnan(options.azimuth)) {
    look.use_angles = true;
    look.azimuth = options.azimuth;
    look.elevation = options.elevation;
  }
  look.isolines = options.isolines;
  const auto& atlas = *result.atlas;
  if(options.color == "patches")
    return diffuv::render_mesh(
        in.mesh, in.mesh.points(),
        [&](Mesh::Face_index f) { return diffuv::patch_color(result.seg.face_patch[f.idx()]); },
        atlas.corner_uv_map(), look);

  // Per-face distortion, chart by chart. The colour is the message: no
  // isolines where they would be under 6 pixels apart (many small charts).
  look.min_line_spacing = 6.;
  std::vector<double> value(num_faces(in.mesh), std::numeric_limits<double>::quiet_NaN());
  std::vector<bool> flipped(num_faces(in.mesh), false);
  double largest = 1.;
  for(std::size_t p = 0; p < result.patches.size(); ++p) {
    if(!result.patches[p].status) continue;
    const auto& chart = atlas.chart(result.patches[p].chart);
    for(std::size_t k = 0; k < chart.faces.size(); ++k) {
      const auto& d = measures[p].per_face[k];
      const double v = options.color == "angle" ? d.angle : d.area;
      value[chart.faces[k].idx()] = v;
      flipped[chart.faces[k].idx()] = d.flipped;
      if(std::isfinite(v)) largest = std::max(largest, v);
    }
  }
  const double top = std::min(largest, 10.); // 1 .. 10 on a log scale; more is clamped
  diffuv::Image image = diffuv::render_mesh(
      in.mesh, in.mesh.points(),
      [&](Mesh::Face_index f) {
        const double v = value[f.idx()];
        if(flipped[f.idx()]) return diffuv::Color{230, 0, 200};
        if(std::isnan(v)) return diffuv::Color{150, 150, 150};
        return diffuv::heat_color(top > 1. ? std::log(std::max(v, 1.)) / std::log(top) : 0.);
      },
      atlas.corner_uv_map(), look);
  diffuv::draw_color_bar(image, 1., top, options.color + " distortion (log)");
  return image;
}

void write_uv_layouts(diffuv::Output_folder& out, const Input_mesh& in, const Parameterization& result)
{
  for(std::size_t p = 0; p < result.patches.size(); ++p)
    if(result.patches[p].status)
      diffuv::write_uv_layout_svg(out.open(output_name(in.path, ".patch" + std::to_string(p) + ".svg")), *result.atlas,
                                  result.patches[p].chart, &result.patches[p].sides);
}

} // namespace diffuv_cli
