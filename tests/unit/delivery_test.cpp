// Delivery from the command line (pipeline/job/delivery_flags.hpp,
// camera/delivery.hpp): the flags -> the delivery, refused with the flag
// named where they do not fit; the delivery -> the camera the frames are
// made through (a dome's tilt and the subject's height checked by where the
// shot's forward lands in the dome master, ODS's stereo and separation) and
// the sky (--sky kstars); the journal spells the delivery so that older
// lines read as they did and a changed flag is another setting.

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "camera/camera.hpp"
#include "camera/delivery.hpp"
#include "camera/equirect.hpp"
#include "camera/fisheye.hpp"
#include "camera/pinhole_params.hpp"
#include "core/constants.hpp"
#include "job/delivery_flags.hpp"
#include "job/render_job.hpp"
#include "monitor/pixel_trace.hpp"
#include "scene/delivered_sky.hpp"
#include "scene/scene_spec.hpp"
#include "scratch_dir.hpp"
#include "sky/sky.hpp"
#include "store/checked_line.hpp"
#include "store/journal.hpp"

namespace lc {
namespace {

// Sets an environment variable for one test and unsets it after.
struct ScopedCatalogue {
  explicit ScopedCatalogue(const std::string& file) { ::setenv("LIGHTCONE_STAR_CATALOGUE", file.c_str(), 1); }
  ~ScopedCatalogue() { ::unsetenv("LIGHTCONE_STAR_CATALOGUE"); }
};

// The message delivery_from_flags refuses `flags` with ("" if accepted).
std::string refusal(const DeliveryFlags& flags) {
  try {
    delivery_from_flags(flags);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Delivery, NoFlagsIsTheShotsOwn) {
  EXPECT_EQ(delivery_from_flags({}), Delivery{});
  DeliveryFlags dome;
  dome.camera = "dome";
  const Delivery d = delivery_from_flags(dome);
  EXPECT_EQ(d.camera, DeliveryCamera::dome);
  EXPECT_EQ(d.dome_tilt, 0.0);
  EXPECT_EQ(d.dome_elevation, 35.0);
  EXPECT_FALSE(d.beyond_camera());  // a plain dome digests and journals as before
}

TEST(Delivery, TheDomesAnglesAndOdsSeparationAreTaken) {
  DeliveryFlags flags;
  flags.camera = "dome";
  flags.dome_tilt = 15;
  flags.dome_elevation = 45;
  const Delivery d = delivery_from_flags(flags);
  EXPECT_EQ(d.dome_tilt, 15.0);
  EXPECT_EQ(d.dome_elevation, 45.0);
  EXPECT_TRUE(d.beyond_camera());
  DeliveryFlags ods;
  ods.camera = "ods";
  ods.separation = 0.5;
  EXPECT_EQ(delivery_from_flags(ods).camera, DeliveryCamera::ods);
  EXPECT_EQ(delivery_from_flags(ods).separation, 0.5);
}

TEST(Delivery, FlagsThatDoNotFitAreRefusedNamingThem) {
  DeliveryFlags tilt_alone;
  tilt_alone.dome_tilt = 15;
  EXPECT_TRUE(has(refusal(tilt_alone), "--dome-tilt 15: only with --camera dome")) << refusal(tilt_alone);
  DeliveryFlags elevation_360;
  elevation_360.camera = "360";
  elevation_360.dome_elevation = 45;
  EXPECT_TRUE(has(refusal(elevation_360), "--dome-elevation 45: only with --camera dome")) << refusal(elevation_360);
  DeliveryFlags steep;
  steep.camera = "dome";
  steep.dome_tilt = 91;
  EXPECT_TRUE(has(refusal(steep), "--dome-tilt 91: must be between 0 and 90 degrees")) << refusal(steep);
  steep.dome_tilt.reset();
  steep.dome_elevation = -5;
  EXPECT_TRUE(has(refusal(steep), "--dome-elevation -5: must be between 0 and 90 degrees")) << refusal(steep);
  DeliveryFlags separation_dome;
  separation_dome.camera = "dome";
  separation_dome.separation = 0.5;
  EXPECT_TRUE(has(refusal(separation_dome), "--separation 0.5: only with --camera ods")) << refusal(separation_dome);
  DeliveryFlags no_eyes;
  no_eyes.camera = "ods";
  no_eyes.separation = 0;
  EXPECT_TRUE(has(refusal(no_eyes), "--separation 0: must be greater than 0")) << refusal(no_eyes);
  DeliveryFlags fisheye;
  fisheye.camera = "fisheye";
  EXPECT_TRUE(has(refusal(fisheye), "--camera fisheye: expected shot, dome, 360 or ods")) << refusal(fisheye);
}

TEST(Delivery, SkyKstarsWithoutTheCatalogueSaysWhichPackageToInstall) {
  const test::ScratchDir dir;
  const ScopedCatalogue missing((dir.path() / "none.dat").string());
  DeliveryFlags flags;
  flags.sky = "kstars";
  const std::string said = refusal(flags);
  EXPECT_TRUE(has(said, "--sky kstars reads KStars' star catalogue " + (dir.path() / "none.dat").string() +
                            ", which is not there: install Debian's kstars-data"))
      << said;
  std::ofstream(dir.path() / "stars.dat") << "\n";
  const ScopedCatalogue present((dir.path() / "stars.dat").string());
  EXPECT_EQ(delivery_from_flags(flags).sky, DeliverySky::kstars);
}

// Where the shot's forward (its subject) lands in the dome master: on the
// centre column, (90 - E - T) / 90 of the disc's radius below the centre
// (the image's bottom edge is the dome's front), E above the audience's
// horizon whatever the dome's tilt T.
void expect_subject_at(const Delivery& d, double elevation, double tilt) {
  PinholeParams shot;  // looking along the aim, no yaw, pitch or roll
  const CameraSpec spec = delivered(CameraSpec{shot}, d);
  const auto* dome = spec.get_if<FisheyeParams>();
  ASSERT_NE(dome, nullptr);
  EXPECT_EQ(dome->tilt, tilt);
  EXPECT_EQ(dome->full_angle, 180.0);
  const int size = 64;
  const FisheyeCamera camera(*dome, size, size);
  const double rho = (90.0 - elevation - tilt) / 90.0;
  const Vec3 at = camera.direction(0.5 * size, 0.5 * size * (1.0 + rho));
  const Vec3 forward = turned_axes(0, 0, 0).forward;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(at[k], forward[k], 1e-12) << "component " << k;
}

TEST(Delivery, TheDomePutsTheSubjectAtItsElevationForAnyTilt) {
  Delivery d;
  d.camera = DeliveryCamera::dome;
  expect_subject_at(d, 35.0, 0.0);  // the default, today's 55-degree pitch
  d.dome_elevation = 45;
  d.dome_tilt = 15;
  expect_subject_at(d, 45.0, 15.0);
  d.dome_elevation = 20;
  d.dome_tilt = 30;
  expect_subject_at(d, 20.0, 30.0);
  // The shot's own pitch is added to the dome's.
  PinholeParams looking_up;
  looking_up.pitch = 10;
  looking_up.yaw = 30;
  const auto dome = delivered(CameraSpec{looking_up}, d).get<FisheyeParams>();
  EXPECT_EQ(dome.pitch, 10.0 + 70.0);
  EXPECT_EQ(dome.yaw, 30.0);
}

TEST(Delivery, OdsIsTheSphereInTopBottomStereoOnASquareFrame) {
  Delivery d;
  d.camera = DeliveryCamera::ods;
  d.separation = 0.5;
  PinholeParams shot;
  shot.yaw = 40;
  shot.pitch = 20;
  shot.roll = 5;
  const auto ods = delivered(CameraSpec{shot}, d).get<EquirectParams>();
  EXPECT_EQ(ods.stereo, StereoLayout::top_bottom);
  EXPECT_EQ(ods.separation, 0.5);
  EXPECT_EQ(ods.yaw, 40.0);  // the heading kept, the horizon level
  EXPECT_EQ(ods.pitch, 0.0);
  EXPECT_EQ(ods.roll, 0.0);
  EXPECT_EQ(delivery_size(DeliveryCamera::ods, 256, 144), (std::pair{288, 288}));
  EXPECT_EQ(delivery_size(DeliveryCamera::sphere, 256, 144), (std::pair{288, 144}));
  // Each eye's picture of ODS is the 360's frame.
  const EquirectCamera camera(ods, 288, 288);
  ASSERT_EQ(camera.pictures().size(), 2u);
  EXPECT_EQ(camera.pictures()[0].width, 288);
  EXPECT_EQ(camera.pictures()[0].height, 144);
  d.camera = DeliveryCamera::sphere;
  d.separation = default_ods_separation;
  EXPECT_EQ(delivered(CameraSpec{shot}, d).get<EquirectParams>().stereo, StereoLayout::mono);
}

TEST(Delivery, SkyKstarsSwitchesStarsAndReplacesTheCheckerButNotAnImage) {
  PointStarSky::Params generated;
  generated.rotate = 12;
  generated.brightness = 34;
  generated.faintest = 7;
  generated.background = "generated";
  const auto real = std::get<PointStarSky::Params>(delivered_sky(SkySpec{generated}, DeliverySky::kstars));
  EXPECT_EQ(real.catalogue, StarCatalogue::kstars);
  EXPECT_EQ(real.rotate, 12.0);
  EXPECT_EQ(real.brightness, 34.0);
  EXPECT_EQ(real.faintest, 7.0);
  EXPECT_EQ(real.background, "none");  // the generated band is not the real sky's
  generated.background = "milkyway.png";
  EXPECT_EQ(std::get<PointStarSky::Params>(delivered_sky(SkySpec{generated}, DeliverySky::kstars)).background,
            "milkyway.png");
  StarImageSky::Params texture;
  texture.rotate = 5;
  const auto from_texture = std::get<PointStarSky::Params>(delivered_sky(SkySpec{texture}, DeliverySky::kstars));
  EXPECT_EQ(from_texture.catalogue, StarCatalogue::kstars);
  EXPECT_EQ(from_texture.rotate, 5.0);
  CheckerSky::Params checker;
  checker.brightness = -2;
  const auto from_checker = std::get<PointStarSky::Params>(delivered_sky(SkySpec{checker}, DeliverySky::kstars));
  EXPECT_EQ(from_checker.catalogue, StarCatalogue::kstars);
  EXPECT_EQ(from_checker.brightness, -2.0);
  ImageSky::Params image;
  image.file = "pano.exr";
  try {
    delivered_sky(SkySpec{image}, DeliverySky::kstars);
    FAIL() << "an image sky was replaced";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(has(e.what(), "--sky kstars: the sky is lc.sky_image{file = \"pano.exr\"}")) << e.what();
    EXPECT_TRUE(has(e.what(), "lc.starfield{catalogue = \"kstars\", background = \"pano.exr\"}")) << e.what();
  }
  // Without --sky every sky is the shot's.
  EXPECT_TRUE(std::holds_alternative<ImageSky::Params>(delivered_sky(SkySpec{image}, DeliverySky::shot)));
}

// A sky kind with every member of SkyModel but real_stars: what a new kind
// that forgot to say what render --sky kstars makes of it looks like.
struct SkyWithoutRealStars {
  static constexpr std::string_view name = "sky_toy";
  struct Params {
    double rotate = 0.0;
    static constexpr auto fields = std::tuple{
        field("rotate", &Params::rotate, std::optional<double>{0.0}, std::nullopt, std::nullopt, "longitude", "degrees"),
    };
  };
  static std::vector<std::string> assets(const Params&) { return {}; }
  SkyWithoutRealStars(const Params&, ShotResources&) {}
  Color color(double, double) const { return {0.0f, 0.0f, 0.0f}; }
};
struct SkyWithRealStars : SkyWithoutRealStars {
  using SkyWithoutRealStars::SkyWithoutRealStars;
  static PointStarSky::Params real_stars(const Params& p) { return real_stars_at(p.rotate, 0.0); }
};
// A sky that does not say what it is delivered as under --sky kstars is
// not a sky: the registry's static_assert refuses it by name, where before
// it silently became the real stars at rotation 0 and brightness 0.
static_assert(!SkyModel<SkyWithoutRealStars>, "a sky kind must say what --sky kstars delivers it as");
static_assert(SkyModel<SkyWithRealStars>);

// Every registered sky, its rotate and brightness set: under --sky kstars
// each is the real stars at them, or (an image) refused naming its file.
TEST(Delivery, SkyKstarsCarriesEveryKindsRotationAndBrightnessOrRefusesIt) {
  int kinds = 0;
  SkyRegistry::for_each([&](auto* kind) {
    using K = std::remove_pointer_t<decltype(kind)>;
    typename K::Params p;
    p.rotate = 7;
    p.brightness = 3;
    if constexpr (std::is_same_v<K, ImageSky>) p.file = "pano.exr";
    ++kinds;
    try {
      const auto real = std::get<PointStarSky::Params>(delivered_sky(SkySpec{p}, DeliverySky::kstars));
      EXPECT_FALSE((std::is_same_v<K, ImageSky>)) << "an image sky was replaced";
      EXPECT_EQ(real.catalogue, StarCatalogue::kstars) << K::name;
      EXPECT_EQ(real.rotate, 7.0) << K::name;
      EXPECT_EQ(real.brightness, 3.0) << K::name;
      EXPECT_EQ(real.background, "auto") << K::name;  // the real sky's default, black
    } catch (const std::invalid_argument& e) {
      EXPECT_TRUE((std::is_same_v<K, ImageSky>)) << K::name << ": " << e.what();
      EXPECT_EQ(std::string(e.what()),
                "--sky kstars: the sky is lc.sky_image{file = \"pano.exr\"}, a picture of the shot's own that the "
                "real stars would be drawn over (stars in it would be doubled): to keep it behind them give the shot "
                "lc.starfield{catalogue = \"kstars\", background = \"pano.exr\"}, else leave out --sky "
                "(docs/cameras.md)");
    }
  });
  EXPECT_EQ(kinds, 4);  // a new kind: add its expectation above
}

TEST(Delivery, TheJournalSpellsTheDeliveryAndOlderLinesReadAsBefore) {
  farm::JournalFrame f;
  f.frame = 3;
  f.settings = {64, 64, 1, false, false};
  f.inputs = "0123456789abcdef";
  f.settings.delivery.camera = DeliveryCamera::dome;
  // A plain dome's line is what it always was.
  EXPECT_EQ(farm::delivery_fields(f.settings.delivery), " camera=dome");
  const std::string plain = farm::journal_frame_line(f);
  f.settings.delivery.dome_tilt = 15;
  f.settings.delivery.dome_elevation = 45.5;
  f.settings.delivery.sky = DeliverySky::kstars;
  EXPECT_EQ(farm::delivery_fields(f.settings.delivery), " camera=dome dome_tilt=15 dome_elevation=45.5 sky_catalogue=kstars");
  const std::string tilted = farm::journal_frame_line(f);
  const auto j = farm::parse_journal(farm::journal_header_line() + "\n" + plain + "\n" + tilted + "\n", "j");
  ASSERT_EQ(j.frames.size(), 1u);
  EXPECT_EQ(j.frames.at(3).settings, f.settings);
  const auto old = farm::parse_journal(farm::journal_header_line() + "\n" + plain + "\n", "j");
  EXPECT_EQ(old.frames.at(3).settings.delivery.camera, DeliveryCamera::dome);
  EXPECT_FALSE(old.frames.at(3).settings == f.settings);  // a resume with other flags is refused
  const std::string said = f.settings.describe(old.frames.at(3).settings);
  EXPECT_TRUE(has(said, "through the dome camera (tilted 15 degrees, the subject 45.5 degrees up), under the KStars sky"))
      << said;
  // ODS's separation.
  f.settings.delivery = Delivery{DeliveryCamera::ods};
  f.settings.delivery.separation = 0.25;
  const auto ods = farm::parse_journal(farm::journal_header_line() + "\n" + farm::journal_frame_line(f) + "\n", "j");
  EXPECT_EQ(ods.frames.at(3).settings.delivery, f.settings.delivery);
  // Values no lightcone writes make the line a bad one.
  for (const std::string& bad : {" camera=dome dome_tilt=91", " camera=ods separation=0", " camera=shot",
                                 " camera=dome sky_catalogue=tycho", " camera=dome dome_elevation=nan"}) {
    std::string line = plain;
    line.replace(line.find(" camera=dome"), std::string(" camera=dome").size(), bad);
    const std::string content = line.substr(0, line.rfind(" #"));
    const auto read = farm::parse_journal(farm::journal_header_line() + "\n" + farm::with_check(content) + "\n", "j");
    EXPECT_TRUE(read.frames.empty()) << bad;
    EXPECT_EQ(read.bad_lines, 1) << bad;  // (its check holds: it is skipped for what it says)
  }
}

// The flags the words say, as main.cpp hands them over.
DeliveryFlags flags_of(const std::vector<std::string>& words) {
  DeliveryFlags out;
  for (std::size_t k = 0; k + 1 < words.size(); k += 2) {
    const std::string &flag = words[k], &value = words[k + 1];
    if (flag == "--camera") out.camera = value;
    else if (flag == "--dome-tilt") out.dome_tilt = std::stod(value);
    else if (flag == "--dome-elevation") out.dome_elevation = std::stod(value);
    else if (flag == "--separation") out.separation = std::stod(value);
    else if (flag == "--sky") out.sky = value;
    else ADD_FAILURE() << "unknown flag " << flag;
  }
  return out;
}

// The monitor's pixel inspector asks trace for the delivery the journal
// recorded: the words read back to the same delivery, to the bit.
TEST(Delivery, TheFlagWordsAskForTheSameDelivery) {
  Delivery d{DeliveryCamera::dome};
  EXPECT_EQ(monitor::delivery_flag_words(d), (std::vector<std::string>{"--camera", "dome"}));
  d.dome_tilt = 15;
  d.dome_elevation = 0.1 + 0.2;  // (no short decimal)
  EXPECT_EQ(delivery_from_flags(flags_of(monitor::delivery_flag_words(d))), d);
  Delivery ods{DeliveryCamera::ods};
  ods.separation = 0.5;
  EXPECT_EQ(monitor::delivery_flag_words(ods), (std::vector<std::string>{"--camera", "ods", "--separation", "0.5"}));
  EXPECT_EQ(delivery_from_flags(flags_of(monitor::delivery_flag_words(ods))), ods);
  EXPECT_EQ(delivery_from_flags(flags_of(monitor::delivery_flag_words(Delivery{}))), Delivery{});
}

// The job's digest (what an MPI master and its workers compare) and its
// frame size follow the delivery.
TEST(Delivery, TheRenderJobTakesTheDelivery) {
  RenderRequest cmd;
  cmd.shot = std::string(LIGHTCONE_TEST_DATA) + "/farm/farm_orbit.lua";
  cmd.out = "unused";
  cmd.frames = "0";
  cmd.delivery.camera = "dome";
  const RenderJob plain = load_render_job(cmd);
  cmd.delivery.dome_tilt = 15;
  const RenderJob tilted = load_render_job(cmd);
  EXPECT_NE(plain.digest, tilted.digest);
  const auto camera = tilted.shot->frame(0).camera.get<FisheyeParams>();
  EXPECT_EQ(camera.tilt, 15.0);
  cmd.delivery = {};
  cmd.delivery.camera = "ods";
  const RenderJob ods = load_render_job(cmd);
  EXPECT_EQ(ods.rs.width, ods.rs.height);
  EXPECT_EQ(ods.rs.width, 2 * plain.rs.height);
}

}  // namespace
}  // namespace lc
