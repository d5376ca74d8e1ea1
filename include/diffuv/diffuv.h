// diffuv: diffusion-based surface parameterization on CGAL -- umbrella header.
//
// Includes every public header of the core target (diffuv::diffuv), layer by
// layer, lowest first (doc/design.md, "Layers"; scripts/check_layers.py
// checks that this list is complete). Not included: render/, the optional
// diffuv::render target (pictures, PNG files and the packed atlas, through stb),
// and core/huge_page_allocation.h, which a program includes in one source file
// (it replaces the global operator new).
//
//   core/             the vocabulary: Status and the error types, the four sides, colours and the label palette
//   io/               reading: meshes (OFF, OBJ, PLY, STL), labels, painted regions, corners, colours; safe output files
//   graph/            multi-source Dijkstra (Fibonacci heap), fast marching, exact geodesics, edge lengths
//   patches/          labels -> disc patches: segmentation, boundary loops, corners and four sides, flat triangles, a patch copied as a mesh
//   layout/           the four-sided layout (Voronoi cells -> quads) and disc_patches(), every way to patches
//   atlas/            the uv-map: (chart, vertex) -> uv array, kd-tree, point location
//   metrics/          distortion and injectivity of a chart
//   parameterization/ diffusion coordinates, the fold repair, a disc or a whole mesh into an atlas
//   cgal/             Diffusion_parameterizer_3, a model of CGAL's Parameterizer_3
//   correspondence/   mesh A -> mesh B through (region, u, v); attribute transfer
//   output/           writers: OBJ + MTL, uv table, SVG of a chart, label files, labelled and coloured PLY
#ifndef DIFFUV_DIFFUV_H
#define DIFFUV_DIFFUV_H

#include <diffuv/core/color.h>
#include <diffuv/core/error.h>
#include <diffuv/core/four_sides.h>

#include <diffuv/io/atomic_file.h>
#include <diffuv/io/paint_look.h>
#include <diffuv/io/painted_labels.h>
#include <diffuv/io/read_labels.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/io/read_obj_charts.h>
#include <diffuv/io/read_vertex_colors.h>
#include <diffuv/io/selection_file.h>

#include <diffuv/graph/distance_tags.h>
#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/exact_geodesics.h>
#include <diffuv/graph/fast_marching.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/graph/patch_graph.h>

#include <diffuv/patches/corners.h>
#include <diffuv/patches/disc_topology.h>
#include <diffuv/patches/flat_triangles.h>
#include <diffuv/patches/merge_small_patches.h>
#include <diffuv/patches/patch_mesh.h>
#include <diffuv/patches/patch_names.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/region_sides.h>
#include <diffuv/patches/segmentation.h>
#include <diffuv/patches/smooth_region_borders.h>
#include <diffuv/patches/split_at_junctions.h>
#include <diffuv/patches/split_cap.h>

#include <diffuv/layout/cut_into_discs.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/layout/fan_split.h>
#include <diffuv/layout/quad_layout.h>
#include <diffuv/layout/quad_layout_options.h>
#include <diffuv/layout/quads_from_cells.h>
#include <diffuv/layout/sub_patches.h>
#include <diffuv/layout/voronoi_cells.h>
#include <diffuv/layout/voronoi_discs.h>

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/atlas/axis_warp.h>

#include <diffuv/metrics/distortion.h>
#include <diffuv/metrics/texture_use.h>

#include <diffuv/parameterization/chart_rectangle.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/diffusion_patches.h>
#include <diffuv/parameterization/known_charts.h>
#include <diffuv/parameterization/layout_judge.h>
#include <diffuv/parameterization/parameterize_disc.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/parameterization/repair_folds.h>

#include <diffuv/cgal/Diffusion_parameterizer_3.h>

#include <diffuv/correspondence/clean_labels.h>
#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/correspondence/labelled_atlas_pair.h>
#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/correspondence/transfer.h>

#include <diffuv/output/write_labels.h>
#include <diffuv/output/write_obj.h>
#include <diffuv/output/write_ply.h>
#include <diffuv/output/write_svg.h>
#include <diffuv/output/write_uv_table.h>

#endif // DIFFUV_DIFFUV_H
