// Tests of lc::resolve_sky_image (engine/assets/asset_path.cpp): which files
// a shot may name as sky images, and what is said about the others.

#include "assets/asset_path.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using lc::resolve_sky_image;
using lc::test::ScratchDir;

std::string error_of(const fs::path& file, const std::vector<fs::path>& dirs) {
  try {
    resolve_sky_image(file, dirs);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << file;
  return {};
}

// A shot's folder, the project's shots/ folder, and a folder outside both.
class SceneAssetPath : public ::testing::Test {
 protected:
  SceneAssetPath() {
    for (const char* d : {"shot", "shots/textures", "elsewhere"}) fs::create_directories(dir_ / d);
    std::ofstream(dir_ / "shot" / "sky.png") << "png";
    std::ofstream(dir_ / "shots" / "textures" / "starfield.png") << "png";
    std::ofstream(dir_ / "elsewhere" / "secret.png") << "secret";
    dirs_ = {dir_ / "shot", dir_ / "shots"};
  }
  ScratchDir dir_;
  std::vector<fs::path> dirs_;
};

TEST_F(SceneAssetPath, FindsFilesInTheShotsFolderThenTheProjects) {
  EXPECT_EQ(resolve_sky_image("sky.png", dirs_), fs::canonical(dir_ / "shot" / "sky.png"));
  EXPECT_EQ(resolve_sky_image("textures/starfield.png", dirs_),
            fs::canonical(dir_ / "shots" / "textures" / "starfield.png"));
  EXPECT_EQ(resolve_sky_image("../shot/./sky.png", dirs_), fs::canonical(dir_ / "shot" / "sky.png"));
  // A link that stays inside is fine (and resolved: one file, one hash).
  fs::create_symlink(dir_ / "shots" / "textures" / "starfield.png", dir_ / "shot" / "stars.png");
  EXPECT_EQ(resolve_sky_image("stars.png", dirs_), fs::canonical(dir_ / "shots" / "textures" / "starfield.png"));
  EXPECT_EQ(error_of("nope.png", dirs_), "sky image 'nope.png' not found; looked in:\n  " +
                                             (dir_ / "shot" / "nope.png").string() + "\n  " +
                                             (dir_ / "shots" / "nope.png").string());
}

// Absolute paths and links out of the folders were read as they were
// (a link to /etc/shadow was hashed and decoded).
TEST_F(SceneAssetPath, RefusesWhatLeavesTheFolders) {
  EXPECT_EQ(error_of(dir_ / "shot" / "sky.png", dirs_),
            "sky image '" + (dir_ / "shot" / "sky.png").string() +
                "': the field 'file' must be a path relative to the shot's folder, not an absolute one");
  EXPECT_EQ(error_of("/dev/zero", dirs_),
            "sky image '/dev/zero': the field 'file' must be a path relative to the shot's folder, not an absolute one");
  fs::create_symlink(dir_ / "elsewhere" / "secret.png", dir_ / "shot" / "link.png");
  EXPECT_EQ(error_of("link.png", dirs_), "sky image 'link.png' (" + (dir_ / "shot" / "link.png").string() +
                                             ") leads through a link to " +
                                             fs::canonical(dir_ / "elsewhere" / "secret.png").string() +
                                             ", outside the folders sky images are read from (" +
                                             (dir_ / "shot").string() + ", " + (dir_ / "shots").string() + ")");
  EXPECT_NE(error_of("../elsewhere/secret.png", dirs_).find("outside the folders sky images are read from"),
            std::string::npos);
  fs::create_symlink("/dev/zero", dir_ / "shot" / "zero.png");
  EXPECT_NE(error_of("zero.png", dirs_).find("leads through a link to /dev/zero, outside"), std::string::npos);
}

// A FIFO or a device is no image: reading it blocked or never ended.
TEST_F(SceneAssetPath, RefusesWhatIsNoRegularFile) {
  ASSERT_EQ(::mkfifo((dir_ / "shot" / "fifo.png").c_str(), 0600), 0);
  EXPECT_EQ(error_of("fifo.png", dirs_),
            "sky image 'fifo.png' (" + (dir_ / "shot" / "fifo.png").string() + ") is a FIFO, not a regular file");
  EXPECT_EQ(error_of("textures", dirs_), "sky image 'textures' (" + (dir_ / "shots" / "textures").string() +
                                             ") is a directory, not a regular file");
}

}  // namespace
