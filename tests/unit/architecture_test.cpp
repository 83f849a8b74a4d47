// The folders' layering (docs/architecture.md#folders): an engine folder
// includes only folders below it, so the include graph has no cycles and a
// folder can be read knowing only what is under it.  The test reads the
// sources' #include lines, so a new include that breaks the order fails here
// naming the file and the line.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

// Bottom to top; a folder may include its own level's folder and those of
// the levels below.  Folders on one level must not include each other.
const std::vector<std::vector<std::string>> engine_levels = {
    {"core"},
    {"light"},
    {"lua", "image", "spacetime", "stars"},
    {"eye"},
    {"geodesic"},
    {"worldline"},
    {"assets"},
    {"camera", "sky", "objects", "observers"},
    {"scene"},
    {"render", "script"},
};

struct Include {
  fs::path file;
  int line;
  std::string target;  // as written between the quotes
};

// Every #include "..." of the .hpp and .cpp files under dir.
std::vector<Include> includes_under(const fs::path& dir) {
  static const std::regex quoted(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<Include> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const auto ext = e.path().extension();
    if (!e.is_regular_file() || (ext != ".hpp" && ext != ".cpp")) continue;
    std::ifstream in(e.path());
    std::string text;
    for (int n = 1; std::getline(in, text); ++n) {
      std::smatch m;
      if (std::regex_search(text, m, quoted)) out.push_back({e.path(), n, m[1]});
    }
  }
  return out;
}

std::string top_folder(const fs::path& p) { return p.begin()->string(); }

// One message per include under dir that breaks levels (a folder includes
// only its own folder and the folders of lower levels) and per folder that
// has no level; `tree` ("engine", "pipeline") names dir in the messages.
// Includes of files outside dir's folders (another tree, the standard
// library, generated headers) are not its business.
std::vector<std::string> level_violations(const fs::path& dir, const std::vector<std::vector<std::string>>& levels,
                                          const std::string& tree) {
  std::map<std::string, int> level;
  for (int l = 0; l < static_cast<int>(levels.size()); ++l)
    for (const auto& f : levels[l]) level[f] = l;
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() && !level.count(name))
      out.push_back(tree + "/" + name + " has no level: add it to " + tree + "_levels and to docs/architecture.md");
    const auto ext = e.path().extension();
    if (e.is_regular_file() && (ext == ".hpp" || ext == ".cpp"))
      out.push_back(tree + "/" + name + " lies outside every folder: each source lives in a folder with a level");
  }
  for (const Include& inc : includes_under(dir)) {
    const std::string from = top_folder(fs::relative(inc.file, dir));
    const std::string to = top_folder(fs::path(inc.target));
    if (to == from || !level.count(to) || !level.count(from) || level[to] < level[from]) continue;
    const std::string file = fs::relative(inc.file, dir).string();
    out.push_back(file + ":" + std::to_string(inc.line) + " includes " + inc.target + ": " + tree + "/" + from +
                  " must not include " + tree + "/" + to + " (docs/architecture.md#folders)");
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Architecture, EngineFoldersIncludeOnlyTheFoldersBelowThem) {
  for (const std::string& v : level_violations(fs::path(LIGHTCONE_SOURCE_DIR) / "engine", engine_levels, "engine"))
    ADD_FAILURE() << v;
}

// The pipeline by concern: storage at the bottom, the readers of storage
// (telemetry, video, the monitor) above it, then what a job is, how its work
// is handed out, the stages done to a frame, where the work runs (threads,
// MPI) and the commands on top.
const std::vector<std::vector<std::string>> pipeline_levels = {
    {"store"}, {"telemetry", "video", "monitor"}, {"job"}, {"schedule"}, {"stages"}, {"transport"}, {"cli"},
};

TEST(Architecture, PipelineFoldersIncludeOnlyTheFoldersBelowThem) {
  for (const std::string& v : level_violations(fs::path(LIGHTCONE_SOURCE_DIR) / "pipeline", pipeline_levels, "pipeline"))
    ADD_FAILURE() << v;
}

