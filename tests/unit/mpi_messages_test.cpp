// The MPI farm's messages (transport/mpi_messages.hpp): a result carries a
// stripe's rows and layers, and alpha only where it is needed.

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "job/stripes.hpp"
#include "transport/mpi_messages.hpp"

namespace lc::farm {
namespace {

TEST(MpiMessages, ResultRoundTripsRowsAndLayers) {
  RenderSettings rs;
  rs.width = 3;
  rs.height = 5;
  rs.layers = true;
  FrameImage src = make_frame(rs), dst = make_frame(rs);
  for (std::size_t i = 0; i < src.rgb.size(); ++i) src.rgb[i] = static_cast<float>(i) + 0.5f;
  for (auto& l : src.layers)
    for (std::size_t i = 0; i < l.values.size(); ++i) l.values[i] = -static_cast<float>(i);
  const StripeLayout layout(5, 2);
  const WorkItem item{4, 1, Pass::full};
  const Bytes b = pack_result(item, {7, 8, 9}, src, layout.rows(1));
  EXPECT_EQ(result_item(b), item);
  const RenderStats st = unpack_result(b, dst, layout.rows(1));
  EXPECT_EQ(st.rays, 7);
  EXPECT_EQ(st.gave_up, 9);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 3; ++i) {
      const std::size_t p = static_cast<std::size_t>(j * 3 + i);
      EXPECT_EQ(dst.rgb[3 * p], j % 2 == 1 ? src.rgb[3 * p] : 0.0f);
      EXPECT_EQ(dst.layers[4].values[p], j % 2 == 1 ? src.layers[4].values[p] : 0.0f);
    }
  EXPECT_THROW(unpack_result(b, dst, layout.rows(0)), std::runtime_error);  // 3 rows, not 2
  EXPECT_EQ(unpack_items(pack_items({{1, 2, Pass::preview}, {3, 4, Pass::full}})),
            (std::vector<WorkItem>{{1, 2, Pass::preview}, {3, 4, Pass::full}}));
}

// Alpha travels only with a set that has a pixel not opaque: an opaque
// set's message is exactly as large as before alpha existed.
TEST(MpiMessages, AlphaTravelsOnlyWhereSomePixelIsNotOpaque) {
  RenderSettings rs;
  rs.width = 4;
  rs.height = 4;
  FrameImage src = make_frame(rs), dst = make_frame(rs);
  const StripeLayout layout(4, 2);  // stripe 0: rows 0, 2; stripe 1: rows 1, 3
  src.alpha[4 * 1 + 2] = 0.25f;     // row 1: stripe 1
  const Bytes opaque = pack_result({0, 0, Pass::full}, {}, src, layout.rows(0));
  const Bytes clear = pack_result({0, 1, Pass::full}, {}, src, layout.rows(1));
  EXPECT_EQ(clear.size() - opaque.size(), 2 * 4 * sizeof(float));
  unpack_result(opaque, dst, layout.rows(0));
  unpack_result(clear, dst, layout.rows(1));
  EXPECT_EQ(dst.alpha, src.alpha);
  FrameImage no_room = make_frame(rs);
  no_room.alpha.clear();
  EXPECT_THROW(unpack_result(clear, no_room, layout.rows(1)), std::runtime_error);
}

}  // namespace
}  // namespace lc::farm
