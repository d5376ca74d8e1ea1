// Tests of split_regions_into_quads() (layout/sub_patches.h): regions of three
// or five to nine runs become four-sided sectors, the same on shuffled,
// following and remeshed copies.
#include "test_correspondence_data.h"

namespace {

// Runs of neighbours around a patch, counted here from its border halfedges
// (not through patch_loops()): the rule of split_regions_into_quads() is
// "split a region whose border changes neighbour k != 4 times and has k = 3
// or 5..9 runs of at least a tenth of its perimeter (same-neighbour runs
// joined across shorter ones)". Returns 0 for a patch whose border is not one
// simple loop.
std::size_t runs_that_count(const Mesh& m, const diffuv::Segmentation<Mesh>& seg, std::size_t p, std::size_t& changes)
{
  using halfedge_descriptor = Mesh::Halfedge_index;
  const std::size_t border = std::numeric_limits<std::size_t>::max();
  std::map<vertex_descriptor, halfedge_descriptor> leaving;  // border halfedge of p by its source
  for(face_descriptor f : seg.patch_faces[p])
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
      const face_descriptor g = m.face(m.opposite(h));
      if(g != Mesh::null_face() && seg.face_patch[g.idx()] == p) continue;
      if(!leaving.emplace(m.source(h), h).second) return 0;  // the border touches itself
    }
  std::vector<std::size_t> neighbour;
  std::vector<double> length;
  halfedge_descriptor h = leaving.begin()->second;
  for(std::size_t steps = 0; steps < leaving.size(); ++steps) {
    const face_descriptor g = m.face(m.opposite(h));
    neighbour.push_back(g == Mesh::null_face() ? border : seg.face_patch[g.idx()]);
    length.push_back(std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h)))));
    h = leaving.at(m.target(h));
  }
  if(h != leaving.begin()->second) return 0;  // more than one loop
  const std::size_t n = neighbour.size();
  std::vector<std::size_t> run_start;
  for(std::size_t i = 0; i < n; ++i)
    if(neighbour[i] != neighbour[(i + n - 1) % n]) run_start.push_back(i);
  changes = run_start.size();
  if(changes < 2) return changes;
  const double perimeter = std::accumulate(length.begin(), length.end(), 0.);
  std::vector<std::size_t> long_runs;  // their neighbours, in order
  for(std::size_t j = 0; j < run_start.size(); ++j) {
    double l = 0;
    for(std::size_t i = run_start[j]; i != run_start[(j + 1) % run_start.size()]; i = (i + 1) % n) l += length[i];
    if(l >= 0.1 * perimeter) long_runs.push_back(neighbour[run_start[j]]);
  }
  std::vector<std::size_t> joined;
  for(std::size_t q : long_runs)
    if(joined.empty() || joined.back() != q) joined.push_back(q);
  while(joined.size() > 1 && joined.front() == joined.back()) joined.pop_back();
  return joined.size();
}

