// diffuv tool: `diffuv bake` — parameterize a mesh as param does, pack its
// charts into one texture and fill that texture with data of the surface:
// the mesh's vertex colours, normals, region labels or a per-vertex scalar,
// or the same from another mesh of the object (closest point).
#include "commands.h"
#include "pictures.h"
#include "packing.h"
#include "pipeline.h"

#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/io/read_vertex_colors.h>
#include <diffuv/output/write_obj.h>
#include <diffuv/render/bake_texture.h>
#include <diffuv/render/pack_charts.h>
#include <diffuv/render/write_gltf.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace diffuv_cli {
namespace {

struct Bake_cli_options {
  Param_options param;         // the mesh, its patches, -o, --up, -q
  std::string what;            // colors | normals | labels | values (default: values with --values, else colors)
  std::string values;          // per-vertex numbers to bake (--what values)
  std::string from;            // take the data from this mesh, by closest point
  int dilation = 8;
};

using Sampler = std::function<diffuv::Rgb(Mesh::Face_index, const std::array<double, 3>&)>;

// What a mesh gives to bake: per-vertex RGB (colours, values) or per-face
// colours (labels), or normals; one of them is filled.
struct Bake_source {
  std::vector<diffuv::Rgb> vertex_rgb;
  std::vector<diffuv::Color> face_color;
  Mesh::Property_map<Mesh::Vertex_index, Kernel::Vector_3> normals;
  bool has_normals = false;
  std::string note;  // for the summary, e.g. "values 0.1 to 3.2 as grey"
};

// The colour of a region label: what the file painted (its value, see
// read_input()'s Paint_reading), else diffuv's palette.
diffuv::Color region_color(const Input_mesh& in, int label)
{
  if(in.label_source.find("a colour's label is its value") != std::string::npos)
    return diffuv::Color{static_cast<unsigned char>((label >> 16) & 255), static_cast<unsigned char>((label >> 8) & 255),
                         static_cast<unsigned char>(label & 255)};
  return diffuv::label_color(label);
}

Bake_source gather(Input_mesh& in, std::string& what, const std::string& values_path)
{
  Bake_source s;
  const std::vector<diffuv::Color> colors = what == "colors" ? diffuv::read_vertex_colors(in.path) : std::vector<diffuv::Color>();
  // Colours painted on the faces (as `diffuv segment` writes them) are the faces' regions.
  if(what == "colors" && colors.empty() && in.label_source.find("painted") != std::string::npos) what = "labels";
  if(what == "colors") {
    if(colors.empty())
      throw diffuv::Input_error(in.path, 0, "has no vertex or face colours (a PLY with red, green, blue per vertex "
                                            "or face, or a COFF file): bake --what normals, labels or values instead");
    s.vertex_rgb.resize(num_vertices(in.mesh));
    for(Mesh::Vertex_index v : vertices(in.mesh)) {
      const std::size_t point = in.report.point_of(v.idx());
      s.vertex_rgb[v.idx()] = point < colors.size() ? diffuv::to_rgb(colors[point]) : diffuv::Rgb{0., 0., 0.};
    }
    s.note = "vertex colours";
  } else if(what == "values") {
    const auto rows = read_value_rows(values_path, in.report.vertices, "the mesh file (" + in.path + ")");
    double low = rows.front().front(), high = low;
    for(const auto& row : rows) {
      low = (std::min)(low, row.front());
      high = (std::max)(high, row.front());
    }
    s.vertex_rgb.resize(num_vertices(in.mesh));
    for(Mesh::Vertex_index v : vertices(in.mesh)) {
      const double x = rows[in.report.point_of(v.idx())].front();
      const double grey = high > low ? (x - low) / (high - low) : 0.5;
      s.vertex_rgb[v.idx()] = {grey, grey, grey};
    }
    char note[300];
    if(high > low)
      std::snprintf(note, sizeof note, "values of %s, %.6g (black) to %.6g (white)", values_path.c_str(), low, high);
    else
      std::snprintf(note, sizeof note, "values of %s, all %.6g: mid-grey", values_path.c_str(), low);
    s.note = note;
    if(rows.front().size() > 1) s.note += ", first column";
  } else if(what == "labels") {
    if(in.face_labels.empty())
      throw diffuv::Input_error(in.path, 0, "has no regions to bake: give --labels FILE (one label per face of this "
                                            "file), or paint the regions into it (--regions-from says which paint counts)");
    s.face_color.resize(num_faces(in.mesh));
    for(Mesh::Face_index f : faces(in.mesh)) s.face_color[f.idx()] = region_color(in, in.face_labels[f.idx()]);
    s.note = "face colours of " + in.label_source;
  } else {
    s.normals = in.mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:diffuv_bake_normal").first;
    CGAL::Polygon_mesh_processing::compute_vertex_normals(in.mesh, s.normals);
    s.has_normals = true;
    s.note = "object-space vertex normals, (n + 1) / 2";
  }
  return s;
}

// The sampler of `s` on `mesh`.
Sampler sampler_of(const Mesh& mesh, const Bake_source& s)
{
  if(!s.vertex_rgb.empty())
    return diffuv::vertex_value_sampler(mesh, boost::make_iterator_property_map(s.vertex_rgb.begin(),
                                                                                get(boost::vertex_index, mesh)));
  if(!s.face_color.empty())
    return [&s](Mesh::Face_index f, const std::array<double, 3>&) { return diffuv::to_rgb(s.face_color[f.idx()]); };
  return diffuv::vertex_normal_sampler(mesh, s.normals);
}

// Share of the vertices read back within 1/255 at every texture point they
// have, over all and over those no other vertex crowds (texture points at
// least 2 texels apart, so that no texel is in both bilinear footprints).
struct Read_back_check {
  std::size_t vertices = 0, good = 0, resolved = 0, resolved_good = 0;
};

template <class CornerMap>
Read_back_check check_read_back(const Mesh& mesh, CornerMap corner, const diffuv::Image& image,
                                const std::vector<diffuv::Rgb>& expected)
{
  const double S = image.width;
  const std::size_t n = num_vertices(mesh);
  std::vector<char> used(n, 0), wrong(n, 0), crowded(n, 0);
  std::vector<std::pair<std::array<double, 2>, std::size_t>> points;
  for(Mesh::Face_index f : faces(mesh))
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const auto t = get(corner, h);
      if(!std::isfinite(t.x()) || !std::isfinite(t.y())) continue;
      const std::size_t v = target(h, mesh).idx();
      used[v] = 1;
      points.push_back({{t.x() * S, t.y() * S}, v});
      const diffuv::Rgb c = diffuv::sample_bilinear(image, t.x(), t.y());
      for(int k = 0; k < 3; ++k)
        if(std::abs(c[std::size_t(k)] - expected[v][std::size_t(k)]) > 1. / 255 + 1e-9) wrong[v] = 1;
    }
  std::sort(points.begin(), points.end());
  for(std::size_t i = 0; i < points.size(); ++i)
    for(std::size_t j = i + 1; j < points.size() && points[j].first[0] - points[i].first[0] < 2.; ++j)
      if(points[j].second != points[i].second && std::abs(points[j].first[1] - points[i].first[1]) < 2.)
        crowded[points[i].second] = crowded[points[j].second] = 1;
  Read_back_check check;
  for(std::size_t v = 0; v < n; ++v) {
    if(!used[v]) continue;
    ++check.vertices;
    check.good += wrong[v] ? 0 : 1;
    if(crowded[v]) continue;
    ++check.resolved;
    check.resolved_good += wrong[v] ? 0 : 1;
  }
  return check;
}

