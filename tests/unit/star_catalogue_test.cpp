// Reading KStars' stars.dat text format (engine/stars/star_catalogue.hpp)
// from lines typed here for well-known stars (positions J2000 from the
// Hipparcos catalogue, ESA 1997): Sirius 06h45m08.92s -16d42'58.0", V
// -1.44, B-V 0.01; Vega 18h36m56.34s +38d47'01.3", V 0.03; a faint star to
// be left out; malformed lines naming the line and the field; and
// Ballesteros' temperature of the Sun's colour.

#include "stars/star_catalogue.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "scratch_dir.hpp"
#include "test_errors.hpp"

namespace lc {
namespace {

namespace fs = std::filesystem;

// A stars.dat line: RA, Dec, then proper motions and parallax (not read),
// V and B-V in their columns, spectral type and the multiplicity flag.
std::string line(const char* ra, const char* dec, const char* v, const char* bv) {
  return fmt::format("{} {} -000546.0-001223.100379.2 {}{}A0 1", ra, dec, v, bv);
}

fs::path write(const test::ScratchDir& dir, const std::string& text) {
  const fs::path file = dir / "stars.dat";
  std::ofstream(file) << text;
  return file;
}

TEST(StarCatalogue, ReadsPositionsMagnitudesAndColours) {
  test::ScratchDir dir;
  const fs::path file = write(dir, "# a comment\n# another\n" + line("064508.92", "-164258.0", "-1.44", "00.01") +
                                       ", alp CMa, Sirius\n" + line("183656.34", "+384701.3", "00.03", "-0.00") + "\n" +
                                       line("000000.00", "+000000.0", "08.99", "01.24") + "\n");
  const std::vector<CatalogueStar> stars = read_star_catalogue(file, 8.0, 1000);
  ASSERT_EQ(stars.size(), 2u);  // the V = 8.99 star is fainter than 8
  // Tolerance 1e-12 rad: the decimal arithmetic's rounding.
  EXPECT_NEAR(stars[0].ra, (6 + 45 / 60.0 + 8.92 / 3600) * 15 * degree, 1e-12);
  EXPECT_NEAR(stars[0].ra / degree, 101.28717, 1e-5);
  EXPECT_NEAR(stars[0].dec / degree, -16.71611, 1e-5);
  EXPECT_EQ(stars[0].v_mag, -1.44);
  EXPECT_EQ(stars[0].b_v, 0.01);
  EXPECT_NEAR(stars[1].ra / degree, 279.23475, 1e-5);
  EXPECT_NEAR(stars[1].dec / degree, 38.78369, 1e-5);
  EXPECT_EQ(stars[1].v_mag, 0.03);
  EXPECT_EQ(read_star_catalogue(file, 9.0, 1000).size(), 3u);
}

TEST(StarCatalogue, MalformedLinesNameTheLineAndTheField) {
  test::ScratchDir dir;
  const std::string good = line("064508.92", "-164258.0", "-1.44", "00.01") + "\n";
  struct Case {
    std::string text, says;
  };
  for (const Case& c : {Case{good + line("6h45m", "-164258.0", "-1.44", "00.01"), ":2: the right ascension (columns 1-9) is not hhmmss.ss"},
                        Case{good + good + line("064508.92", " 164258.0", "-1.44", "00.01"),
                             ":3: the declination (columns 11-19) is not sddmmss.s with its sign"},
                        Case{line("246508.92", "-164258.0", "-1.44", "00.01"), ":1: the right ascension"},
                        Case{line("064508.92", "-164258.0", "bright", "00.01"), ":1: the magnitude V (columns 47-51) is not a number from -2 to 30"},
                        Case{line("064508.92", "-164258.0", "-1.44", ""), ":1: the colour index B-V (columns 52-56) is not a number from -1 to 6"},
                        // A line one column short: V and B-V read half from their neighbours.
                        Case{"064508.92 -164258.0 -000546.0-001223.10379.2 -1.4400.01A0 1", ":1: the colour index B-V"},
                        Case{"064508.92 -16", ":1: the declination"},
                        // std::from_chars reads "nan" and "inf"; NaN passed every range check and
                        // crashed the star bins (issue #25).
                        Case{line("0645  nan", "-164258.0", "-1.44", "00.01"), ":1: the right ascension (columns 1-9)"},
                        Case{line("0645 -nan", "-164258.0", "-1.44", "00.01"), ":1: the right ascension (columns 1-9)"},
                        Case{line("064508.92", "-1642 nan", "-1.44", "00.01"), ":1: the declination (columns 11-19)"},
                        Case{line("064508.92", "-1642 inf", "-1.44", "00.01"), ":1: the declination (columns 11-19)"},
                        Case{line("0645-1.00", "-164258.0", "-1.44", "00.01"), ":1: the right ascension (columns 1-9)"},
                        Case{line("064508.92", "-164258.0", "  nan", "00.01"), ":1: the magnitude V (columns 47-51)"},
                        Case{line("064508.92", "-164258.0", " -inf", "00.01"), ":1: the magnitude V (columns 47-51)"},
                        Case{line("064508.92", "-164258.0", "-1.44", "  nan"), ":1: the colour index B-V (columns 52-56)"},
                        Case{line("064508.92", "-164258.0", "-1.44", "  inf"), ":1: the colour index B-V (columns 52-56)"}}) {
    const fs::path file = write(dir, c.text);
    const std::string msg = test::error_of<CatalogueError>([&] { read_star_catalogue(file, 9.0, 1000); });
    EXPECT_EQ(msg.rfind(file.string(), 0), 0u) << msg;
    EXPECT_NE(msg.find(c.says), std::string::npos) << msg;
  }
}

TEST(StarCatalogue, MissingFilesDirectoriesAndTooManyStarsAreRefused) {
  test::ScratchDir dir;
  EXPECT_NE(test::error_of<CatalogueError>([&] { read_star_catalogue(dir / "none.dat", 9, 10); })
                .find("none.dat: no such star catalogue"),
            std::string::npos);
  EXPECT_NE(test::error_of<CatalogueError>([&] { read_star_catalogue(dir.path(), 9, 10); }).find("not a regular file"),
            std::string::npos);
  std::string many;
  for (int k = 0; k < 5; ++k) many += line("064508.92", "-164258.0", "-1.44", "00.01") + "\n";
  const fs::path file = write(dir, many);
  EXPECT_NE(test::error_of<CatalogueError>([&] { read_star_catalogue(file, 9, 4); })
                .find("more than 4 stars brighter than V = 9"),
            std::string::npos);
}

TEST(StarCatalogue, ALineLongerThanTheLimitIsRefusedWithoutHoldingIt) {
  test::ScratchDir dir;
  const std::string good = line("064508.92", "-164258.0", "-1.44", "00.01") + "\n";
  // A line just under the limit is read (its columns past 56 are not);
  // one over it is refused naming its line, however long it goes on.
  const std::string under = line("064508.92", "-164258.0", "-1.44", "00.01") + std::string(max_catalogue_line - 70, 'x');
  ASSERT_LE(under.size(), max_catalogue_line);
  EXPECT_EQ(read_star_catalogue(write(dir, good + under + "\n"), 9, 10).size(), 2u);
  const std::string over = good + good + std::string(5'000'000, 'y') + "\n" + good;
  const std::string msg = test::error_of<CatalogueError>([&] { read_star_catalogue(write(dir, over), 9, 10); });
  EXPECT_NE(msg.find("stars.dat:3: the line is longer than 1024 bytes"), std::string::npos) << msg;
}

TEST(StarCatalogue, ACatalogueThatGivesNoStarSaysSo) {
  test::ScratchDir dir;
  for (const std::string text : {std::string(), std::string("# only a comment\n\n")}) {
    const fs::path file = write(dir, text);
    const std::string msg = test::error_of<CatalogueError>([&] { read_star_catalogue(file, 9, 10); });
    EXPECT_EQ(msg.rfind(file.string() + ": 0 stars read from it: it holds no star line", 0), 0u) << msg;
  }
  const fs::path file = write(dir, line("064508.92", "-164258.0", "-1.44", "00.01") + "\n");
  const std::string msg = test::error_of<CatalogueError>([&] { read_star_catalogue(file, -2, 10); });
  EXPECT_NE(msg.find("0 stars read from it: none of its 1 stars is as bright as V = -2: raise `faintest`"),
            std::string::npos)
      << msg;
}

TEST(StarCatalogue, TheSunsColourIsTheSunsTemperature) {
  // Ballesteros calibrated his formula so that the Sun, B-V = 0.65, is at
  // ~5,780 K; Vega's 0.00 is ~10,125 K (against ~9,600 K measured: the
  // formula is a blackbody fit, good to a few percent on the main sequence).
  EXPECT_NEAR(star_temperature(0.65), 5778, 5);
  EXPECT_NEAR(star_temperature(0.0), 10125, 5);
  EXPECT_GT(star_temperature(-0.3), star_temperature(0.0));
  EXPECT_EQ(star_temperature(-3.0), star_temperature(-0.4));  // clamped
}

}  // namespace
}  // namespace lc
