// Tests of the sandbox's string.find, match, gmatch and gsub
// (engine/lua/string_patterns.cpp): the same results and errors as LuaJIT's
// own, side by side with an unrestricted LuaJIT state, on chosen and on
// random patterns; the time limit inside pathological patterns; gsub's
// result under the memory cap.

#include "lua/sandbox.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "scratch_dir.hpp"
#include "test_errors.hpp"

namespace {

namespace fs = std::filesystem;
using lc::lua::Sandbox;
using lc::lua::SandboxLimits;
using lc::lua::ScriptError;
using lc::test::ScratchDir;

// run(op, s, p, a, b) -> one line describing what string[op](s, p, a, b)
// returned or raised (every value typed), the same in any state. gmatch's
// iterator is run to its end; for gsub, a = "@fn", "@tab" or "@bad" stands
// for a function of the captures, a table with an __index function, and a
// function returning a table.
constexpr const char* kHarness = R"lua(
local function ser(...)
  local out = {tostring(select("#", ...))}
  for i = 1, select("#", ...) do
    local v = select(i, ...)
    out[#out + 1] = type(v) .. ":" .. tostring(v)
  end
  return table.concat(out, "|")
end
local function drain(it)
  local out = {}
  for _ = 1, 200 do
    local line = ser(it())
    out[#out + 1] = line
    if line == "0" or line == "1|nil:nil" then break end
  end
  return table.concat(out, ";")
end
local replacements = {
  ["@fn"] = function(...) return "<" .. ser(...) .. ">" end,
  ["@tab"] = setmetatable({a = "A", b = 7, x = false},
                          {__index = function(_, k) if k == "c" then return "C" end end}),
  ["@bad"] = function() return {} end,
}
return function(op, s, p, a, b)
  if op == "gmatch" then
    local ok, it = pcall(string.gmatch, s, p)
    if not ok then return "raised " .. it end
    return ser(pcall(drain, it))
  end
  if op == "gsub" and replacements[a] then a = replacements[a] end
  return ser(pcall(string[op], s, p, a, b))
end
)lua";

struct Nil {};
using Arg = std::variant<Nil, double, std::string, bool>;

struct Case {
  std::string op;
  Arg s, p, a = Nil{}, b = Nil{};
};

void push(lua_State* L, const Arg& v) {
  if (std::holds_alternative<double>(v)) {
    lua_pushnumber(L, std::get<double>(v));
  } else if (std::holds_alternative<std::string>(v)) {
    const auto& s = std::get<std::string>(v);
    lua_pushlstring(L, s.data(), s.size());
  } else if (std::holds_alternative<bool>(v)) {
    lua_pushboolean(L, std::get<bool>(v));
  } else {
    lua_pushnil(L);
  }
}

std::string describe(const Case& c) {
  const auto text = [](const Arg& v) -> std::string {
    if (std::holds_alternative<double>(v)) return fmt::format("{}", std::get<double>(v));
    if (std::holds_alternative<std::string>(v)) return fmt::format("{:?}", std::get<std::string>(v));
    if (std::holds_alternative<bool>(v)) return std::get<bool>(v) ? "true" : "false";
    return "nil";
  };
  return fmt::format("string.{}({}, {}, {}, {})", c.op, text(c.s), text(c.p), text(c.a), text(c.b));
}

// The harness in the sandbox (its string functions) and in a plain LuaJIT
// state (LuaJIT's own), each leaving `run` at stack index 1.
class StringPatterns : public ::testing::Test {
 protected:
  StringPatterns() : sandbox_({}, SandboxLimits{.memory_bytes = 64u << 20, .seconds = 10}), plain_(luaL_newstate()) {
    luaL_openlibs(plain_);
    for (lua_State* L : {sandbox_.state(), plain_}) {
      EXPECT_EQ(luaL_loadbuffer(L, kHarness, std::strlen(kHarness), "=harness"), 0);
      lua_call(L, 0, 1);
    }
  }
  ~StringPatterns() override { lua_close(plain_); }

  // What run(...) says in the sandbox (first) and in plain LuaJIT.
  std::pair<std::string, std::string> run(const Case& c) {
    std::pair<std::string, std::string> out;
    for (lua_State* L : {sandbox_.state(), plain_}) {
      lua_pushvalue(L, 1);
      lua_pushstring(L, c.op.c_str());
      for (const Arg* v : {&c.s, &c.p, &c.a, &c.b}) push(L, *v);
      if (L == plain_) {
        EXPECT_EQ(lua_pcall(L, 5, 1, 0), 0) << lua_tostring(L, -1);
      } else {
        sandbox_.call(5, 1);
      }
      (L == plain_ ? out.second : out.first) = lua_tostring(L, -1);
      lua_pop(L, 1);
    }
    return out;
  }

  void expect_same(const Case& c) {
    const auto [ours, luajit] = run(c);
    EXPECT_EQ(ours, luajit) << describe(c);
  }

  Sandbox sandbox_;
  lua_State* plain_;
};

// The sandbox's functions are not LuaJIT's (whose names say "builtin").
TEST_F(StringPatterns, SandboxHasItsOwnFunctions) {
  for (lua_State* L : {sandbox_.state(), plain_}) {
    for (const char* name : {"find", "match", "gmatch", "gsub"}) {
      lua_getglobal(L, "string");
      lua_getfield(L, -1, name);
      lua_getglobal(L, "tostring");
      lua_insert(L, -2);
      lua_call(L, 1, 1);
      const std::string text = lua_tostring(L, -1);
      EXPECT_EQ(text.find("builtin") == std::string::npos, L == sandbox_.state()) << name << ": " << text;
      lua_pop(L, 2);
    }
  }
  EXPECT_EQ(run({"match", std::string("key = value"), std::string("(%w+)%s*=%s*(%w+)")}).first,
            "3|boolean:true|string:key|string:value");
}

TEST_F(StringPatterns, SameAsLuaJitOnChosenCases) {
  using S = std::string;
  const std::vector<Case> cases = {
      // find: plain and pattern searches, start positions as LuaJIT converts them
      {"find", S("hello world"), S("o w")}, {"find", S("hello"), S("l+")}, {"find", S("hello"), S("xyz")},
      {"find", S(""), S("")}, {"find", S("abc"), S(""), 10.0}, {"find", S("abcabc"), S("b"), -2.0},
      {"find", S("abcabc"), S("b"), 0.0}, {"find", S("abcabc"), S("b"), 2.9}, {"find", S("abcabc"), S("b"), -100.0},
      {"find", S("abcabcabc"), S("b"), std::ldexp(1.0, 40)}, {"find", S("abcabcabc"), S("b"), std::ldexp(1.0, 32) + 3},
      {"find", S("abcabcabc"), S("b."), std::ldexp(1.0, 31)}, {"find", S("abcabc"), S("c"), NAN},
      {"find", S("abcabc"), S("c"), S("2")}, {"find", S("abcabc"), S("c"), S(" 0x2 ")},
      {"find", S("abc"), S("b"), S("x")}, {"find", S("a.b"), S("."), 1.0, true}, {"find", S("a+b"), S("+"), Nil{}, true},
      {"find", S("abc"), S("b)")}, {"find", S("a\0b", 3), S("\0", 1)}, {"find", S("a\0b", 3), S("%z")},
      {"find", S("a\0b", 3), S(".\0", 2)}, {"find", 12345.0, 34.0}, {"find", Nil{}, S("x")}, {"find", S("x"), Nil{}},
      {"find", S("hello"), S("()ll()")}, {"find", S("hello"), S("^h")}, {"find", S("hello"), S("^e")},
      // match: classes, sets, anchors, repetitions, captures
      {"match", S("key = value"), S("(%w+)%s*=%s*(%w+)")}, {"match", S("  trim  "), S("^%s*(.-)%s*$")},
      {"match", S("THE (quick) fox"), S("%((%a+)%)")}, {"match", S("f(a(b)c)d"), S("%b()")},
      {"match", S("f(a(b c)d"), S("%b()")}, {"match", S("THE quick"), S("%f[%a]%a+")},
      {"match", S("hello"), S("%f[%l]%l+$")}, {"match", S("abcabc"), S("(abc)%1")}, {"match", S("aaa"), S("a-")},
      {"match", S("aaa"), S("a-$")}, {"match", S("aaab"), S("a*b")}, {"match", S("b"), S("a+b")},
      {"match", S("ab"), S("a?b?c?")}, {"match", S("[test]"), S("%[(.*)%]")}, {"match", S("a]b"), S("[]]")},
      {"match", S("a^b"), S("[%^]")}, {"match", S("a-b"), S("[a%-]+")}, {"match", S("xa-"), S("[a-]+")},
      {"match", S("-a"), S("[-a]+")}, {"match", S("2024-01-15"), S("(%d+)-(%d+)-(%d+)")},
      {"match", S("\t\v x"), S("%s+")}, {"match", S("\xc3\xa9t\xc3\xa9"), S("%a+")}, {"match", S("\xc3\xa9t"), S("[\xc3\xa9]+")},
      {"match", S("ABCdef"), S("%u+")}, {"match", S("ABCdef"), S("%U+")}, {"match", S(" x~"), S("%g+")},
      {"match", S("a.,b"), S("%p+")}, {"match", S("0x1Fg"), S("%x+")}, {"match", S("ctrl\x01\x7f"), S("%c+")},
      {"match", S("a1_b"), S("%w+")}, {"match", S("a1_b"), S("%W")}, {"match", S("hello$"), S("o$")},
      {"match", S("a$b"), S("$b")}, {"match", S("%a"), S("%%a")}, {"match", S("x.y"), S("%.")},
      {"match", S("hello"), S("()")}, {"match", S("hello"), S("(h)(e)(l)(l)(o)")},
      {"match", S("hello"), S("((h)(e))")}, {"match", S("hello"), S("[^aeiou]+")}, {"match", S("q"), S("[%a_][%w_]*")},
      {"match", S("x"), S("[]")}, {"match", S("x"), S("[^]")}, {"match", S("a"), S("[a-]")},
      {"match", std::string(300, 'a'), S("a*a*b")}, {"match", std::string(40, 'a'), S("(a)").append(S("(a)")).append(S("(a)"))},
      // malformed patterns and bad captures
      {"match", S("x"), S("(")}, {"match", S("x"), S("%")}, {"match", S("x"), S("[a")}, {"match", S("x"), S("[%")},
      {"match", S("x"), S("(()")}, {"match", S("x"), S(")")}, {"match", S("x"), S("x)")}, {"match", S("x"), S("%b")},
      {"match", S("x"), S("%bx")}, {"match", S("x"), S("%f")}, {"match", S("x"), S("%fx")}, {"match", S("x"), S("%1")},
      {"match", S("xx"), S("(x)%2")}, {"match", S("xx"), S("(x%1)")}, {"match", S("xx"), S("()%1")},
      {"match", std::string(300, 'a'), [] { std::string p; for (int i = 0; i < 250; ++i) p += "a?"; return p; }()},
      {"match", std::string(40, 'a'), [] { std::string p; for (int i = 0; i < 33; ++i) p += "(a)"; return p; }()},
      {"match", std::string(40, 'a'), [] { std::string p; for (int i = 0; i < 32; ++i) p += "(a)"; return p; }()},
      // gmatch: empty matches, anchors (literal in gmatch), captures
      {"gmatch", S("one two  three"), S("%a+")}, {"gmatch", S("k=v, a=b"), S("(%w+)=(%w+)")},
      {"gmatch", S("abc"), S("")}, {"gmatch", S("^a^b"), S("^.")}, {"gmatch", S("abc"), S("x")},
      {"gmatch", S("aXbX"), S("()X")}, {"gmatch", S("x"), S("(")}, {"gmatch", S("abc"), S("a*")},
      {"gmatch", Nil{}, S("x")}, {"gmatch", 1234.0, 2.0},
      // gsub: every kind of replacement, counts, anchors, errors
      {"gsub", S("hello world"), S("o"), S("0")}, {"gsub", S("hello"), S(""), S("-")},
      {"gsub", S("hello world"), S("(o)"), S("[%1]")}, {"gsub", S("hello"), S("l"), S("%0%0")},
      {"gsub", S("abc"), S("b"), S("%")}, {"gsub", S("abc"), S("b"), S("%x%%")}, {"gsub", S("abc"), S("b"), S("%2")},
      {"gsub", S("abc"), S("(b)"), S("%2")}, {"gsub", S("abc"), S("()"), S("%1")}, {"gsub", S("abc"), S("%w"), S("@fn")},
      {"gsub", S("abc"), S("(%w)(%w)"), S("@fn")}, {"gsub", S("abcx"), S("%w"), S("@tab")},
      {"gsub", S("abc"), S("%w"), S("@bad")}, {"gsub", S("abc"), S("b"), true}, {"gsub", S("abc"), S("b"), Nil{}},
      {"gsub", S("abc"), S("b"), 7.0}, {"gsub", S("abcabc"), S("b"), S("x"), 0.0}, {"gsub", S("abcabc"), S("b"), S("x"), 1.0},
      {"gsub", S("abcabc"), S("b"), S("x"), -1.0}, {"gsub", S("abcabc"), S("b"), S("x"), 1.5},
      {"gsub", S("abcabc"), S("b"), S("x"), std::ldexp(1.0, 32) + 1}, {"gsub", S("abcabc"), S("c"), S("x"), std::ldexp(1.0, 31)},
      {"gsub", S("abcabc"), S("c"), S("x"), -std::ldexp(1.0, 31) - 1}, {"gsub", S("abcabc"), S("c"), S("x"), NAN},
      {"gsub", S("abcabc"), S("c"), S("x"), S("y")}, {"gsub", S("abab"), S("^ab"), S("x")}, {"gsub", S("abab"), S("^"), S("x")},
      {"gsub", 12345.0, S("%d"), 9.0}, {"gsub", S("a b  c"), S("%s*"), S("-")}, {"gsub", S("x"), S("("), S("")},
      {"gsub", S("a\0b", 3), S("%z"), S("0")}, {"gsub", S("hello"), S("l+"), S("@fn"), 1.0},
  };
  for (const auto& c : cases) expect_same(c);
}

// Random patterns over a small alphabet, malformed ones included, on short
// subjects (so no pattern backtracks for long).
TEST_F(StringPatterns, SameAsLuaJitOnRandomPatterns) {
  std::mt19937 rng(20240612);
  const std::vector<std::string> atoms = {"a", "b", "x", ".", "%a", "%d", "%s", "%w", "%p", "%x", "%z", "%A", "%%",
                                          "%(", "[ab]", "[^a]", "[a-c]", "[%]x]", "[%a%d]", "%b()", "%f[%w]",
                                          "%f[%W]", "(", ")", "()", "%1", "%2", "^", "$", "[", "%", "-", " "};
  const std::vector<std::string> repeats = {"", "", "", "*", "+", "-", "?"};
  const std::string letters = std::string("ab(). %-[]x1\0c", 14);
  const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const std::vector<std::string> ops = {"find", "match", "gmatch", "gsub"};
  for (int n = 0; n < 3000; ++n) {
    std::string s, p;
    const std::size_t slen = pick(13);
    for (std::size_t i = 0; i < slen; ++i) s += letters[pick(letters.size())];
    const std::size_t items = 1 + pick(5);
    for (std::size_t i = 0; i < items; ++i) p += atoms[pick(atoms.size())] + repeats[pick(repeats.size())];
    const std::string& op = ops[pick(ops.size())];
    Case c{op, s, p};
    if (op == "find" && pick(3) == 0) c.a = static_cast<double>(static_cast<int>(pick(17)) - 8);
    if (op == "gsub") {
      const std::vector<std::string> repl = {"<%0>", "%1", "[%2]", "%", "@fn", "@tab"};
      c.a = repl[pick(repl.size())];
      if (pick(4) == 0) c.b = static_cast<double>(pick(4));
    }
    expect_same(c);
  }
}

// The message of the ScriptError running `file` throws.
std::string script_error(Sandbox& sandbox, const fs::path& file) {
  return lc::test::error_of<ScriptError>([&] { sandbox.run_file(file, 0); });
}

// ("a*"):rep(8) .. "b" against 40 a's backtracks through ~4e8 steps (13 s
// in LuaJIT's own matcher on the machine this was written on; 60 and 60, the
// form reported, through more than the universe has time for). Each string
// function stops at the time limit, at the script's line.
TEST(StringPatternsLimits, PathologicalPatternsStopAtTheTimeLimit) {
  ScratchDir dir;
  const std::vector<std::pair<std::string, std::string>> calls = {
      {"match", "local r = s:match(p)"},
      {"find", "local r = s:find(p)"},
      {"gmatch", "for w in s:gmatch(p) do end"},
      {"gsub", "local r = s:gsub(p, '')"},
  };
  for (const auto& [name, call] : calls) {
    const fs::path file = dir / (name + ".lua");
    std::ofstream(file) << "local s = string.rep('a', 40)\nlocal p = string.rep('a*', 8) .. 'b'\n" << call << "\n";
    Sandbox sandbox({}, SandboxLimits{.seconds = 0.5, .set_by = "the test"});
    const auto t0 = std::chrono::steady_clock::now();
    const std::string msg = script_error(sandbox, file);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(msg.rfind(file.string() + ":3: time limit of 0.5 s exceeded (set by the test)", 0), 0u) << msg;
    EXPECT_LT(elapsed, 3.0) << name;
    // Once stopped, the sandbox runs the next evaluation normally.
    std::ofstream(dir / "fine.lua") << "assert(('x = 1'):match('(%w+) = (%d)') == 'x')\n";
    sandbox.run_file(dir / "fine.lua", 0);
  }
}

// gsub's result lives in the capped Lua heap; string.rep and table.concat
// are capped too (LuaJIT builds them there).
TEST(StringPatternsLimits, BuiltStringsCountAgainstTheMemoryCap) {
  ScratchDir dir;
  const std::vector<std::string> scripts = {
      "local s = string.rep('a', 1e6)\nlocal r = s:gsub('.', string.rep('x', 1000))\n",
      "local s = string.rep('a', 1e6)\nlocal r = s:gsub('.', function(c) return string.rep(c, 1000) end)\n",
      "local s = string.rep('x', 2^30)\n",
      "local s = string.rep('xy', 2^28, ', ')\n",
      "local t = {}\nfor i = 1, 2^16 do t[i] = string.rep('x', 2^10) end\nlocal s = table.concat(t, ',', 1, #t)\n"
      "local u = {} for i = 1, 64 do u[i] = s end\nlocal v = table.concat(u)\n",
  };
  for (std::size_t i = 0; i < scripts.size(); ++i) {
    const fs::path file = dir / fmt::format("bomb{}.lua", i);
    std::ofstream(file) << scripts[i];
    Sandbox sandbox({}, SandboxLimits{.memory_bytes = 32u << 20});
    const std::string msg = script_error(sandbox, file);
    EXPECT_EQ(msg.rfind(file.string() + ": memory limit of 32 MiB exceeded", 0), 0u) << msg;
  }
}

}  // namespace
