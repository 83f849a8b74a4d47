// Every relative link of the user guide (README.md and docs/*.md) leads
// somewhere: the file exists, and a #fragment names a heading of the
// Markdown file it points into, by GitHub's rule for heading anchors.  A
// renamed heading or a moved file then fails here, naming the file and
// line of each link it broke, instead of leaving a reader at the top of a
// page (or at GitHub's 404).

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

// A file's lines with what Markdown does not read as links or headings
// blanked out: fenced code blocks (a "# comment" in a shell block is no
// heading) and inline code spans.  Line numbers stay as in the file.
std::vector<std::string> prose_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  std::string line;
  bool fenced = false;
  static const std::regex code_span("`[^`]*`");
  while (std::getline(in, line)) {
    const bool fence = line.rfind("```", 0) == 0 || line.rfind("~~~", 0) == 0;
    if (fence) fenced = !fenced;
    out.push_back(fence || fenced ? "" : std::regex_replace(line, code_span, "x"));
  }
  return out;
}

// The code point at s[k] (UTF-8) and its length in bytes.  Assumes valid
// UTF-8 (the docs are).
std::pair<char32_t, int> code_point(const std::string& s, std::size_t k) {
  const auto b = static_cast<unsigned char>(s[k]);
  const int n = b < 0x80 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : 4;
  char32_t c = n == 1 ? b : b & (0x7F >> n);
  for (int m = 1; m < n && k + static_cast<std::size_t>(m) < s.size(); ++m)
    c = (c << 6) | (static_cast<unsigned char>(s[k + static_cast<std::size_t>(m)]) & 0x3F);
  return {c, n};
}

// GitHub's anchor of a heading whose rendered text is `text`
// (github-slugger): lowercased, every punctuation mark and symbol dropped
// except '-' and '_', each space a '-'.  Beyond ASCII, letters of the
// Latin-1, Latin Extended and Greek blocks are kept (capitals lowered) and
// everything else is taken as punctuation or a symbol (dashes, '…', '∂',
// '×'): the docs' headings hold nothing else.
std::string github_anchor(const std::string& text) {
  std::string out;
  for (std::size_t k = 0; k < text.size();) {
    const auto [c, n] = code_point(text, k);
    if (c < 0x80) {
      const char a = static_cast<char>(c);
      if (std::isalnum(static_cast<unsigned char>(a)) || a == '-' || a == '_') out += static_cast<char>(std::tolower(a));
      else if (a == ' ') out += '-';
    } else {
      const bool latin = c >= 0xC0 && c <= 0x24F && c != 0xD7 && c != 0xF7;
      const bool greek = c >= 0x386 && c <= 0x3FF;
      if (latin || greek) {
        const bool capital = (c >= 0xC0 && c <= 0xDE) || (c >= 0x391 && c <= 0x3AB);
        // Re-encode the (lowered) two-byte code point.
        const char32_t l = capital ? c + 0x20 : c;
        out += static_cast<char>(0xC0 | (l >> 6));
        out += static_cast<char>(0x80 | (l & 0x3F));
      }
    }
    k += static_cast<std::size_t>(n);
  }
  return out;
}

// The anchors of a Markdown file's headings ("# ..." to "###### ..."),
// with GitHub's "-1", "-2" for a repeated one.  A heading's rendered text
// is its source without the code spans' backticks and with each link
// replaced by its text.
std::set<std::string> anchors_of(const fs::path& file) {
  std::ifstream in(file);
  std::set<std::string> out;
  std::map<std::string, int> seen;
  std::string line;
  bool fenced = false;
  static const std::regex heading(R"(^#{1,6}\s+(.*?)\s*#*\s*$)");
  static const std::regex link(R"(!?\[([^\]]*)\]\([^)]*\))");
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0 || line.rfind("~~~", 0) == 0) fenced = !fenced;
    std::smatch m;
    if (fenced || !std::regex_match(line, m, heading)) continue;
    std::string text = std::regex_replace(m[1].str(), link, "$1");
    std::erase(text, '`');
    const std::string base = github_anchor(text);
    const int repeat = seen[base]++;
    out.insert(repeat == 0 ? base : base + "-" + std::to_string(repeat));
  }
  return out;
}