// The check itself, on a fixture tree with deliberate violations
// (tests/unit/architecture_fixture/): each is found, named by file and
// line, and nothing allowed is.
TEST(Architecture, TheLevelCheckCatchesEveryKindOfViolation) {
  const fs::path fixture = fs::path(LIGHTCONE_SOURCE_DIR) / "tests/unit/architecture_fixture";
  EXPECT_EQ(level_violations(fixture / "pipeline", pipeline_levels, "pipeline"), (std::vector<std::string>{
                          "pipeline/farm has no level: add it to pipeline_levels and to docs/architecture.md",
                          "pipeline/loose.hpp lies outside every folder: each source lives in a folder with a level",
                          "store/bad.hpp:3 includes cli/some_command.hpp: pipeline/store must not include pipeline/cli "
                          "(docs/architecture.md#folders)",
                          "video/reader.hpp:5 includes job/job.hpp: pipeline/video must not include pipeline/job "
                          "(docs/architecture.md#folders)",
                      }));
  EXPECT_EQ(level_violations(fixture / "engine", engine_levels, "engine"), (std::vector<std::string>{"core/bad.hpp:3 includes render/x.hpp: engine/core must not include "
                                              "engine/render (docs/architecture.md#folders)"}));
}

// docs/architecture.md names every engine and pipeline folder.
TEST(Architecture, DocsNameEveryFolder) {
  std::ifstream in(std::string(LIGHTCONE_SOURCE_DIR) + "/docs/architecture.md");
  ASSERT_TRUE(in) << "docs/architecture.md";
  std::stringstream text;
  text << in.rdbuf();
  for (const auto& l : engine_levels) {
    for (const auto& f : l)
      EXPECT_NE(text.str().find("`engine/" + f + "/`"), std::string::npos) << "docs/architecture.md lacks engine/" << f;
  }
  for (const auto& l : pipeline_levels)
    for (const auto& f : l)
      EXPECT_NE(text.str().find("`pipeline/" + f + "/`"), std::string::npos)
          << "docs/architecture.md lacks pipeline/" << f;
}

// docs/architecture.md's table of the sample's path names, for each stage,
// files that exist (a renamed or removed stage file fails here), and the
// stages the path has; what each file may include is the folder order
// above.
TEST(Architecture, TheSamplePathTableNamesTheStageFiles) {
  const fs::path root(LIGHTCONE_SOURCE_DIR);
  std::ifstream in(root / "docs/architecture.md");
  ASSERT_TRUE(in) << "docs/architecture.md";
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::size_t from = doc.find("### The path of a sample");
  ASSERT_NE(from, std::string::npos) << "docs/architecture.md lacks the section 'The path of a sample'";
  // The table: from its header row to the blank line after it.
  const std::size_t head = doc.find("\n| stage |", from);
  ASSERT_NE(head, std::string::npos) << "the section 'The path of a sample' has no table of stages";
  const std::string section = doc.substr(head, doc.find("\n\n", head) - head);
  std::set<std::string> stages;
  static const std::regex row(R"(\n\| (\w+) \| ([^|]+) \|)");
  static const std::regex file(R"(`((?:core|light|lua|image|stars|spacetime|eye|geodesic|worldline|assets|camera|sky|objects|observers|scene|render|script)/[\w/]+\.[ch]pp)`)");
  for (auto r = std::sregex_iterator(section.begin(), section.end(), row); r != std::sregex_iterator(); ++r) {
    const std::string stage = (*r)[1], files = (*r)[2];
    if (stage == "stage") continue;  // the header
    stages.insert(stage);
    int named = 0;
    for (auto f = std::sregex_iterator(files.begin(), files.end(), file); f != std::sregex_iterator(); ++f, ++named)
      EXPECT_TRUE(fs::exists(root / "engine" / (*f)[1].str())) << "stage " << stage << ": engine/" << (*f)[1] << " does not exist";
    EXPECT_GT(named, 0) << "stage " << stage << " names no file";
  }
  for (const char* s : {"plan", "recall", "generate", "trace", "shade", "keep", "reconstruct"})
    EXPECT_TRUE(stages.count(s)) << "the sample-path table has no stage '" << s << "'";
}