// The sub-patches of labelled regions: each region with 3 or 5..9 runs of
// neighbours becomes that many discs, each with its four corners on its
// border, sharing one centre inside the region, the centre's sector keys
// numbered 100·part + 10·k + s + 1; every other region stays as it was.
TEST(SubPatches, RegionsOfThreeOrFiveToNineRunsBecomeFourSidedSectors)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  diffuv::Segmentation<Mesh> regions;
  ASSERT_TRUE(diffuv::disc_patches(a, a.points(), labels, regions, diffuv::Labelled_atlas_options().patching).ok());
  std::map<std::pair<int, int>, std::size_t> expected;  // (label, part) of a region -> its runs, if split
  std::size_t whole = 0;
  for(std::size_t p = 0; p < regions.number_of_patches(); ++p) {
    std::size_t changes = 0;
    const std::size_t k = runs_that_count(a, regions, p, changes);
    if(changes != 4 && (k == 3 || (k >= 5 && k <= 9))) expected[{regions.patch_label[p], regions.patch_part[p]}] = k;
    else ++whole;
  }
  ASSERT_GE(expected.size(), 3u) << "cow's 12 Voronoi regions should have several with 3 or 5+ runs";

  diffuv::Segmentation<Mesh> seg = regions;
  const diffuv::Sub_patch_report report = diffuv::split_regions_into_quads(a, a.points(), seg);
  EXPECT_EQ(report.regions_split + report.not_split, expected.size());
  EXPECT_LE(report.not_split, 1u);
  ASSERT_EQ(report.runs.size(), regions.number_of_patches());

  std::size_t sectors_seen = 0, whole_seen = 0;
  for(std::size_t p = 0; p < regions.number_of_patches(); ++p) {
    const auto it = expected.find({regions.patch_label[p], regions.patch_part[p]});
    std::vector<std::size_t> pieces;  // the patches of seg on region p's faces
    for(face_descriptor f : regions.patch_faces[p]) pieces.push_back(seg.face_patch[f.idx()]);
    std::sort(pieces.begin(), pieces.end());
    pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
    if(report.runs[p].empty()) {
      ASSERT_EQ(pieces.size(), 1u);
      EXPECT_EQ(seg.patch_faces[pieces[0]].size(), regions.patch_faces[p].size());
      EXPECT_EQ(seg.patch_part[pieces[0]], regions.patch_part[p]);
      ++whole_seen;
      continue;
    }
    ASSERT_NE(it, expected.end()) << "region " << p << " was split but has 4 runs or more than 9";
    const std::size_t k = it->second;
    EXPECT_EQ(report.runs[p].size(), k);
    ASSERT_EQ(pieces.size(), k);
    std::size_t faces_in_sectors = 0;
    vertex_descriptor centre = Mesh::null_vertex();
    for(std::size_t s = 0; s < k; ++s) {
      const std::size_t q = pieces[s];
      ++sectors_seen;
      faces_in_sectors += seg.patch_faces[q].size();
      EXPECT_EQ(seg.patch_label[q], regions.patch_label[p]);
      const int part = seg.patch_part[q] - 100 * regions.patch_part[p] - 10 * static_cast<int>(k);
      EXPECT_TRUE(part >= 1 && part <= static_cast<int>(k)) << seg.patch_part[q];
      // A disc: one border loop and Euler characteristic 1.
      std::size_t changes = 0;
      EXPECT_GT(runs_that_count(a, seg, q, changes), 0u) << "sector " << q << " has no simple border";
      std::set<vertex_descriptor> vs;
      std::set<std::pair<vertex_descriptor, vertex_descriptor>> es;
      for(face_descriptor f : seg.patch_faces[q])
        for(auto h : CGAL::halfedges_around_face(a.halfedge(f), a)) {
          vs.insert(a.source(h));
          es.insert(std::minmax(a.source(h), a.target(h)));
        }
      EXPECT_EQ(static_cast<long>(vs.size()) - static_cast<long>(es.size()) + static_cast<long>(seg.patch_faces[q].size()), 1);
      // Four distinct corners, all on the sector's border; the first is the shared centre.
      const auto* corners = seg.corners(q);
      ASSERT_NE(corners, nullptr);
      std::set<vertex_descriptor> distinct(corners->begin(), corners->end());
      EXPECT_EQ(distinct.size(), 4u);
      if(s == 0) centre = (*corners)[0];
      EXPECT_EQ((*corners)[0], centre);
      for(vertex_descriptor c : *corners) {
        bool on_border = false;
        for(auto h : CGAL::halfedges_around_target(c, a)) {
          const face_descriptor f1 = a.face(h), f2 = a.face(a.opposite(h));
          const bool in1 = f1 != Mesh::null_face() && seg.face_patch[f1.idx()] == q;
          const bool in2 = f2 != Mesh::null_face() && seg.face_patch[f2.idx()] == q;
          on_border = on_border || in1 != in2;
        }
        EXPECT_TRUE(on_border) << "corner " << c.idx() << " of sector " << q;
      }
    }
    EXPECT_EQ(faces_in_sectors, regions.patch_faces[p].size());
    // The centre lies inside the region: every face around it is the region's.
    for(face_descriptor f : CGAL::faces_around_target(a.halfedge(centre), a))
      EXPECT_TRUE(f != Mesh::null_face() && regions.face_patch[f.idx()] == p);
  }
  EXPECT_EQ(sectors_seen, report.sub_patches);
  EXPECT_EQ(whole_seen + report.regions_split, regions.number_of_patches());
  EXPECT_GE(whole_seen, whole);
}

