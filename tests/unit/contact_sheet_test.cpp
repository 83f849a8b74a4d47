// The contact sheet (video/contact_sheet.hpp): its picks spread evenly, and
// its thumbnails, read a band of rows at a time, are the whole image's area
// average.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "image/image_io.hpp"
#include "image/srgb.hpp"
#include "scratch_dir.hpp"
#include "video/contact_sheet.hpp"
#include "video/pixel_font.hpp"
#include "video/rgb8_image.hpp"
#include "video/title_card.hpp"

namespace {

TEST(ContactSheet, PicksSpreadEvenlyWithFirstAndLast) {
  EXPECT_EQ(lc::pick_evenly(5, 16), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(lc::pick_evenly(900, 4), (std::vector<std::size_t>{0, 300, 599, 899}));
  EXPECT_EQ(lc::pick_evenly(10, 1), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(lc::pick_evenly(0, 4).empty());
  for (std::size_t n = 2; n < 60; ++n)
    for (std::size_t k = 2; k < n; ++k) {
      const auto p = lc::pick_evenly(n, k);
      ASSERT_EQ(p.size(), k);
      EXPECT_EQ(p.front(), 0u);
      EXPECT_EQ(p.back(), n - 1);
      for (std::size_t i = 1; i < k; ++i) ASSERT_LT(p[i - 1], p[i]) << n << " " << k;
    }
}

// The area average as the contact sheet made it before it read frames in
// bands (the whole image in memory, both axes' weights at once): what the
// band-by-band thumbnail must equal.
lc::FrameImage whole_image_average(const lc::FrameImage& src, int w, int h) {
  auto spans = [](int n_src, int n_dst) {
    std::vector<std::pair<int, std::vector<double>>> s(static_cast<std::size_t>(n_dst));
    const double ratio = static_cast<double>(n_src) / n_dst;
    for (int d = 0; d < n_dst; ++d) {
      const double a = d * ratio, b = (d + 1) * ratio;
      const int first = static_cast<int>(std::floor(a));
      const int last = std::min(n_src - 1, static_cast<int>(std::ceil(b)) - 1);
      s[static_cast<std::size_t>(d)].first = first;
      for (int k = first; k <= last; ++k)
        s[static_cast<std::size_t>(d)].second.push_back((std::min<double>(b, k + 1) - std::max<double>(a, k)) / ratio);
    }
    return s;
  };
  const auto xs = spans(src.width, w), ys = spans(src.height, h);
  lc::FrameImage out;
  out.width = w;
  out.height = h;
  out.rgb.assign(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto& [fy, wy] = ys[static_cast<std::size_t>(y)];
      const auto& [fx, wx] = xs[static_cast<std::size_t>(x)];
      double acc[3] = {0, 0, 0};
      for (std::size_t j = 0; j < wy.size(); ++j)
        for (std::size_t i = 0; i < wx.size(); ++i)
          for (std::size_t c = 0; c < 3; ++c)
            acc[c] += wy[j] * wx[i] *
                      src.rgb[3 * ((static_cast<std::size_t>(fy) + j) * static_cast<std::size_t>(src.width) +
                                   static_cast<std::size_t>(fx) + i) +
                              c];
      for (std::size_t c = 0; c < 3; ++c)
        out.rgb[3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) + c] =
            static_cast<float>(acc[c]);
    }
  return out;
}

TEST(ContactSheet, ABandByBandThumbnailIsTheWholeImagesAreaAverage) {
  lc::test::ScratchDir dir;
  std::mt19937 rng(25);
  // 1000 x 700: many bands of 64 rows and a short last one; then a small
  // frame blown up (each output row then takes a part of one source row).
  for (const auto [w, h, tw, th] : {std::array{1000, 700, 154, 108}, std::array{32, 18, 160, 90}}) {
    lc::FrameImage frame;
    frame.width = w;
    frame.height = h;
    frame.rgb.resize(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (float& v : frame.rgb) v = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    const auto file = dir / "frame.png";
    lc::write_png(file, frame);
    const lc::FrameImage expected = whole_image_average(lc::read_image_linear(file), tw, th);
    const lc::FrameImage got = lc::thumbnail(file, tw, th, {w, h});
    ASSERT_EQ(got.width, tw);
    ASSERT_EQ(got.height, th);
    ASSERT_EQ(got.rgb.size(), expected.rgb.size());
    for (std::size_t i = 0; i < got.rgb.size(); ++i)
      ASSERT_NEAR(got.rgb[i], expected.rgb[i], 1e-6f * std::max(1.0f, expected.rgb[i])) << i;
    // A frame of another size than the sequence's first is named.
    EXPECT_THROW(lc::thumbnail(file, tw, th, {w + 1, h}), std::runtime_error);
  }
}

}  // namespace
