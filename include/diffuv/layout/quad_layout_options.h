// diffuv: the options of the four-sided layout and what it reports
// (layout/quad_layout.h, layout/quads_from_cells.h).
#ifndef DIFFUV_LAYOUT_QUAD_LAYOUT_OPTIONS_H
#define DIFFUV_LAYOUT_QUAD_LAYOUT_OPTIONS_H

#include <cstddef>

namespace diffuv {

/// Options of the four-sided layout.
struct Quad_layout_options {
  /// How many faces a cell holds to start with (cells are split in about six
  /// quads each). 0: from `target_patches`.
  double faces_per_cell = 900;
  /// If set (> 0), aim at about this many patches instead of `faces_per_cell`.
  std::size_t target_patches = 0;
  std::size_t relax_steps = 5;         ///< Lloyd-like steps moving seeds to the deepest face of their cell
  std::size_t max_cuts = 5;            ///< at most this many cuts from a cell's centre (shorter arcs collapse)
  double short_arc_fraction = 0.25;    ///< an arc shorter than this fraction of its cells' mean arc collapses
  double min_opening = 0.;             ///< a sector whose angle at its centre is below this (radians) collapses an arc
  bool collapse_near_junction = true;  ///< collapse a short arc whose dual edge crosses it next to a junction
  std::size_t max_cells = 100000;      ///< stop adding seeds for non-disc cells beyond this
  std::size_t min_cell_faces = 0;      ///< a smaller cell joins a neighbour of its region (if both stay discs)
  std::size_t min_split_faces = 400;   ///< refinement splits no cell smaller than this, unless:
  /// a patch of at least this many faces whose map is bad may have its cell
  /// split whatever the cell's size: such a patch is most of its cell, and
  /// large enough that the halves can still be fanned (a cow's leg left as
  /// one 255-face quad by a layout of labels folded almost whole: L2 130; a
  /// 119-face patch of the coarse triceratops around a horn: L2 21;
  /// doc/layout.md, "Large patches in small cells")
  std::size_t min_split_patch_faces = 100;
  std::size_t refine_rounds = 4;       ///< rounds of refinement asked by the judge (see `quad_layout()`)
  /// Labelled regions stay whole when they are all discs and at least this
  /// share of their faces lie in regions with exactly four runs of neighbours
  /// (a layout read back: its few fallback patches are small).
  double keep_layout_fraction = 0.75;
  /// Labelled regions (not a layout read back): a face with two edges on its
  /// region's border towards one same other region joins that region first
  /// (`move_ear_faces_across_borders()`). Such a face is flat in any map of
  /// its patch unless a corner sits on its tip, and a painted border's stair
  /// steps have many (cow in four height bands: 46 faces, man in six: 117).
  bool move_region_ears = true;
  /// Voronoi distances grow by this factor times sqrt(region area / seeds)
  /// per radian of turn along a path (0: plain geodesic cells; kept for study,
  /// it did not help on the CGAL meshes, see doc/layout.md).
  double bend = 0;
  std::size_t min_fix_faces = 100;     ///< cells smaller than this are not refined for the cell-complex rules
  /// A cell deeper than this times (rim length / 2 pi) is an extremity (a
  /// finger tip, a horn): it is framed by a ring of wall quads around an inner
  /// quad instead of being cut through one centre. 0 turns framing off.
  double frame_depth = 1.0;
  /// Cut fallback patches that need more than four corners (junctions, ear
  /// tips) between two junctions until no piece does (`split_at_junctions()`).
  bool split_at_junctions = true;
  /// ... with no cut longer than this times the boundary arc it cuts off
  /// (longer cuts made slivers: doc/layout.md).
  double max_cut_ratio = 0.5;
};

/// What the four-sided layout did.
struct Quad_layout_report {
  std::size_t cells = 0;             ///< Voronoi cells
  std::size_t collapsed_arcs = 0;    ///< arcs collapsed (too short, crossed next to a junction, too many cuts)
  std::size_t quads = 0;             ///< four-sided patches of the layout
  std::size_t fallback_patches = 0;  ///< patches whose region could not be fanned (corners from their neighbours)
  std::size_t cell_fallbacks = 0;    ///< cells that could not be fanned
  std::size_t region_fallbacks = 0;  ///< dual regions that could not be fanned nor kept as plain sectors
  std::size_t plain_regions = 0;     ///< dual regions kept as the cells' sectors (corner at the junction)
  std::size_t kept_regions = 0;      ///< labelled regions kept whole (they were a four-sided layout already)
  std::size_t region_ears_moved = 0; ///< faces that jutted out of their labelled region, moved into the region they jutted into (`move_region_ears`)
  std::size_t rounds = 0;            ///< refinement rounds run
  std::size_t refined_cells = 0;     ///< seeds added by the refinement
  std::size_t framed_cells = 0;      ///< deep cells split into walls and a tip (extremities)
  std::size_t split_fallbacks = 0;   ///< fallback patches needing more than four corners (junctions, ear tips) cut between junctions (`split_at_junctions()`)
  std::size_t fans_made = 0;         ///< fans flattened and traced, over all rounds
  std::size_t fans_reused = 0;       ///< fans found unchanged from an earlier round (`internal::Fan_memo`)
};

} // namespace diffuv

#endif // DIFFUV_LAYOUT_QUAD_LAYOUT_OPTIONS_H
