// diffuv: diffusion-based surface parameterization on CGAL — umbrella header.
//
// The folders follow the pipeline:
//   graph/             multi-source Dijkstra, heap tags, edge lengths
//   patches/           disc check, boundary loop, four sides and corners
//   parameterization/  diffusion coordinates (u, v) of a patch, fold repair; a whole disc mesh
//   cgal/              Diffusion_parameterizer_3, a CGAL Parameterizer_3 model
//   atlas/             the uv-map: (chart, vertex) -> uv array, kd-tree, point location
//   metrics/           distortion measures of a chart
//   io/                mesh reader, selection files, OBJ and CSV writers
#ifndef DIFFUV_DIFFUV_H
#define DIFFUV_DIFFUV_H

#include <diffuv/error.h>
#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/patches/disc_topology.h>
#include <diffuv/patches/four_sides.h>
#include <diffuv/patches/segmentation.h>
#include <diffuv/patches/region_sides.h>
#include <diffuv/patches/split_patches.h>
#include <diffuv/patches/disc_patches.h>
#include <diffuv/patches/clean_labels.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/parameterize_disc.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/parameterization/repair_folds.h>
#include <diffuv/cgal/Diffusion_parameterizer_3.h>
#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/correspondence/correspondence.h>
#include <diffuv/correspondence/transfer.h>
#include <diffuv/correspondence/nearest_face_labels.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/io/labels.h>
#include <diffuv/io/vertex_colors.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/io/selection_file.h>
#include <diffuv/io/write_obj.h>
#include <diffuv/io/write_uv_table.h>

#endif // DIFFUV_DIFFUV_H