struct Link {
  fs::path file;  // where it is written
  int line;
  std::string target;  // as written between the parentheses
};

// The inline links and images ([text](target), ![alt](target)) of a file
// whose target is not a URL (http:, https:, mailto:).
std::vector<Link> relative_links(const fs::path& file) {
  static const std::regex target(R"(\]\(([^)\s]+)(\s+"[^"]*")?\))");
  static const std::regex url("^[a-z]+:");
  std::vector<Link> out;
  const std::vector<std::string> lines = prose_lines(file);
  for (std::size_t n = 0; n < lines.size(); ++n)
    for (std::sregex_iterator it(lines[n].begin(), lines[n].end(), target), end; it != end; ++it)
      if (!std::regex_search((*it)[1].str(), url)) out.push_back({file, static_cast<int>(n + 1), (*it)[1]});
  return out;
}

// The user guide: README.md and every docs/*.md.
std::vector<fs::path> guide_files() {
  const fs::path source = LIGHTCONE_SOURCE_DIR;
  std::vector<fs::path> out{source / "README.md"};
  for (const auto& e : fs::directory_iterator(source / "docs"))
    if (e.is_regular_file() && e.path().extension() == ".md") out.push_back(e.path());
  return out;
}

// "" if the link resolves, else what is wrong with it.
std::string broken(const Link& l, std::map<fs::path, std::set<std::string>>& anchors) {
  const std::size_t hash = l.target.find('#');
  const std::string path = l.target.substr(0, hash);
  const fs::path into = path.empty() ? l.file : (l.file.parent_path() / path).lexically_normal();
  if (!fs::exists(into)) return "no such file " + into.string();
  if (hash == std::string::npos) return "";
  const std::string fragment = l.target.substr(hash + 1);
  if (into.extension() != ".md") return "a #fragment into a file that is not Markdown";
  if (!anchors.contains(into)) anchors[into] = anchors_of(into);
  if (!anchors[into].contains(fragment)) return "no heading of " + into.filename().string() + " has the anchor #" + fragment;
  return "";
}

}  // namespace

TEST(DocsLinks, AnchorsFollowGitHubsRule) {
  EXPECT_EQ(github_anchor("lightcone render SHOT.lua --out DIR [options]"), "lightcone-render-shotlua---out-dir-options");
  EXPECT_EQ(github_anchor("The sandbox's limits"), "the-sandboxs-limits");
  EXPECT_EQ(github_anchor("lc.seconds and lc.frames_to_seconds"), "lcseconds-and-lcframes_to_seconds");
  EXPECT_EQ(github_anchor("To add …"), "to-add-");
  EXPECT_EQ(github_anchor("1. Baseline: Hamiltonian Kerr–Schild + Dormand–Prince 5(4) (2026-11-22)"),
            "1-baseline-hamiltonian-kerrschild--dormandprince-54-2026-11-22");
  EXPECT_EQ(github_anchor("Müller's Σ"), "müllers-σ");
}

TEST(DocsLinks, EveryRelativeLinkAndAnchorOfTheGuideResolves) {
  std::map<fs::path, std::set<std::string>> anchors;
  int links = 0;
  std::ostringstream errors;
  for (const fs::path& file : guide_files())
    for (const Link& l : relative_links(file)) {
      ++links;
      if (const std::string why = broken(l, anchors); !why.empty())
        errors << fs::relative(l.file, LIGHTCONE_SOURCE_DIR).string() << ":" << l.line << ": (" << l.target << "): " << why
               << "\n";
    }
  EXPECT_GT(links, 100) << "the guide's links were not found (has the link syntax changed?)";
  EXPECT_EQ(errors.str(), "");
}