// The split depends on the surface and the labels only: a shuffled copy gets
// (shuffled, or also rotated and scaled) gets the same sectors, face for
// face, with the same corners.
TEST(SubPatches, SameSectorsOnAShuffledCopy)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  for(bool move : {false, true}) {
  SCOPED_TRACE(move ? "moved copy" : "shuffled copy");
  const Moved_copy b = shuffled_moved_copy(a, 17, move);
  Atlas atlas_a(a), atlas_b(b.mesh);
  diffuv::Labelled_atlas_options options;
  options.sub_patches = true;
  build(a, labels, atlas_a, options);
  build(b.mesh, carry_labels(labels, b), atlas_b, options);
  ASSERT_GT(atlas_a.sub_patching.regions_split, 0u);
  EXPECT_EQ(atlas_a.split_runs, atlas_b.split_runs);
  const auto keys_a = diffuv::patch_keys(atlas_a.segmentation), keys_b = diffuv::patch_keys(atlas_b.segmentation);
  std::map<diffuv::Patch_key, std::size_t> patch_b;
  for(std::size_t q = 0; q < keys_b.size(); ++q) patch_b[keys_b[q]] = q;
  ASSERT_EQ(patch_b.size(), keys_a.size());
  const auto& seg_a = atlas_a.segmentation;
  const auto& seg_b = atlas_b.segmentation;
  for(std::size_t p = 0; p < keys_a.size(); ++p) {
    ASSERT_EQ(patch_b.count(keys_a[p]), 1u);
    const std::size_t q = patch_b[keys_a[p]];
    for(face_descriptor f : seg_a.patch_faces[p]) EXPECT_EQ(seg_b.face_patch[b.face_of[f.idx()].idx()], q);
    if(const auto* corners = seg_a.corners(p)) {
      ASSERT_NE(seg_b.corners(q), nullptr);
      for(int i = 0; i < 4; ++i) EXPECT_EQ((*seg_b.corners(q))[i], b.vertex_of[(*corners)[i].idx()]) << "patch " << p << " corner " << i;
    }
  }
  }
}

// Following: B splits as A did even where its own rule would not (here B's
// options would split nothing), and the shuffled pair still maps exactly.
TEST(SubPatches, AFollowingMeshSplitsAsTheOneItFollows)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  const Moved_copy b = shuffled_moved_copy(a, 23, false);
  Atlas atlas_a(a), atlas_b(b.mesh);
  diffuv::Labelled_atlas_options options;
  options.sub_patches = true;
  build(a, labels, atlas_a, options);
  ASSERT_GT(atlas_a.sub_patching.regions_split, 0u);
  diffuv::Labelled_atlas_options own = options;
  own.sub_patching.split_three = false;
  own.sub_patching.max_runs = 4;
  {
    Atlas alone(b.mesh);
    build(b.mesh, carry_labels(labels, b), alone, own);
    EXPECT_EQ(alone.sub_patching.regions_split, 0u) << "these options should split nothing on their own";
  }
  const diffuv::Atlas_to_follow follow = diffuv::atlas_to_follow(atlas_a);
  ASSERT_TRUE(diffuv::build_labelled_atlas(b.mesh, b.mesh.points(), carry_labels(labels, b), follow, atlas_b, own).ok());
  EXPECT_EQ(atlas_b.split_runs, atlas_a.split_runs);
  EXPECT_EQ(atlas_b.sub_patching.regions_split, atlas_a.sub_patching.regions_split);
  const Correspondence c(atlas_a, atlas_b);
  EXPECT_TRUE(c.report().unmatched_patches_a.empty());
  const auto images = c.map_vertices();
  double worst = 0;
  for(auto v : vertices(a)) {
    ASSERT_TRUE(images[v.idx()].mapped());
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(images[v.idx()].point, b.mesh.point(b.vertex_of[v.idx()]))));
  }
  EXPECT_LE(worst, 1e-9 * sqrt_area(b.mesh));
}

