#include "script/constructor_docs.hpp"

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace lc {
namespace {

// docs/shots.md holds `lightcone fields` verbatim, so the reference a user
// reads is what the constructors declare.
TEST(ConstructorDocs, ShotsGuideHoldsTheGeneratedReference) {
  std::ifstream in(std::string(LIGHTCONE_SOURCE_DIR) + "/docs/shots.md");
  ASSERT_TRUE(in) << "docs/shots.md";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(constructor_tables()), std::string::npos)
      << "docs/shots.md's constructor reference differs from the declarations: paste `lightcone fields` into it";
}

// Every registered kind reaches the reference with its declared fields,
// and a '|' in a description does not break its table row.
TEST(ConstructorDocs, ListsEveryKindWithItsFields) {
  const std::string t = constructor_tables();
  for (const char* heading : {"#### `lc.kerr{...}`", "#### `lc.dihole{...}`", "#### `lc.minkowski{...}`",
                              "#### `lc.camera{...}`", "#### `lc.sky_checker{...}`", "#### `lc.sky_image{...}`",
                              "#### `lc.sky_stars{...}`", "#### `lc.disk{...}`", "#### `lc.sphere{...}`"})
    EXPECT_NE(t.find(heading), std::string::npos) << heading;
  EXPECT_NE(t.find("| `mass` | required | at least 0 | the mass M |"), std::string::npos);
  EXPECT_NE(t.find("| `fov` | 60 degrees | greater than 0 and less than 180 degrees |"), std::string::npos);
  EXPECT_NE(t.find("\\|a\\| <= M"), std::string::npos);
  EXPECT_NE(t.find("`worldline = w`"), std::string::npos) << "the sphere's placement is documented";
}

}  // namespace
}  // namespace lc
