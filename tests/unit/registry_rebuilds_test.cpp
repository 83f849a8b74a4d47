// What adding a kind rebuilds (docs/architecture.md, "What a new kind
// rebuilds"): a new camera, object, sky, observer or spacetime kind is one
// line in its registry's header, so every translation unit that includes
// that header, directly or through others, is compiled again.  The test
// counts them in the build's own terms: the translation units and include
// directories of build/compile_commands.json, and each file's #include "..."
// lines resolved as the compiler does (the including file's folder first,
// then the -I folders in order).  Counted so, the numbers equal the
// compiler's depfiles' (checked by hand when the limits were set:
// docs/architecture.md).  A limit is the count reached; the goal
// stands beside it, and a change that lowers a count lowers its limit.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

struct TranslationUnit {
  fs::path file;
  std::vector<fs::path> include_dirs;  // the -I folders, in order
};

// The text of a JSON string that starts at `from` (just past its opening
// quote), its escapes undone; compile_commands.json escapes only quotes and
// backslashes in what CMake writes.
std::string json_string_at(const std::string& text, std::size_t from) {
  std::string out;
  for (std::size_t i = from; i < text.size() && text[i] != '"'; ++i) out += text[i] == '\\' ? text[++i] : text[i];
  return out;
}

// Every translation unit the build compiles, from the compile database
// CMake writes at configure time (CMAKE_EXPORT_COMPILE_COMMANDS): its source
// and its -I folders.  Assumes CMake's layout, "command" before "file" in
// each entry.
std::vector<TranslationUnit> translation_units(const fs::path& database) {
  std::ifstream in(database);
  if (!in) return {};
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::vector<TranslationUnit> out;
  const std::string command_key = "\"command\": \"", file_key = "\"file\": \"";
  for (std::size_t at = text.find(command_key); at != std::string::npos; at = text.find(command_key, at + 1)) {
    TranslationUnit tu;
    std::istringstream words(json_string_at(text, at + command_key.size()));
    for (std::string w; words >> w;)
      if (w.rfind("-I", 0) == 0 && w.size() > 2) tu.include_dirs.emplace_back(w.substr(2));
    const std::size_t file_at = text.find(file_key, at);
    if (file_at == std::string::npos) break;
    tu.file = fs::path(json_string_at(text, file_at + file_key.size())).lexically_normal();
    out.push_back(std::move(tu));
  }
  return out;
}

// The files `file` names in #include "..." lines, each resolved as the
// compiler resolves it: the including file's folder, then `dirs` in order;
// a name found in none (a system header in quotes) is left out.
std::vector<fs::path> direct_includes(const fs::path& file, const std::vector<fs::path>& dirs) {
  std::vector<fs::path> out;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != '#') continue;
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || line.compare(i, 7, "include") != 0) continue;
    const std::size_t open = line.find('"', i + 7), close = open == std::string::npos ? open : line.find('"', open + 1);
    if (close == std::string::npos) continue;
    const std::string name = line.substr(open + 1, close - open - 1);
    std::vector<fs::path> search{file.parent_path()};
    search.insert(search.end(), dirs.begin(), dirs.end());
    for (const fs::path& dir : search) {
      const fs::path p = (dir / name).lexically_normal();
      if (!fs::exists(p)) continue;
      out.push_back(p);
      break;
    }
  }
  return out;
}

// Every file a translation unit includes, directly or through others.
std::set<fs::path> includes_of(const TranslationUnit& tu) {
  std::set<fs::path> seen;
  std::vector<fs::path> todo{tu.file};
  while (!todo.empty()) {
    const fs::path f = todo.back();
    todo.pop_back();
    for (const fs::path& p : direct_includes(f, tu.include_dirs))
      if (seen.insert(p).second) todo.push_back(p);
  }
  return seen;
}

// A kind of kind: the headers a new one's registry line(s) are written in
// (engine/-relative), the count reached and the goal; or, for a
// change to one kind's code, that kind's header.
struct KindSeam {
  const char* change;  // what is changed, as the report says it
  const char* docs_row;  // its row in docs/architecture.md's table ("" : none)
  std::vector<const char*> registry_headers;
  std::size_t limit;  // the count reached: more fails
  std::size_t goal;   // issue 44's; 0: none stated
};

