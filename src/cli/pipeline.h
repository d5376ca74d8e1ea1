// diffuv tool: the pipeline that `param` and `render` share — a mesh read
// (inputs.h), cut into patches or taken whole with given corners, mapped
// chart by chart, and measured; the options that steer it, and its clock.
#ifndef DIFFUV_CLI_PIPELINE_H
#define DIFFUV_CLI_PIPELINE_H

#include "inputs.h"

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/parameterization/repair_folds.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace diffuv_cli {

using Atlas = diffuv::Uv_atlas<Mesh>;

/// The options of `param` and `render`.
struct Param_options {
  std::string mesh;
  std::string corners;
  std::string output = "diffuv-out";
  int runs = 1;
  std::string distance = "fmm";
  bool no_repair = false;
  int warp_pieces = 6;       // pieces of each chart's warps of u and v (--warp-pieces; 0: plain rectangles)
  std::string view = "iso";
  std::string up = "auto";  // the mesh's up axis in the picture (--up): x, y, z or auto
  double azimuth = std::numeric_limits<double>::quiet_NaN(); // set: the camera's angles (refused with --view)
  double elevation = 20;
  std::string size = "800x600";
  int isolines = 10;
  bool svg = false;
  bool unit_squares = false; // write each chart on the unit square, not on its own rectangle
  bool stacked = false;      // each chart at the texture's origin, not packed into one texture
  int texture_size = 1024;   // the packed texture's width and height, in texels
  int gutter = 2;            // texels kept free between two packed charts
  std::string packer = "shelves"; // --packer: shelves (rows filled to the edge) or skyline (stb's, one density)
  std::string color = "patches";
  bool render_only = false; // diffuv render: the picture only
  std::size_t threads = 0;   // 0: every core (with oneTBB)
  Patch_cli_options patches;
  std::string outputs = "obj,glb,uv,patches,picture"; // param: what is written (--outputs)
  bool no_measure = false;   // skip the distortion measures (the table shows '-')
  bool quiet = false;        // print nothing but warnings and errors
};

/// One parameterization of the whole mesh: its patches and its atlas.
struct Parameterization {
  std::unique_ptr<Atlas> atlas;
  diffuv::Segmentation<Mesh> seg;
  diffuv::Patching_report patching;
  std::vector<diffuv::Patch_result<Mesh>> patches;
  double milliseconds = 0;       // patches + map
  double patches_ms = 0;         // making the patches
};

/// A disc mesh with four given corners: one chart.
/// \throws diffuv::Input_error naming the corner file for bad corners, else the mesh
Parameterization parameterize_with_corners(const Input_mesh& in, const std::vector<Mesh::Vertex_index>& corners,
                                           const std::string& corner_file, const std::string& distance,
                                           const diffuv::Repair_options& repair,
                                           const diffuv::Chart_drawing_options& drawing = diffuv::Chart_drawing_options());

/// Any mesh: disc patches (from labels, or automatic), each mapped on its own.
Parameterization parameterize_by_patches(const Input_mesh& in, const Patch_cli_options& options,
                                         const std::string& distance, const diffuv::Repair_options& repair,
                                         std::size_t threads,
                                         const diffuv::Chart_drawing_options& drawing = diffuv::Chart_drawing_options());

/// The distortion of one patch's chart, face by face and in summary: measured
/// once, for the table and for the heat map.
struct Chart_measure {
  diffuv::Distortion_summary summary;
  std::vector<diffuv::Triangle_distortion> per_face; // one per face of the chart, in chart order
};

/// #P entries; a patch without a chart gets an empty measure. Each chart is
/// measured as the OBJ carries it: on its rectangle, or on the unit square.
std::vector<Chart_measure> measure_charts(const Input_mesh& in, const Parameterization& result, bool unit_squares);

/// How long each stage of a run took: "stages: read 120 ms, ..." at the end,
/// and, for meshes over a million vertices, a line on stderr as each stage
/// ends, so that a long run shows where it is.
struct Stage_clock {
  bool large = false;
  std::vector<std::pair<std::string, double>> stages;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  void restart() { start = std::chrono::steady_clock::now(); }
  // 950 ms, 9.70 s: milliseconds below a second, else seconds.
  static std::string duration(double ms)
  {
    char text[32];
    if(ms < 1000.) std::snprintf(text, sizeof text, "%.3g ms", ms);
    else std::snprintf(text, sizeof text, "%.2f s", ms / 1000.);
    return text;
  }
  void add(const std::string& name, double ms, const std::string& detail = {})
  {
    stages.emplace_back(name, ms);
    if(large)
      std::cerr << "diffuv: " << name << " done in " << duration(ms) << (detail.empty() ? "" : " (" + detail + ")")
                << std::endl;
  }
  void done(const std::string& name, const std::string& detail = {})
  {
    add(name, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(), detail);
    restart();
  }
  std::string summary() const
  {
    std::string s;
    for(std::size_t i = 0; i < stages.size(); ++i)
      s += (i ? ", " : "") + stages[i].first + ' ' + duration(stages[i].second);
    return s;
  }
};

} // namespace diffuv_cli

#endif // DIFFUV_CLI_PIPELINE_H