// Engine code is named for what it is: a header named like a test
// (*_test.hpp) is taken for one (objects/ had sphere_test.hpp and
// step_test.hpp, the sphere's intersection and the step objects query).
TEST(Architecture, NoEngineOrPipelineFileIsNamedLikeATest) {
  for (const char* dir : {"engine", "pipeline"})
    for (const auto& e : fs::recursive_directory_iterator(fs::path(LIGHTCONE_SOURCE_DIR) / dir)) {
      const std::string stem = e.path().stem().string();
      EXPECT_FALSE(e.is_regular_file() && (stem.ends_with("_test") || stem.starts_with("test_")) &&
                   e.path().filename() != "test_pause.hpp" && e.path().filename() != "test_pause.cpp")
          << e.path() << " is engine or pipeline code with a test's name";
    }
}

// The test hook is read in one place: pipeline/job/test_pause.cpp, the
// only file of engine/ and pipeline/ that names a LIGHTCONE_TEST_ variable
// in code (comments aside), and docs/architecture.md says so.
TEST(Architecture, TheTestHookIsReadInOnePlace) {
  static const std::regex test_variable(R"re("LIGHTCONE_TEST_\w*")re");
  for (const char* dir : {"engine", "pipeline"})
    for (const auto& e : fs::recursive_directory_iterator(fs::path(LIGHTCONE_SOURCE_DIR) / dir)) {
      const auto ext = e.path().extension();
      if (!e.is_regular_file() || (ext != ".hpp" && ext != ".cpp")) continue;
      std::ifstream in(e.path());
      std::string text;
      for (int n = 1; std::getline(in, text); ++n) {
        const auto comment = text.find("//");
        if (std::regex_search(text.substr(0, comment), test_variable)) {
          EXPECT_EQ(e.path().filename(), "test_pause.hpp")
              << e.path() << ":" << n << " names a test variable outside pipeline/job/test_pause.hpp";
        }
      }
    }
  std::ifstream in(std::string(LIGHTCONE_SOURCE_DIR) + "/docs/architecture.md");
  std::stringstream doc;
  doc << in.rdbuf();
  EXPECT_NE(doc.str().find("pipeline/job/test_pause"), std::string::npos)
      << "docs/architecture.md does not say where the test hook lives";
}

// Every file a source includes, directly or not, resolved against its own
// folder, engine/ and pipeline/ (the include paths).
std::set<fs::path> included_by(const fs::path& file) {
  static const std::regex quoted(R"re(^\s*#\s*include\s*"([^"]+)")re");
  const fs::path root(LIGHTCONE_SOURCE_DIR);
  std::set<fs::path> seen;
  std::vector<fs::path> todo{file};
  while (!todo.empty()) {
    const fs::path f = todo.back();
    todo.pop_back();
    std::ifstream in(f);
    std::string text;
    while (std::getline(in, text)) {
      std::smatch m;
      if (!std::regex_search(text, m, quoted)) continue;
      for (const fs::path& dir : {f.parent_path(), root / "engine", root / "pipeline"}) {
        const fs::path p = (dir / std::string(m[1])).lexically_normal();
        if (!fs::exists(p)) continue;
        if (seen.insert(p).second) todo.push_back(p);
        break;
      }
    }
  }
  return seen;
}

// A new kind should not rebuild the farm's queue, budget, messages and
// loops: their headers include no registry (docs/architecture.md, "What a
// new kind rebuilds").
TEST(Architecture, TheFarmsLoopsIncludeNoRegistry) {
  const fs::path root(LIGHTCONE_SOURCE_DIR);
  for (const char* header : {"schedule/work_queue.hpp", "stages/memo_budget.hpp", "stages/stripe_renderer.hpp",
                             "job/test_pause.hpp", "stages/pausing_stripe_renderer.hpp", "transport/local_farm.hpp", "transport/mpi_worker.hpp",
                             "transport/mpi_messages.hpp", "telemetry/progress.hpp", "schedule/farm_run.hpp"}) {
    const std::set<fs::path> in = included_by(root / "pipeline" / header);
    for (const char* registry : {"spacetime/spacetime.hpp", "camera/camera_params.hpp", "camera/camera_registry.hpp",
                                 "sky/sky.hpp", "objects/object_params.hpp", "objects/objects.hpp",
                                 "observers/observers.hpp"})
      EXPECT_EQ(in.count((root / "engine" / registry).lexically_normal()), 0u)
          << "pipeline/" << header << " includes engine/" << registry << ", so adding a kind rebuilds it";
  }
}

}  // namespace