// The registries, with the translation units a new kind rebuilds today.
const std::vector<KindSeam> seams = {
    {"a new camera kind", "camera", {"camera/camera_params.hpp", "camera/camera_registry.hpp"}, 7, 15},
    {"a new object kind", "object", {"objects/object_params.hpp", "objects/objects.hpp"}, 18, 15},
    {"a new sky kind", "sky", {"sky/sky.hpp"}, 61, 15},
    {"a new observer kind", "observer", {"observers/observers.hpp"}, 55, 15},
    {"a new spacetime kind", "spacetime", {"spacetime/spacetime.hpp"}, 19, 20},
    // A camera's code apart from its parameters (camera/fisheye_params.hpp):
    // only what builds cameras (camera/camera.cpp) and its tests include it.
    {"a change to the fisheye camera's code", "", {"camera/fisheye.hpp"}, 4, 0},
};

TEST(RegistryRebuilds, ANewKindRebuildsNoMoreThanItsLimit) {
  const fs::path database = fs::path(LIGHTCONE_BINARY_DIR) / "compile_commands.json";
  const std::vector<TranslationUnit> tus = translation_units(database);
  ASSERT_GT(tus.size(), 100u) << database << " lists too few translation units (is CMAKE_EXPORT_COMPILE_COMMANDS on?)";
  std::vector<std::set<fs::path>> included;
  for (const TranslationUnit& tu : tus) included.push_back(includes_of(tu));
  const fs::path engine = fs::path(LIGHTCONE_SOURCE_DIR) / "engine";
  for (const KindSeam& seam : seams) {
    std::size_t rebuilt = 0;
    for (const std::set<fs::path>& in : included) {
      bool hit = false;
      for (const char* header : seam.registry_headers) hit = hit || in.count((engine / header).lexically_normal()) > 0;
      rebuilt += hit;
    }
    // Printed on every run: the measure the docs quote.
    std::cout << seam.change << " rebuilds " << rebuilt << " of " << tus.size() << " translation units (limit "
              << seam.limit << ", goal " << seam.goal << ")\n";
    EXPECT_LE(rebuilt, seam.limit) << seam.change << " now rebuilds more translation units: a header that many files "
                                   << "include has begun to include " << seam.registry_headers.front();
  }
}

// The count is only as good as the include resolution: a registry header
// must be found in the translation units that name it directly.
TEST(RegistryRebuilds, CountsTheFilesThatIncludeARegistryDirectly) {
  const std::vector<TranslationUnit> tus = translation_units(fs::path(LIGHTCONE_BINARY_DIR) / "compile_commands.json");
  const fs::path source(LIGHTCONE_SOURCE_DIR);
  const fs::path fisheye_test = (source / "tests/unit/fisheye_test.cpp").lexically_normal();
  bool found = false;
  for (const TranslationUnit& tu : tus)
    if (tu.file == fisheye_test) {
      found = true;
      EXPECT_EQ(includes_of(tu).count((source / "engine/camera/fisheye.hpp").lexically_normal()), 1u);
    }
  EXPECT_TRUE(found) << "the compile database does not list " << fisheye_test;
}

// docs/architecture.md ("What a new kind rebuilds") states each limit and
// the number of translation units in a table; the test holds them equal,
// so the docs change with the limits.
TEST(RegistryRebuilds, TheDocsTableStatesEachLimit) {
  const std::size_t units = translation_units(fs::path(LIGHTCONE_BINARY_DIR) / "compile_commands.json").size();
  std::ifstream in(fs::path(LIGHTCONE_SOURCE_DIR) / "docs/architecture.md");
  ASSERT_TRUE(in) << "docs/architecture.md cannot be read";
  std::map<std::string, std::vector<std::string>> rows;  // first word of the row -> its cells
  bool header_seen = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| a new kind of |", 0) == 0) {
      header_seen = true;
      EXPECT_NE(line.find("now, the limit (of " + std::to_string(units) + ")"), std::string::npos)
          << "the table's header should say the build has " << units << " translation units: " << line;
      continue;
    }
    if (!header_seen || line.rfind("| ", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell.substr(1, cell.size() >= 2 ? cell.size() - 2 : 0));
    const std::string first = cells.empty() ? "" : cells[0].substr(0, cells[0].find(' '));
    rows[first] = cells;
  }
  ASSERT_TRUE(header_seen) << "docs/architecture.md has no table of what a new kind rebuilds";
  for (const KindSeam& seam : seams) {
    if (*seam.docs_row == '\0') continue;
    const auto row = rows.find(seam.docs_row);
    ASSERT_NE(row, rows.end()) << "docs/architecture.md's table has no row for " << seam.docs_row;
    ASSERT_GE(row->second.size(), 4u) << seam.docs_row;
    EXPECT_EQ(row->second[2], std::to_string(seam.limit)) << "docs/architecture.md states another limit for " << seam.change;
    EXPECT_EQ(row->second[3], std::to_string(seam.goal)) << "docs/architecture.md states another goal for " << seam.change;
  }
}

}  // namespace