void run_bake(Bake_cli_options& o)
{
  Param_options& options = o.param;
  if(!o.values.empty() && o.what.empty()) o.what = "values";
  if(o.what.empty()) o.what = "colors";
  const std::string asked = o.what;  // names the texture, also when painted faces turn colors into labels
  if(o.what == "values" && o.values.empty())
    throw CLI::ValidationError("--what", "values needs --values FILE (one number per vertex of the mesh file)");
  if(o.what != "values" && !o.values.empty())
    throw CLI::ValidationError("--values", "bakes values: it does not go with --what " + o.what);
  check_patch_options(options.patches);
  Stage_clock stages;
  Input_mesh in = read_input(options.mesh, options.patches, Paint_reading{true, true, o.what != "colors"});
  stages.large = in.report.vertices > 1000000;
  stages.done("read", count_text(in.report.vertices, "vertex", "vertices"));
  // The data: from the mesh itself, or from --from by closest point.
  std::unique_ptr<Input_mesh> from;
  Bake_source data;
  if(o.from.empty()) {
    data = gather(in, o.what, o.values);
  } else {
    Patch_cli_options source_options;
    source_options.labels = "";
    source_options.strict_input = options.patches.strict_input;
    from = std::make_unique<Input_mesh>(read_input(o.from, source_options, Paint_reading{o.what == "labels" || o.what == "colors", true, false}));
    data = gather(*from, o.what, o.values);
    // Closest points mean something only where MESH lies on --from's surface.
    diffuv::Nearest_face_report lying;
    diffuv::nearest_face_labels(from->mesh, std::vector<int>(num_faces(from->mesh), 0), in.mesh, &lying);
    if(!lying.lies_on_source()) {
      char what[300];
      std::snprintf(what, sizeof what,
                    "does not lie on %s (the median distance from its faces to it is %.2f %% of its bounding-box "
                    "diagonal, more than 1 %%): --from takes the data of a mesh of the same object in the same place",
                    o.from.c_str(), 100. * lying.median_fraction());
      throw diffuv::Input_error(in.path, 0, what);
    }
    stages.done("read --from", count_text(from->report.vertices, "vertex", "vertices"));
  }

  diffuv::Repair_options repair;
  repair.enabled = !options.no_repair;
  const std::size_t cores = (std::max)(1u, std::thread::hardware_concurrency());
  Patch_cli_options patching = options.patches;
  patching.threads = options.threads == 0 ? 0 : (std::min)(options.threads, cores);
  diffuv::Chart_drawing_options drawing;
  drawing.pieces = static_cast<std::size_t>(options.warp_pieces);
  Parameterization result = parameterize_by_patches(in, patching, options.distance, repair, patching.threads, drawing);
  std::size_t failed = 0;
  for(const auto& p : result.patches) failed += p.status ? 0 : 1;
  if(failed == result.patches.size())
    throw diffuv::Input_error(in.path, 0, "no patch can be parameterized; the first: " + std::string(result.patches.front().status.what()));
  stages.add("patches", result.patches_ms, count_text(result.seg.number_of_patches(), "patch", "patches"));
  stages.add("map", result.milliseconds - result.patches_ms);
  stages.restart();
  const Atlas& atlas = *result.atlas;
  diffuv::Chart_packing packing;
  try {
    packing = diffuv::pack_charts(atlas, in.mesh.points(), packing_options(options));
  } catch(const std::invalid_argument&) {
    throw CLI::ValidationError("--resolution", "the " + count_text(atlas.number_of_charts(), "chart") +
                                                   " do not fit in " + std::to_string(options.texture_size) + " x " +
                                                   std::to_string(options.texture_size) + " texels with gutters of " +
                                                   std::to_string(options.gutter) + ": raise --resolution or lower --gutter");
  }
  stages.done("pack");
  const auto corner = diffuv::packed_corner_map(atlas, packing);

  diffuv::Bake_options baking;
  baking.size = options.texture_size;
  baking.dilation = o.dilation;
  // A face's label colour is one colour: the vertex's own value is not one.
  baking.pin_vertices = o.what != "labels";
  const Sampler own = sampler_of(from ? from->mesh : in.mesh, data);
  const diffuv::Baked_texture baked =
      from ? diffuv::bake_texture(in.mesh, corner, diffuv::closest_point_sampler(in.mesh, in.mesh.points(), from->mesh, own), baking)
           : diffuv::bake_texture(in.mesh, corner, own, baking);
  stages.done("bake");
  const double bake_ms = stages.stages.back().second;

  // Everything is computed before anything is written: all files or none.
  const std::string stem = output_name(in.path, "");
  const std::string png_name = output_name(in.path, "." + asked + ".png");
  std::ostringstream png;
  diffuv::write_png(png, baked.image, png_name);
  diffuv::Output_folder out(options.output, {in.path, o.from, o.values, options.patches.labels});
  out.open(png_name) << png.str();
  const std::string mtl = output_name(in.path, ".mtl");
  diffuv::write_obj(out.open(output_name(in.path, ".obj")), in.mesh, in.mesh.points(), corner, mtl, "diffuv_baked");
  diffuv::write_mtl(out.open(mtl), "diffuv_baked", png_name);
  diffuv::Gltf_options gltf;
  gltf.png = png.str();
  gltf.name = std::filesystem::path(in.path).stem().string();
  gltf.up = up_axis(in, options);
  if(!diffuv::write_glb(out.open(output_name(in.path, ".glb")), in.mesh, in.mesh.points(), corner, gltf))
    throw diffuv::Output_error(output_name(in.path, ".glb"), "glTF encoding failed");
  // The mesh as a renderer shows it with the baked texture.
  diffuv::Render_options look;
  look.up = up_axis(in, options);
  look.texture = &baked.image;
  look.isolines = 0;
  diffuv::write_png(out.open(output_name(in.path, ".png")),
                    diffuv::render_mesh(in.mesh, in.mesh.points(), [](Mesh::Face_index) { return diffuv::Color{128, 128, 128}; },
                                        corner, look),
                    output_name(in.path, ".png"));
  out.commit();
  stages.done("write");

  if(failed > 0)
    std::cerr << "diffuv: warning: " << count_text(failed, "patch", "patches")
              << " could not be mapped: their faces are in no chart and get no texels\n";
  if(options.quiet) return;
  std::cout << "diffuv bake " << in.path << ": " << count_text(in.report.vertices, "vertex", "vertices") << ", "
            << count_text(num_faces(in.mesh), "face") << "; " << count_text(result.seg.number_of_patches(), "patch", "patches")
            << (in.face_labels.empty() ? std::string() : " (" + in.label_source + ")") << "\n";
  std::cout << packing_summary(atlas.number_of_charts(), options, packing) << "\n";
  std::cout << "baked " << o.what << " (" << data.note << (from ? ", from the closest points of " + o.from : std::string())
            << "): " << baked.face_texels << " texels from the faces, " << baked.vertex_texels
            << " around the vertices, " << baked.gutter_texels << " in the gutters (" << o.dilation << " passes); "
            << Stage_clock::duration(bake_ms) << "\n";
  if(!from && !data.vertex_rgb.empty()) {
    const Read_back_check check = check_read_back(in.mesh, corner, baked.image, data.vertex_rgb);
    char line[300];
    std::snprintf(line, sizeof line,
                  "read back at the vertices (bilinear): %.1f %% within 1/255; %.1f %% of the %zu vertices that no "
                  "other vertex crowds within 2 texels",
                  check.vertices ? 100. * double(check.good) / double(check.vertices) : 0.,
                  check.resolved ? 100. * double(check.resolved_good) / double(check.resolved) : 0., check.resolved);
    std::cout << line << (check.resolved < check.vertices ? " (the others lie in squeezed charts: raise --resolution)" : "")
              << "\n";
  }
  std::cout << "stages: " << stages.summary() << "\n";
  std::cout << wrote_line(out.paths()) << "\n";
}

} // namespace

