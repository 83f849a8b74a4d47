// The renderer's pixel stages (render/pixel_rows.hpp) driven from outside
// the renderer: hit records as the one source of the pixels (kept records
// shade to the same pixels, byte for byte), a camera of the test's own
// that has no ray through half its image, and one that moves the eye, whose
// image shifts as flat space says.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "camera/pinhole.hpp"
#include "core/constants.hpp"
#include "objects/disk.hpp"
#include "objects/sphere.hpp"
#include "render/pixel_rows.hpp"
#include "render/scene_builder.hpp"
#include "render/scene_visit.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"
#include "test_scenes.hpp"

namespace lc {
namespace {

// Every row of a frame through the pixel stages with `camera` and `tracer`.
template <class S, class C, class T = pixel_rows::TraceRays>
FrameImage render_with(const SceneIn<S>& sc, const C& camera, const RenderSettings& rs, RenderStats* stats = nullptr,
                       const T& tracer = {}) {
  FrameImage img = make_frame(rs);
  if (sc.sky.point_stars()) img.sky.assign(static_cast<std::size_t>(rs.width) * rs.height, SkyPoint{});
  std::vector<int> rows;
  for (int j = 0; j < rs.height; ++j) rows.push_back(j);
  const RenderStats s = render_rows_with(sc, camera, rs, std::span<const int>(rows), img, nullptr, tracer);
  if (stats) *stats = s;
  return img;
}

// The trace stage that also keeps every record it traced, by (row, sample).
using KeptRecords = std::map<std::pair<int, std::size_t>, HitRecord>;
struct KeepingTracer {
  KeptRecords* kept;
  template <class S>
  void operator()(const SceneIn<S>& sc, std::span<const pixel_rows::SampleItem> items,
                  std::span<const RayStart> starts, std::span<HitRecord> out) const {
    trace_records(sc, starts, out);
    for (std::size_t n = 0; n < items.size(); ++n) (*kept)[{items[n].row, items[n].slot}] = out[n];
  }
};
// The trace stage replaced by the kept records: nothing is traced.
struct ReplayTracer {
  const KeptRecords* kept;
  template <class S>
  void operator()(const SceneIn<S>&, std::span<const pixel_rows::SampleItem> items, std::span<const RayStart>,
                  std::span<HitRecord> out) const {
    for (std::size_t n = 0; n < items.size(); ++n) out[n] = kept->at({items[n].row, items[n].slot});
  }
};

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(PixelRows, RecordsShadeToTheSamePixels) {
  // Every path of the ray loop and every kind of end: the Kerr fast path
  // with its disk, and Kerr–Schild with a sphere, in the light model that
  // splits g (the record's g and its gravitational part), with point stars
  // (the sky points), adaptive 2 x 2 samples and the layers.
  for (const bool sphere : {false, true}) {
    SceneSpec fs;
    fs.spacetime = Kerr(1, 0.9);
    fs.observer = StaticObserver::Params{{0, 30, 80 * degree, 0}};
    fs.camera.get<PinholeCamera::Params>().fov = 40;
    fs.objects.push_back(Disk::Params{6, 15, 9, 24});
    if (sphere) fs.objects.push_back(test::falling_sphere(fs.spacetime, {0, 10, 90 * degree, 0}, {0, 0, 0.3}, 60, 1.0));
    fs.light.model = LightModel::shifted;
    fs.sky = PointStarSky::Params{};
    ShotResources res;
    const RenderSettings rs{32, 18, 2, true, true};
    const Scene scene = build_scene(fs, rs.width, rs.height, res);
    visit_scene(
        [&](const auto& sc) {
          KeptRecords kept;
          RenderStats traced;
          const FrameImage first = render_with(sc, sc.camera, rs, &traced, KeepingTracer{&kept});
          ASSERT_EQ(static_cast<long>(kept.size()), traced.rays);
          const FrameImage again = render_with(sc, sc.camera, rs, nullptr, ReplayTracer{&kept});
          EXPECT_TRUE(same_bytes(first.rgb, again.rgb)) << (sphere ? "with a sphere" : "disk only");
          ASSERT_EQ(first.layers.size(), again.layers.size());
          for (std::size_t l = 0; l < first.layers.size(); ++l)
            EXPECT_TRUE(same_bytes(first.layers[l].values, again.layers[l].values)) << first.layers[l].name;
          ASSERT_FALSE(first.sky.empty());
          EXPECT_TRUE(same_bytes(first.sky, again.sky));
          // ... and they are the renderer's own pixels.
          const FrameImage rendered = render_frame(scene, rs, 1);
          EXPECT_TRUE(same_bytes(first.rgb, rendered.rgb));
        },
        scene);
  }
}

// A pinhole camera of the test's own that has no ray through the left half
// of its image.
struct HalfCamera {
  PinholeCamera pinhole;
  int width;
  std::optional<CameraRay> ray(const CameraSample& s) const {
    if (s.px < 0.5 * width) return std::nullopt;
    return pinhole.ray(s);
  }
  ImageWrap wrap() const { return {}; }
  const CameraAxes& axes() const { return pinhole.axes(); }
};

// Adaptive sampling along a row that wraps (a whole sphere's): its first
// and last pixels are neighbours, so a feature at the seam has both
// refined; along a row with edges neither looks across them.
TEST(PixelRows, AcrossAWrappedSeamTheEndsOfARowAreNeighbours) {
  const pixel_rows::RowGrid grid(2, 8);
  for (const bool wraps : {false, true}) {
    pixel_rows::RowPlan plan(grid, true, wraps);
    std::vector<std::size_t> where;
    plan.first_round(where);
    std::vector<FrameSample> samples(grid.W * grid.NN + grid.W);
    for (const std::size_t g : where) samples[g].kind = HitKind::sky;
    samples[where[0]].kind = HitKind::horizon;  // pixel 0 sees something else
    ASSERT_TRUE(plan.next_round(where, samples));
    std::set<std::size_t> refined;
    for (const std::size_t g : where) refined.insert(g / grid.NN);
    EXPECT_EQ(refined, wraps ? (std::set<std::size_t>{0, 1, 7}) : (std::set<std::size_t>{0, 1}));
  }
}

TEST(PixelRows, PointsWithoutARayAreBlackTransparentAndNeverTraced) {
  SceneSpec fs;
  fs.spacetime = Kerr(1, 0.5);
  fs.observer = StaticObserver::Params{{0, 30, 80 * degree, 0}};
  fs.objects.push_back(Disk::Params{6, 15, 9, 24});
  ShotResources res;
  const RenderSettings rs{16, 8, 2, true, true};
  const auto sc = scene_get<Kerr>(build_scene(fs, rs.width, rs.height, res));
  const HalfCamera half{PinholeCamera(fs.camera.get<PinholeCamera::Params>(), rs.width, rs.height), rs.width};
  RenderStats whole_stats, half_stats;
  const FrameImage whole = render_with(sc, sc.camera, rs, &whole_stats);
  const FrameImage img = render_with(sc, half, rs, &half_stats);
  EXPECT_EQ(half_stats.gave_up, 0);
  long traced_right = 0;
  for (int j = 0; j < rs.height; ++j)
    for (int i = 0; i < rs.width; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * rs.width + i;
      if (i < rs.width / 2) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(img.rgb[3 * p + c], 0.0f);
        EXPECT_EQ(img.alpha[p], 0.0f);
        EXPECT_EQ(img.layers[0].values[p], static_cast<float>(HitKind::no_ray));
      } else {
        // The half with rays is the whole camera's, pixel for pixel.
        for (int c = 0; c < 3; ++c) EXPECT_EQ(img.rgb[3 * p + c], whole.rgb[3 * p + c]);
        EXPECT_EQ(img.alpha[p], 1.0f);
      }
    }
  // Only the right half was traced: fewer rays than the whole image, and
  // at least one per pixel there.
  for (int j = 0; j < rs.height; ++j) traced_right += rs.width / 2;
  EXPECT_LT(half_stats.rays, whole_stats.rays);
  EXPECT_GE(half_stats.rays, traced_right);
}

// A pinhole camera of the test's own whose eye sits `offset` M along the
// camera's right axis from the observer.
struct MovedEyeCamera {
  PinholeCamera pinhole;
  double offset;
  std::optional<CameraRay> ray(const CameraSample& s) const {
    std::optional<CameraRay> r = pinhole.ray(s);
    for (int k = 0; k < 3; ++k) r->eye[k] = offset * pinhole.axes().right[k];
    return r;
  }
  ImageWrap wrap() const { return {}; }
  const CameraAxes& axes() const { return pinhole.axes(); }
};

TEST(PixelRows, AMovedEyeSeesTheImageShiftAsFlatSpaceSays) {
  // Flat space (the dihole without masses), a sphere of radius 1 at
  // x = 5, seen from 80 M along +y (forward -y, right = e_phi = -x).  An eye
  // d to the right (at x = -d) sees the sphere's centre at angle
  // atan((5 + d) / 80) to the left of forward, its limbs
  // asin(1 / hypot(5 + d, 80)) either side; the pinhole maps angle a to
  // image column W/2 (1 + tan a / tan(fov/2)).
  SceneSpec fs;
  fs.spacetime = Dihole(0.0, 0.0, 1.0);
  fs.observer = StaticObserver::Params{{0, 0, 80, 0}};
  fs.camera.get<PinholeCamera::Params>().fov = 12;
  Sphere::Params sp;
  sp.radius = 1.0;
  sp.placement.at = Vec4{0, 5, 0, 0};
  fs.objects.push_back(sp);
  ShotResources res;
  const RenderSettings rs{400, 1, 1, true, false};
  const auto sc = scene_get<Dihole>(build_scene(fs, rs.width, rs.height, res));
  const double t = std::tan(6 * degree);
  auto column_of = [&](double angle) { return rs.width / 2.0 * (1 + std::tan(angle) / t); };
  for (const double d : {0.0, 2.0, -3.0}) {
    const MovedEyeCamera camera{PinholeCamera(fs.camera.get<PinholeCamera::Params>(), rs.width, rs.height), d};
    RenderStats stats;
    const FrameImage img = render_with(sc, camera, rs, &stats);
    EXPECT_EQ(stats.gave_up, 0);
    int first = -1, last = -1;
    for (int i = 0; i < rs.width; ++i)
      if (img.layers[0].values[static_cast<std::size_t>(i)] == static_cast<float>(Sphere::hit_kind)) {
        if (first < 0) first = i;
        last = i;
      }
    ASSERT_GE(first, 0) << "d = " << d;
    const double centre = -std::atan2(5.0 + d, 80.0), half = std::asin(1.0 / std::hypot(5.0 + d, 80.0));
    // The first and last pixel centres inside the limbs: within a pixel.
    EXPECT_NEAR(first + 0.5, column_of(centre - half), 1.0) << "d = " << d;
    EXPECT_NEAR(last + 0.5, column_of(centre + half), 1.0) << "d = " << d;
  }
}

// The row loop is the stages called in order, on one screen, and a blurred
// frame has no branch of its own in it (only its items differ), so that a
// new per-sample feature becomes a field of SampleItem or a stage rather
// than one more branch of the loop (issue 44: it was 101 lines, `blurred`
// tested in seven places).
TEST(PixelRows, TheRowLoopFitsOnAScreenWithNoBranchForBlur) {
  std::ifstream in(std::filesystem::path(LIGHTCONE_SOURCE_DIR) / "engine/render/pixel_rows.hpp");
  ASSERT_TRUE(in) << "engine/render/pixel_rows.hpp";
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t from = text.find("RenderStats render_rows_with(");
  ASSERT_NE(from, std::string::npos) << "render_rows_with is not in render/pixel_rows.hpp";
  const std::size_t to = text.find("\n}\n", from);
  ASSERT_NE(to, std::string::npos);
  int lines = 0;
  for (std::size_t at = from; at < to;) {
    const std::size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end - at);
    const std::string code = line.substr(0, line.find("//"));
    EXPECT_EQ(code.find("blur"), std::string::npos) << "the row loop branches on blur: " << line;
    ++lines;
    at = end + 1;
  }
  EXPECT_LE(lines + 1, 40) << "the row loop no longer fits on a screen";
}

}  // namespace
}  // namespace lc
