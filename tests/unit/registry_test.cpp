// The registry template (core/registry.hpp): every_kind, the one per-kind
// assertion helper every registry's concept check goes through.

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "core/registry.hpp"

namespace lc {
namespace {

struct KindA {};
struct KindB {};

// Counts the kinds it is called for, in order, at compile time.
constexpr int order_of_visits() {
  int n = 0, seen_b_after_a = 0;
  every_kind<std::variant<KindA, KindB>>([&]<class K>() {
    if constexpr (std::is_same_v<K, KindB>) seen_b_after_a = n == 1;
    ++n;
  });
  return n * 10 + seen_b_after_a;
}

TEST(Registry, EveryKindVisitsEachKindOfAVariantOrARegistryInOrder) {
  static_assert(order_of_visits() == 21);
  int n = 0;
  const bool all = every_kind<std::variant<KindA, KindB, KindA>>([&]<class K>() { ++n; });
  EXPECT_TRUE(all);
  EXPECT_EQ(n, 3);
}

// No registry header writes its own per-kind assertion helper again (the
// four copies every_kind replaced: satisfies_camera_model, all_skies, ...).
TEST(Registry, NoRegistryHeaderWritesItsOwnPerKindAssertion) {
  namespace fs = std::filesystem;
  static const std::regex own_helper(R"(constexpr bool (satisfies_\w+|all_\w+)\s*\()");
  for (const auto& e : fs::recursive_directory_iterator(fs::path(LIGHTCONE_SOURCE_DIR) / "engine")) {
    if (!e.is_regular_file() || e.path().extension() != ".hpp") continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_FALSE(std::regex_search(text.str(), own_helper))
        << e.path() << " writes its own per-kind assertion helper; use every_kind (core/registry.hpp)";
  }
}

}  // namespace
}  // namespace lc