void add_bake_command(CLI::App& app)
{
  auto options = std::make_shared<Bake_cli_options>();
  CLI::App* cmd = app.add_subcommand(
      "bake", "Parameterize a mesh as param does, pack its charts into one texture and bake into it the mesh's vertex "
              "colours, normals, region labels or per-vertex values, or those of another mesh of the same object "
              "(--from, by closest point); write the texture, a textured OBJ and a glTF file");
  Param_options& p = options->param;
  cmd->add_option("mesh", p.mesh, "Triangle mesh (OFF, OBJ, PLY, STL) to parameterize and bake")->required();
  cmd->add_option("--what", options->what,
                  "What to bake: colors (the vertex colours of a PLY or COFF file, interpolated across faces), normals "
                  "(an object-space normal map: area-weighted vertex normals, (n + 1) / 2 per channel), labels (each "
                  "face's region in its painted or palette colour) or values (--values FILE, as grey from its lowest "
                  "to its highest value). Default: values with --values, else colors")
      ->check(CLI::IsMember({"colors", "normals", "labels", "values"}));
  cmd->add_option("--values", options->values,
                  "Per-vertex numbers to bake: one row per point of the mesh file they belong to (with --from, of "
                  "--from's file), numbers separated by spaces, the first column baked; # starts a comment");
  cmd->add_option("--from", options->from,
                  "Take what is baked from this mesh (e.g. a high-resolution scan of the same object, in the same "
                  "place): each texel's point on MESH takes the data at its closest point on this mesh");
  cmd->add_option("--resolution,--texture-size", p.texture_size, "Width and height of the texture in texels")
      ->check(number_in(16, 8192))
      ->capture_default_str();
  cmd->add_option("--warp-pieces", p.warp_pieces, "As in param: the pieces of each chart's warps of u and v (0: none)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  cmd->add_option("--gutter", p.gutter, "Texels kept free between two packed charts (half of it at the texture's edge)")
      ->check(number_in(0, 256))
      ->capture_default_str();
  add_packer_option(cmd, p);
  cmd->add_option("--dilation", options->dilation,
                  "Texels around the charts filled with the colour of their neighbours, so that filtering and "
                  "mipmaps do not bleed the black background into the charts' borders")
      ->check(number_in(0, 256))
      ->capture_default_str();
  add_patch_options(cmd, p.patches);
  cmd->add_option("-o,--output", p.output, "Output folder (created if needed)")
      ->check(output_folder_check())
      ->capture_default_str();
  cmd->add_option("--up", p.up, "The mesh's up axis (x, y, z or auto), for the glTF file's node as in param")
      ->check(CLI::IsMember({"auto", "x", "y", "z"}))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", p.quiet, "Print nothing but warnings and errors");
  cmd->footer("Writes OUTPUT/<mesh>.<what>.png (the baked texture), OUTPUT/<mesh>.obj and .mtl (the mesh with its "
              "packed texture coordinates, textured with it), OUTPUT/<mesh>.glb (the same as one binary glTF 2.0 "
              "file) and OUTPUT/<mesh>.png (a picture of the textured mesh, seen as param's --view iso). The four texels around each vertex hold the vertex's own value (colors, normals, values), so "
              "that a renderer reading the texture at a vertex gets it back.\n"
              "Exit codes: 0 ok, 1 bad input, 2 bad command line, 3 cannot write, 4 internal error.");
  cmd->callback([options]() { run_bake(*options); });
}

} // namespace diffuv_cli
