// diffuv tool: `diffuv segment` — cut a mesh into disc patches and write them
// as a label file and a PLY with face colours, to inspect or repaint.
#include "commands.h"
#include "inputs.h"

#include <diffuv/io/atomic_file.h>
#include <diffuv/output/write_ply.h>
#include <diffuv/patches/region_sides.h>

#include <array>

#include <iostream>
#include <memory>
#include <string>

namespace diffuv_cli {
namespace {

struct Segment_options {
  std::string mesh;
  std::string output = "diffuv-out";
  Patch_cli_options patches;
};

void run_segment(const Segment_options& options)
{
  check_patch_options(options.patches);
  const std::string mesh_path = options.mesh.empty() ? default_mesh("cow.off") : options.mesh;
  const Input_mesh in = read_input(mesh_path, options.patches);
  diffuv::Patching_report report;
  const diffuv::Segmentation<Mesh> seg = make_patches(in, options.patches, report);

  std::vector<int> face_patch(num_faces(in.mesh));
  for(auto f : faces(in.mesh)) face_patch[f.idx()] = static_cast<int>(seg.face_patch[f.idx()]);

  // Each patch's four corners, (0,0) first: the layout's, or those region_sides() picks.
  std::vector<std::array<std::size_t, 4>> corners(seg.number_of_patches());
  std::vector<char> has_corners(seg.number_of_patches(), 0);
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    diffuv::Four_sides<Mesh::Vertex_index> sides;
    if(!diffuv::check_patch_disc(in.mesh, seg, p) || !diffuv::region_sides(in.mesh, in.mesh.points(), seg, p, sides)) continue;
    for(std::size_t k = 0; k < 4; ++k) corners[p][k] = sides.corners[k].idx();  // vertex i of the mesh is point i of the file
    has_corners[p] = 1;
  }

  diffuv::Output_folder out(options.output, {in.path, options.patches.labels});
  write_polygon_patches(out.open(output_name(in.path, ".patches.txt")), in, seg);
  diffuv::write_labelled_ply(out.open(output_name(in.path, ".patches.ply")), in.mesh, in.mesh.points(), face_patch);
  std::ostream& corner_file = out.open(output_name(in.path, ".corners.txt"));
  corner_file << "# patch and its four corners (vertex numbers of the mesh file): (0,0) (1,0) (1,1) (0,1), "
                 "counter-clockwise\n";
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
    if(has_corners[p])
      corner_file << p << ' ' << corners[p][0] << ' ' << corners[p][1] << ' ' << corners[p][2] << ' ' << corners[p][3] << '\n';
  out.commit();

  std::size_t smallest = num_faces(in.mesh), largest = 0;
  for(const auto& faces_of_patch : seg.patch_faces) {
    smallest = std::min(smallest, faces_of_patch.size());
    largest = std::max(largest, faces_of_patch.size());
  }
  std::cout << "diffuv segment " << in.path << ": " << count_text(num_vertices(in.mesh), "vertex", "vertices") << ", "
            << count_text(num_faces(in.mesh), "face") << '\n';
  if(const std::string repaired = repair_line(in); !repaired.empty()) std::cout << repaired << '\n';
  std::cout << count_text(seg.number_of_patches(), "patch", "patches") << " ("
            << (!in.label_source.empty() ? in.label_source
                : report.automatic       ? "automatic"
                : report.components > 1  ? "each component a whole disc"
                                         : "the whole disc")
            << "), "
            << (seg.number_of_patches() == 1 ? count_text(largest, "face")
                : smallest == largest        ? count_text(largest, "face") + " each"
                                             : std::to_string(smallest) + " to " + count_text(largest, "face") + " each")
            << "; "
            << patching_clause(report, options.patches);
  if(!report.not_discs.empty()) std::cout << "; " << count_text(report.not_discs.size(), "not a disc", "not discs");
  std::cout << '\n' << wrote_line(out.paths()) << '\n';
  warn_of_zero_area_faces(in);
}

} // namespace

void add_segment_command(CLI::App& app)
{
  auto options = std::make_shared<Segment_options>();
  CLI::App* cmd = app.add_subcommand("segment", "Cut a mesh into disc patches; write them as labels and a coloured PLY");
  cmd->add_option("mesh", options->mesh, "Triangle mesh (OFF, OBJ, PLY, STL). Default: CGAL's cow.off");
  add_patch_options(cmd, options->patches);
  cmd->add_option("-o,--output", options->output, "Output folder (created if needed)")
      ->check(output_folder_check())
      ->capture_default_str();
  cmd->footer("Writes OUTPUT/<mesh>.patches.txt (the patch of each face of the mesh file, one per line: a label file for --labels), "
              "OUTPUT/<mesh>.patches.ply (a colour per patch, for MeshLab or Blender; repaint it and pass it "
              "back to diffuv param) and OUTPUT/<mesh>.corners.txt (each patch's four corners).\nExit codes: 0 ok, 1 bad input, 2 bad command line, 3 cannot write, 4 internal error.");
  cmd->callback([options]() { run_segment(*options); });
}

} // namespace diffuv_cli
