// diffuv tool: `diffuv param` and `diffuv render` — parameterize a mesh patch
// by patch and write its uv-map (param) or its picture (render). The pipeline
// is in pipeline.cpp, the pictures in pictures.cpp, the printed report in
// report.cpp.
#include "commands.h"
#include "pictures.h"
#include "packing.h"
#include "pipeline.h"
#include "report.h"

#include <diffuv/io/atomic_file.h>
#include <diffuv/io/selection_file.h>
#include <diffuv/output/write_obj.h>
#include <diffuv/output/write_uv_table.h>
#include <diffuv/render/pack_charts.h>
#include <diffuv/render/texture.h>
#include <diffuv/render/texture_layout.h>
#include <diffuv/render/write_gltf.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace diffuv_cli {
namespace {

/// What --outputs names: obj (with its .mtl and checker texture), glb, atlas, uv, patches, picture.
struct Outputs {
  bool obj = false, glb = false, atlas = false, uv = false, patches = false, picture = false;
};

Outputs parse_outputs(const Param_options& options)
{
  if(options.render_only) return Outputs{false, false, false, false, false, true};
  Outputs o;
  for(const std::string& name : split_list(options.outputs)) {
    bool* flag = name == "obj" ? &o.obj : name == "glb" ? &o.glb : name == "atlas" ? &o.atlas : name == "uv" ? &o.uv
               : name == "patches" ? &o.patches : name == "picture" ? &o.picture : nullptr;
    if(!flag)
      throw CLI::ValidationError("--outputs", "unknown output '" + name + "' (obj, glb, atlas, uv, patches or picture)");
    if(*flag) throw CLI::ValidationError("--outputs", "'" + name + "' is listed twice");
    *flag = true;
  }
  if(!o.obj && !o.glb && !o.atlas && !o.uv && !o.patches && !o.picture && !options.svg)
    throw CLI::ValidationError("--outputs", "no output given");
  return o;
}

void run_param(const Param_options& options)
{
  picture_size(options.size); // a bad --size is a usage error before any work
  const Outputs outputs = parse_outputs(options);
  if(options.no_measure && options.color != "patches")
    throw CLI::ValidationError("--no-measure", "--color " + options.color + " draws the measures; measure, or colour the patches");
  check_patch_options(options.patches);
  if(!options.corners.empty() && (!options.patches.labels.empty()))
    throw CLI::ValidationError("--corners", "applies to a disc mesh without --labels");
  if(!options.corners.empty() && options.patches.patches > 0)
    throw CLI::ValidationError("--corners", "maps the disc as one patch: --patches does not apply");
  const std::string mesh_path = options.mesh.empty() ? default_mesh("cow.off") : options.mesh;
  Stage_clock stages;
  // A file this large takes seconds to read: say so before, not only after.
  std::error_code size_error;
  const auto file_size = std::filesystem::file_size(mesh_path, size_error);
  if(!size_error && file_size > 50'000'000)
    std::cerr << "diffuv: reading " << mesh_path << " (" << file_size / 1'000'000 << " MB)" << std::endl;
  const Input_mesh in = read_input(mesh_path, options.patches);
  stages.large = in.report.vertices > 1000000;
  stages.done("read", count_text(in.report.vertices, "vertex", "vertices"));

  std::vector<Mesh::Vertex_index> corners;
  if(!options.corners.empty())
    corners = selected_vertices(in, options.corners);

  // --runs repeats everything after reading and reports the median time.
  Parameterization result;
  std::vector<double> times;
  diffuv::Repair_options repair;
  repair.enabled = !options.no_repair;
  diffuv::Chart_drawing_options drawing;
  drawing.pieces = options.unit_squares ? 0 : static_cast<std::size_t>(options.warp_pieces);  // unit squares: canonical (u,v)
  // More threads than cores gain nothing, and oneTBB would warn about them.
  const std::size_t cores = (std::max)(1u, std::thread::hardware_concurrency());
  const std::size_t threads = options.threads == 0 ? 0 : (std::min)(options.threads, cores);
  Patch_cli_options patching = options.patches;
  patching.threads = threads;
  for(int run = 0; run < options.runs; ++run) {
    result = options.corners.empty()
                 ? parameterize_by_patches(in, patching, options.distance, repair, threads, drawing)
                 : parameterize_with_corners(in, corners, options.corners, options.distance, repair, drawing);
    times.push_back(result.milliseconds);
  }
  stages.add("patches", result.patches_ms, count_text(result.seg.number_of_patches(), "patch", "patches"));
  stages.add("map", result.milliseconds - result.patches_ms,
             options.runs > 1 ? "last of " + std::to_string(options.runs) + " runs" : std::string());
  std::sort(times.begin(), times.end());
  const double total_ms = times[times.size() / 2];
  const Atlas& atlas = *result.atlas;

  // A patch that could not be mapped: an error if every one failed or with
  // --strict (then nothing is written), else a warning and the others' results.
  std::size_t failed = 0;
  std::string first_failure;
  for(std::size_t p = 0; p < result.patches.size(); ++p)
    if(!result.patches[p].status && failed++ == 0) first_failure = result.patches[p].status.what();
  if(failed > 0 && (failed == result.patches.size() || options.patches.strict)) {
    // Patches of a face or two each: the mesh is most likely an export whose
    // triangles do not share their points.
    const bool crumbs = 2 * result.patches.size() >= num_faces(in.mesh) && result.patches.size() > 1;
    throw diffuv::Input_error(in.labels_path.empty() ? in.path : in.labels_path, 0,
                              std::to_string(failed) + " of " + count_text(result.patches.size(), "patch", "patches") +
                                  " cannot be parameterized; the first: " + first_failure +
                                  (crumbs ? std::string(" (the mesh falls apart into pieces of one or two faces: if the "
                                                        "file is an export whose faces do not share their points, weld "
                                                        "it; reading stitches only borders whose points coincide exactly)")
                                          : std::string()));
  }

  // Everything is computed before anything is written: all files or none.
  const std::vector<std::string> inputs = {in.path, options.corners, options.patches.labels};
  stages.restart();
  // For the picture and the table; --no-measure leaves them empty.
  const std::vector<Chart_measure> measures = options.no_measure ? std::vector<Chart_measure>(result.patches.size())
                                                                  : measure_charts(in, result, options.unit_squares);
  if(!options.no_measure) stages.done("measure");
  // The charts packed into one texture (unless stacked at its origin).
  const bool textured = outputs.obj || outputs.glb || outputs.atlas;
  const bool packed = textured && !options.unit_squares && !options.stacked;
  diffuv::Chart_packing packing;
  std::string atlas_line;
  if(packed) {
    try {
      packing = diffuv::pack_charts(atlas, in.mesh.points(), packing_options(options));
    } catch(const std::invalid_argument&) {
      throw CLI::ValidationError("--texture-size", "the " + count_text(atlas.number_of_charts(), "chart") +
                                                       " do not fit in " + std::to_string(options.texture_size) +
                                                       " x " + std::to_string(options.texture_size) +
                                                       " texels with gutters of " + std::to_string(options.gutter) +
                                                       ": raise --texture-size or lower --gutter");
    }
    atlas_line = packing_summary(atlas.number_of_charts(), options, packing);
    stages.done("pack");
  }
  diffuv::Output_folder out(options.output, inputs);
  // The picture (rendered and encoded, the largest single output: cow ~50
  // of ~90 ms) is made on a second thread while the other files are
  // written; nothing in it writes to what they read. Its bytes go to the
  // folder here, on this thread, so the folder is only ever touched by one.
  const std::string picture_name = output_name(in.path, ".png");
  const auto make_picture = [&] {
    std::ostringstream png;
    diffuv::write_png(png, picture(in, result, measures, options), picture_name);
    return png.str();
  };
  std::future<std::string> picture_png;
  if(outputs.picture && options.threads != 1) {
    atlas.prepare_lookups(); // the atlas's lazy vertex index, built before two threads read it
    try {
      picture_png = std::async(std::launch::async, make_picture);
    } catch(const std::system_error&) {
      // No thread to be had: the picture is made below, after the other files.
    }
  }
  // The texture of the OBJ and the glTF file. Packed: squares of 16 texels
  // of the packed texture, the same size on every chart; stacked: 8 x 8
  // squares across each chart.
  std::ostringstream checker_png;
  if(outputs.obj || outputs.glb) {
    // Packed: the texture itself, --texture-size texels wide; stacked: 512.
    const int size = packed ? options.texture_size : 512;
    if(!diffuv::write_checker_png(checker_png, size, packed ? std::max(1, size / 16) : 8))
      throw std::runtime_error("the checker texture could not be encoded (zlib ran out of memory)");
  }
  auto write_textured = [&](auto corner_uv) {
    if(outputs.obj) {
      // A textured OBJ: any viewer shows the map as a checkerboard on the mesh.
      const std::string texture = output_name(in.path, ".checker.png");
      const std::string mtl = output_name(in.path, ".mtl");
      diffuv::write_obj(out.open(output_name(in.path, ".obj")), in.mesh, in.mesh.points(), corner_uv, mtl, "diffuv_checker");
      diffuv::write_mtl(out.open(mtl), "diffuv_checker", texture);
      out.open(texture) << checker_png.str();
    }
    if(outputs.glb) {
      // The same, as one self-contained glTF 2.0 file (three.js, Blender, game
      // engines). On this thread: encoded on a second one while the OBJ was
      // written, it took longer (doc/performance.md).
      diffuv::Gltf_options gltf;
      gltf.png = checker_png.str();
      gltf.name = std::filesystem::path(in.path).stem().string();
      gltf.up = up_axis(in, options);
      if(!diffuv::write_glb(out.open(output_name(in.path, ".glb")), in.mesh, in.mesh.points(), corner_uv, gltf))
        throw diffuv::Output_error(output_name(in.path, ".glb"), "glTF encoding failed");
    }
    if(outputs.atlas) {
      // The texture's layout: each chart in its patch's colour where its
      // texture coordinates put it, one pixel per texel.
      diffuv::Texture_layout_options look;
      look.size = options.texture_size;
      const diffuv::Image layout = diffuv::render_texture_layout(
          in.mesh, corner_uv, [&](Mesh::Face_index f) { return diffuv::patch_color(result.seg.face_patch[f.idx()]); },
          atlas.corner_uv_map(), look);
      diffuv::write_png(out.open(output_name(in.path, ".atlas.png")), layout, output_name(in.path, ".atlas.png"));
    }
  };
  // Each corner's texture point found once (chart lookup, warps, packing),
  // not once per file that reads it: the OBJ, the glb and the layout picture.
  std::vector<Kernel::Point_2> corner_points;
  auto each_corner_once = [&](auto corner_uv) {
    corner_points.resize(in.mesh.number_of_halfedges() + in.mesh.number_of_removed_halfedges());
    for(Mesh::Halfedge_index h : in.mesh.halfedges())
      if(!in.mesh.is_border(h)) corner_points[h.idx()] = get(corner_uv, h);
    return boost::make_function_property_map<Mesh::Halfedge_index>(
        [&corner_points](Mesh::Halfedge_index h) { return corner_points[h.idx()]; });
  };
  if(textured) {  // else no file reads texture points
    if(options.unit_squares)
      write_textured(each_corner_once(atlas.corner_uv_map()));
    else if(options.stacked)
      write_textured(each_corner_once(atlas.corner_texture_map()));
    else
      write_textured(each_corner_once(diffuv::packed_corner_map(atlas, packing)));
  }
  if(options.svg) write_uv_layouts(out, in, result);
  if(outputs.uv) diffuv::write_uv_table(out.open(output_name(in.path, ".uv.csv")), atlas);
  if(outputs.patches) write_polygon_patches(out.open(output_name(in.path, ".patches.txt")), in, result.seg);
  if(outputs.picture) out.open(picture_name) << (picture_png.valid() ? picture_png.get() : make_picture());
  out.commit();
  stages.done("write");

  if(!options.quiet)
    print_param_report(
        Param_run{in, result, measures, total_ms, failed, stages, out.paths(), !options.no_measure, atlas_line}, options);
  else
    print_param_warnings(Param_run{in, result, measures, total_ms, failed, stages, out.paths(), !options.no_measure});
}

// The options `param` and `render` share: what is parameterized, and how it is drawn.
void add_common_options(CLI::App* cmd, Param_options& o)
{
  cmd->add_option("--threads", o.threads,
                  "Threads mapping the patches: 0 = every core, 1 = one after the other (the results are the same; "
                  "more threads than cores are not used); unless 1, param also draws its picture while it writes "
                  "the other files")
      ->check(number_in(0, 1024))
      ->capture_default_str();
  cmd->add_option("mesh", o.mesh,
                  "Triangle mesh (OFF, OBJ, PLY, STL). A disc whose map as one patch is good stays one patch; any other mesh "
                  "is cut into disc patches. "
                  "Default: CGAL's cow.off");
  cmd->add_option("--corners", o.corners,
                  "Disc mesh only, mapped as one patch: CGAL *.selection.txt with four boundary vertex indices on its first line. The first "
                  "goes to (0,0), the others follow counter-clockwise along the boundary to (1,0), (1,1), (0,1). "
                  "Default: automatic (the sharpest boundary vertex, then equal arc lengths)");
  add_patch_options(cmd, o.patches);
  cmd->add_option("-o,--output", o.output, "Output folder (created if needed)")
      ->check(output_folder_check())
      ->capture_default_str();
  cmd->add_option("--distance", o.distance,
                  "Distance diffused from each side: fmm (fast marching through triangles), graph (edge paths, the "
                  "paper's) or exact (exact geodesics, CGAL's Surface_mesh_shortest_path; slow)")
      ->check(CLI::IsMember({"graph", "fmm", "exact"}))
      ->capture_default_str();
  cmd->add_flag("--no-repair", o.no_repair,
                "Keep the raw diffusion coordinates, folds included (the paper's method). By default every fold is "
                "repaired: the folded region is re-solved as a convex-combination map (see doc/quality.md)");
  cmd->add_option("--warp-pieces", o.warp_pieces,
                  "Each chart is drawn on its rectangle with u and v warped by increasing piecewise-linear maps of "
                  "this many pieces, fitted to lower the chart's stretch (its iso-lines and border kept; see "
                  "doc/layout.md, \"Charts drawn with warped axes\"); 0 draws each chart's (u,v) on its plain rectangle")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  CLI::Option* view = cmd->add_option("--view", o.view, "View of the picture: front, back, left, right, top or iso")
      ->check(CLI::IsMember({"front", "back", "left", "right", "top", "iso"}))
      ->capture_default_str();
  cmd->add_option("--up", o.up,
                  "The mesh's up axis: x, y, z, or auto (z for a mesh more than 2.5 times taller along z than deep "
                  "along y, as man.off; else y, as cow.off). The picture shows it upright (with z up, front looks "
                  "along +y as in Blender, with x up along -z) and the glTF file turns its node so that it stands "
                  "in glTF's y-up frame")
      ->check(CLI::IsMember({"auto", "x", "y", "z"}))
      ->capture_default_str();
  const auto finite = CLI::Validator(
      [](std::string& text) {
        try {
          return std::isfinite(std::stod(text)) ? std::string() : std::string("must be a finite number");
        } catch(const std::exception&) {
          return std::string("must be a number");
        }
      },
      "DEGREES");
  CLI::Option* azimuth =
      cmd->add_option("--azimuth", o.azimuth,
                      "Camera azimuth in degrees around the up axis (0: as front); instead of --view")
          ->check(finite)
          ->check(number_in(-360, 360, false));
  azimuth->excludes(view);
  cmd->add_option("--elevation", o.elevation, "Camera elevation in degrees (needs --azimuth)")
      ->check(finite)
      ->check(number_in(-90, 90, false))
      ->needs(azimuth)
      ->capture_default_str();
  cmd->add_option("--size", o.size, "Size of the picture, WxH pixels")->capture_default_str();
  cmd->add_option("--isolines", o.isolines, "u and v isolines every 1/N in the picture (0: none)")
      ->check(number_in(0, 1000))
      ->capture_default_str();
  cmd->add_flag("--no-measure", o.no_measure,
                "Do not measure the distortion of the charts (the table's distortion columns show '-'): faster for "
                "a batch that does not need them");
  cmd->add_flag("-q,--quiet", o.quiet, "Print nothing but warnings and errors");
  cmd->add_option("--color,--colour", o.color,
                  "Face colours of the picture: patches, angle (sigma_max/sigma_min) or area distortion, as a heat "
                  "map from 1 to 10 (log scale; flipped faces magenta)")
      ->check(CLI::IsMember({"patches", "angle", "area"}))
      ->capture_default_str();
}

const char* const exit_codes = "Exit codes: 0 ok, 1 bad input, 2 bad command line, 3 cannot write, 4 internal error.";

} // namespace

