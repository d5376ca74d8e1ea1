// diffuv tool: the pipeline of `param` and `render` — patches, charts, measures.
#include "pipeline.h"

#include <diffuv/parameterization/parameterize_disc.h>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace diffuv_cli {
namespace {

bool is_corner_problem(diffuv::Status_code code)
{
  switch(code) {
    case diffuv::Status_code::corner_count:
    case diffuv::Status_code::corner_out_of_range:
    case diffuv::Status_code::corner_not_on_border:
    case diffuv::Status_code::corner_duplicated:
      return true;
    default:
      return false;
  }
}

} // namespace

Parameterization parameterize_with_corners(const Input_mesh& in, const std::vector<Mesh::Vertex_index>& corners,
                                           const std::string& corner_file, const std::string& distance,
                                           const diffuv::Repair_options& repair, const diffuv::Chart_drawing_options& drawing)
{
  Parameterization result;
  result.atlas = std::make_unique<Atlas>(in.mesh);
  diffuv::Patch_result<Mesh> patch;
  const auto start = std::chrono::steady_clock::now();
  diffuv::Disc_parameterization_report<Mesh> report;
  patch.status = with_distance(distance, [&](auto tag) {
    return diffuv::parameterize_disc<decltype(tag)>(in.mesh, in.mesh.points(), corners, *result.atlas,
                                                    diffuv::Disc_parameterization_options{repair, drawing}, &report);
  });
  patch.sides = std::move(report.sides);
  patch.repair = report.repair;
  result.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if(!patch.status) {
    if(is_corner_problem(patch.status.code)) {
      std::string what = patch.status.what();
      if(patch.status.code == diffuv::Status_code::corner_not_on_border ||
         patch.status.code == diffuv::Status_code::corner_duplicated) {
        what += ": vertices"; // name the vertices, not only their places in the list
        for(auto c : corners) what += " " + std::to_string(c.idx());
      }
      throw diffuv::Input_error(corner_file, 1, what);
    }
    throw diffuv::Input_error(in.path, 0, patch.status.what());
  }
  patch.chart = 0;
  patch.milliseconds = result.milliseconds;
  result.seg.face_patch.assign(num_faces(in.mesh), 0);
  result.seg.patch_label = {0};
  result.seg.patch_part = {0};
  result.seg.patch_faces = {std::vector<Mesh::Face_index>(faces(in.mesh).begin(), faces(in.mesh).end())};
  result.patches.push_back(patch);
  return result;
}

Parameterization parameterize_by_patches(const Input_mesh& in, const Patch_cli_options& options,
                                         const std::string& distance, const diffuv::Repair_options& repair,
                                         std::size_t threads, const diffuv::Chart_drawing_options& drawing)
{
  Parameterization result;
  result.atlas = std::make_unique<Atlas>(in.mesh);
  const auto start = std::chrono::steady_clock::now();
  // The discs the layout keeps whole are mapped once, by its judge.
  auto known = std::make_shared<diffuv::Known_charts>();
  result.seg = make_patches(in, options, result.patching, known);
  result.patches_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.patches = with_distance(distance, [&](auto tag) {
    return diffuv::parameterize_patches<decltype(tag)>(in.mesh, in.mesh.points(), result.seg, *result.atlas,
                                                       diffuv::Patch_parameterization_options{repair, nullptr, true, threads, drawing, known.get()});
  });
  result.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<Chart_measure> measure_charts(const Input_mesh& in, const Parameterization& result, bool unit_squares)
{
  std::vector<Chart_measure> measures(result.patches.size());
  for(std::size_t p = 0; p < result.patches.size(); ++p) {
    const auto& r = result.patches[p];
    if(!r.status) continue;
    const auto& chart = result.atlas->chart(r.chart);
    Chart_measure& m = measures[p];
    // As the OBJ carries it: on the chart's rectangle, or on the unit square.
    if(unit_squares)
      m.summary = diffuv::measure_distortion(in.mesh, in.mesh.points(), chart.faces,
                                             result.atlas->chart_uv_map(r.chart), &m.per_face);
    else
      m.summary = diffuv::measure_distortion(in.mesh, in.mesh.points(), chart.faces,
                                             result.atlas->chart_texture_map(r.chart), &m.per_face);
  }
  return measures;
}

} // namespace diffuv_cli