// The split is a rule of the surface and the region borders, not of the
// tessellation: on a Loop-subdivided and on an isotropically remeshed cow,
// labelled by nearness to the cow's regions, every region splits into sectors
// with the same keys, and each sector covers nearly the same surface as the
// cow's (the cow's sectors carried over by nearness; the cuts are edge paths
// of each mesh, so they may land a few faces apart).
TEST(SubPatches, SameSectorsOnARemeshedCopy)
{
  const Mesh& a = cow();
  const std::vector<int> labels = segment_labels(a);
  diffuv::Labelled_atlas_options options;
  options.sub_patches = true;
  Atlas atlas_a(a);
  build(a, labels, atlas_a, options);
  ASSERT_GT(atlas_a.sub_patching.regions_split, 2u);
  const auto keys_a = diffuv::patch_keys(atlas_a.segmentation);
  std::vector<int> sector_a(num_faces(a));  // the patch of each face of the cow
  for(auto f : faces(a)) sector_a[f.idx()] = static_cast<int>(atlas_a.segmentation.face_patch[f.idx()]);

  Mesh loop = a;
  CGAL::Subdivision_method_3::Loop_subdivision(loop, CGAL::parameters::number_of_iterations(1));
  Mesh remeshed = a;
  CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(remeshed), 0.012 * sqrt_area(a), remeshed,
                                                     CGAL::parameters::number_of_iterations(3));
  remeshed.collect_garbage();
  for(const Mesh* b : {&loop, &remeshed}) {
    SCOPED_TRACE(b == &loop ? "Loop subdivision" : "isotropic remeshing");
    ASSERT_NE(num_faces(*b), num_faces(a));
    Atlas atlas_b(*b);
    build(*b, diffuv::nearest_face_labels(a, labels, *b), atlas_b, options);
    EXPECT_EQ(atlas_b.split_runs, atlas_a.split_runs);
    const auto keys_b = diffuv::patch_keys(atlas_b.segmentation);
    EXPECT_EQ(std::set<diffuv::Patch_key>(keys_b.begin(), keys_b.end()), std::set<diffuv::Patch_key>(keys_a.begin(), keys_a.end()));
    // Area of each of B's patches, and the part of it nearest the cow's patch of the same key.
    const std::vector<int> carried = diffuv::nearest_face_labels(a, sector_a, *b);
    std::map<diffuv::Patch_key, double> area, agreeing;
    double all = 0, all_agreeing = 0;
    for(auto f : faces(*b)) {
      const std::size_t q = atlas_b.segmentation.face_patch[f.idx()];
      const double fa = CGAL::Polygon_mesh_processing::face_area(f, *b);
      area[keys_b[q]] += fa;
      all += fa;
      if(keys_a[static_cast<std::size_t>(carried[f.idx()])] == keys_b[q]) {
        agreeing[keys_b[q]] += fa;
        all_agreeing += fa;
      }
    }
    // Measured (2026-12-03): 94.3 % of the area on the Loop copy, 91.2 % on
    // the remeshed one; the worst sectors 71 % (Loop: one of region 10's six)
    // and 64 % (remeshed: region 8), where a cut turns a little. A sector
    // matched to the wrong one would be near 0.
    EXPECT_GE(all_agreeing / all, 0.88);
    for(const auto& [key, b_area] : area) {
      if(std::get<1>(key) <= 10) continue;  // a region kept whole (part 0, or a piece of a region cut into discs)
      EXPECT_GE(agreeing[key] / b_area, 0.55) << "sector " << std::get<0>(key) << "/" << std::get<1>(key);
    }
  }
}

} // namespace
