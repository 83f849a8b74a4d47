// The data-layer table (render/layers.hpp) is what docs/layers.md lists,
// and what a frame carries.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "render/layers.hpp"
#include "render/renderer.hpp"

namespace lc {
namespace {

TEST(Layers, DocsListEveryLayerAsTheTableSaysIt) {
  std::ifstream in(std::string(LIGHTCONE_SOURCE_DIR) + "/docs/layers.md");
  ASSERT_TRUE(in) << "docs/layers.md";
  std::stringstream text;
  text << in.rdbuf();
  for (const LayerSpec& l : layers) {
    const std::string row = "| `" + std::string(l.name) + "` | " + std::string(l.what) + " |";
    EXPECT_NE(text.str().find(row), std::string::npos) << "docs/layers.md lacks the row\n" << row;
  }
}

TEST(Layers, AFrameCarriesEveryLayerInTableOrder) {
  const FrameImage f = make_frame(RenderSettings{4, 2, 1, true});
  ASSERT_EQ(f.layers.size(), layer_count);
  for (std::size_t k = 0; k < layer_count; ++k) EXPECT_EQ(f.layers[k].name, layers[k].name);
  HitRecord s;
  s.kind = HitKind::horizon;
  s.r = 2.5;
  s.order = 3;
  s.g = 0.75;
  const LayerValues v = layer_values(s);
  const auto value = [&](std::string_view name) {
    for (std::size_t k = 0; k < layer_count; ++k)
      if (layers[k].name == name) return v[k];
    ADD_FAILURE() << "no layer " << name;
    return -1.0f;
  };
  EXPECT_EQ(value("hit.kind"), 2.0f);
  EXPECT_EQ(value("hit.r"), 2.5f);
  EXPECT_EQ(value("hit.g"), 0.75f);
  EXPECT_EQ(value("hit.order"), 3.0f);
}

}  // namespace
}  // namespace lc