void add_param_command(CLI::App& app)
{
  auto options = std::make_shared<Param_options>();
  CLI::App* cmd = app.add_subcommand(
      "param", "Parameterize a mesh patch by patch, each onto a rectangle of its own aspect (--unit-squares: the unit "
               "square); write OBJ and glTF (the charts packed into one texture), a uv table, "
               "the patches and a picture");
  add_common_options(cmd, *options);
  cmd->add_flag("--svg", options->svg, "Also write each patch's uv layout as OUTPUT/<mesh>.patch<N>.svg (flipped "
                                      "triangles in red, the four sides in colour)");
  CLI::Option* unit_squares = cmd->add_flag("--unit-squares", options->unit_squares,
                "Write every chart on the unit square (the canonical (u,v)) instead of on a rectangle of its own "
                "aspect (the aspect with the least stretch for the chart's map); the table then measures the squares");
  CLI::Option* stacked = cmd->add_flag("--stacked", options->stacked,
                "Draw every chart on its own rectangle at the origin of the texture (charts on top of each other), "
                "instead of packing them side by side into one texture");
  // Unit squares are stacked too; neither packs, so the packing's options would be ignored.
  unit_squares->excludes(stacked);
  CLI::Option* texture_size = cmd->add_option("--texture-size", options->texture_size,
                  "Width and height in texels of the texture the charts are packed into (the checker texture "
                  "written beside the OBJ and in the glTF file has this size)")
      ->check(number_in(16, 8192))
      ->capture_default_str();
  CLI::Option* gutter = cmd->add_option("--gutter", options->gutter,
                  "Texels kept free between two packed charts (half of it between a chart and the texture's edge), so "
                  "that filtering does not mix two charts")
      ->check(number_in(0, 256))
      ->capture_default_str();
  CLI::Option* packer = add_packer_option(cmd, *options);
  for(CLI::Option* packing : {texture_size, gutter, packer}) {
    packing->excludes(stacked);
    packing->excludes(unit_squares);
  }
  cmd->add_option("--outputs", options->outputs,
                  "What to write, a comma-separated list of: obj (the OBJ with its .mtl and checker texture), glb (the same "
                  "mesh, uv and texture as one binary glTF 2.0 file), atlas (a picture of the charts in the texture, "
                  "<mesh>.atlas.png; not written by default), uv (the "
                  "uv table), patches (the label file), picture (the PNG)")
      ->capture_default_str();
  cmd->add_option("--runs", options->runs, "Run the parameterization N times and report the median time")
      ->check(number_in(1, 1000))
      ->capture_default_str();
  cmd->footer(std::string("Writes, unless --outputs says otherwise, OUTPUT/<mesh>.obj (v in input order, one vt per distinct (vertex, uv), "
              "the charts packed side by side into one texture of --texture-size texels unless --stacked or --unit-squares), "
              "OUTPUT/<mesh>.uv.csv (vertex,patch,u,v), OUTPUT/<mesh>.mtl and <mesh>.checker.png (the OBJ's material "
              "and texture), OUTPUT/<mesh>.glb (the same mesh, texture coordinates and texture as one binary glTF 2.0 "
              "file), OUTPUT/<mesh>.png (the mesh with its patches and u, v isolines) and "
              "OUTPUT/<mesh>.patches.txt (the patch of each face of the mesh file, one per "
              "line: a label file for --labels).\nA patch that cannot be mapped is listed and warned about; the others "
              "are written (with --strict, or if none can be mapped: an error).\n") + exit_codes);
  cmd->callback([options]() { run_param(*options); });
}

void add_render_command(CLI::App& app)
{
  auto options = std::make_shared<Param_options>();
  options->render_only = true;
  CLI::App* cmd = app.add_subcommand(
      "render", "Parameterize a mesh as param does and draw it: u, v isolines on patch colours or a distortion "
                "heat map (offscreen, PNG)");
  add_common_options(cmd, *options);
  cmd->footer(std::string("Writes OUTPUT/<mesh>.png only.\n") + exit_codes);
  cmd->callback([options]() { run_param(*options); });
}

} // namespace diffuv_cli
