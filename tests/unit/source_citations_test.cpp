// Every project file a comment or a doc cites exists: a comment that says
// "see render/pixel_rows.hpp" or a doc that points at
// "pipeline/store/journal.cpp" stays true when files move (docs/architecture.md,
// "Conventions the code relies on").  The test reads comments (after // or inside /* */ in C++,
// after # in shell, Python and CMake, after -- in Lua) and the whole text of
// the docs, and checks each path whose first folder is one of the project's
// own folders.

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

const fs::path root = LIGHTCONE_SOURCE_DIR;

// Folders whose files are cited relative to them (besides the root and the
// citing file's own folder).
const std::vector<fs::path> cite_bases = {root, root / "engine", root / "pipeline", root / "tests"};

// Cited files the build makes, with where they come from.
const std::set<std::string> generated = {
    "pipeline/monitor/page.h",  // from page.html, by pipeline/CMakeLists.txt
    "monitor/page.h",
};

enum class CommentStyle { cpp, hash, lua, prose, none };

// Reads a file's name and says where its comments are.
CommentStyle style_of(const fs::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".hpp" || ext == ".cpp" || ext == ".h") return CommentStyle::cpp;
  if (ext == ".sh" || ext == ".py" || ext == ".cmake" || p.filename() == "CMakeLists.txt") return CommentStyle::hash;
  if (ext == ".lua") return CommentStyle::lua;
  if (ext == ".md") return CommentStyle::prose;
  return CommentStyle::none;
}

// Walks the source tree's files, leaving out build folders (those with a
// CMakeCache.txt), hidden folders and renders' output.
std::vector<fs::path> source_files() {
  std::vector<fs::path> out;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path& p = it->path();
    if (it->is_directory()) {
      const std::string name = p.filename().string();
      if (name.starts_with(".") || name == "out" || fs::exists(p / "CMakeCache.txt")) it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && style_of(p) != CommentStyle::none) out.push_back(p);
  }
  return out;
}

// The comment text of one line, given whether a /* */ comment is open
// before it (updated).  Approximate on purpose: a "//" inside a string
// counts as a comment, which only makes the test stricter.
std::string comment_text(const std::string& line, CommentStyle style, bool& in_block) {
  switch (style) {
    case CommentStyle::prose: return line;
    case CommentStyle::none: return {};
    case CommentStyle::lua: {
      const auto at = line.find("--");
      return at == std::string::npos ? std::string{} : line.substr(at + 2);
    }
    case CommentStyle::hash: {
      const auto at = line.find('#');
      return at == std::string::npos ? std::string{} : line.substr(at + 1);
    }
    case CommentStyle::cpp: {
      std::string out;
      std::size_t i = 0;
      while (i < line.size()) {
        if (in_block) {
          const auto end = line.find("*/", i);
          out += line.substr(i, end == std::string::npos ? std::string::npos : end - i);
          if (end == std::string::npos) return out;
          in_block = false;
          i = end + 2;
          continue;
        }
        const auto slash = line.find("//", i);
        const auto block = line.find("/*", i);
        if (slash != std::string::npos && (block == std::string::npos || slash < block))
          return out + " " + line.substr(slash + 2);
        if (block == std::string::npos) return out;
        in_block = true;
        i = block + 2;
      }
      return out;
    }
  }
  return {};
}

// The names of the folders a citation may start with: the top folders of
// the tree and the folders of engine/, pipeline/ and tests/.
std::set<std::string> project_folders() {
  std::set<std::string> out;
  for (const fs::path& base : cite_bases)
    for (const auto& e : fs::directory_iterator(base))
      if (e.is_directory() && !e.path().filename().string().starts_with(".") &&
          !fs::exists(e.path() / "CMakeCache.txt"))
        out.insert(e.path().filename().string());
  out.erase("build");
  out.erase("out");
  return out;
}

// Does `cited` name a file relative to one of the bases or to the citing
// file's folder and its parents?
bool resolves(const std::string& cited, const fs::path& citing) {
  for (const fs::path& base : cite_bases)
    if (fs::exists(base / cited)) return true;
  for (fs::path dir = citing.parent_path(); dir.string().size() >= root.string().size(); dir = dir.parent_path()) {
    if (fs::exists(dir / cited)) return true;
    if (dir == dir.parent_path()) break;
  }
  return false;
}

TEST(SourceCitations, EveryProjectFileACommentOrADocCitesExists) {
  // A path of folders and a file with an extension the project writes; not
  // part of a longer path or a variable ($SRC/docs/x.md is the test's own).
  static const std::regex cited(R"re((?:^|[^\w./$-])(([\w-]+)/(?:[\w.-]+/)*[\w-]+\.(?:hpp|cpp|md|lua|sh|py|html|cmake)))re");
  const std::set<std::string> folders = project_folders();
  int checked = 0;
  for (const fs::path& file : source_files()) {
    std::ifstream in(file);
    const CommentStyle style = style_of(file);
    bool in_block = false;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      if (style == CommentStyle::cpp && line.find("#include") != std::string::npos) continue;
      const std::string text = comment_text(line, style, in_block);
      for (std::sregex_iterator m(text.begin(), text.end(), cited), end; m != end; ++m) {
        const std::string path = (*m)[1];
        if (!folders.count((*m)[2]) || generated.count(path)) continue;
        ++checked;
        EXPECT_TRUE(resolves(path, file)) << fs::relative(file, root).string() << ":" << n << " cites " << path
                                          << ", which does not exist (moved or renamed?)";
      }
    }
  }
  EXPECT_GT(checked, 500) << "the test found too few citations to be reading the tree";
}

}  // namespace
