#include "lua/string_patterns.hpp"

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "lua/sandbox.hpp"

namespace lc::lua {

namespace {

constexpr int kMaxCaptures = 32;     // LUA_MAXCAPTURES
constexpr int kMaxMatchDepth = 200;  // LuaJIT's LJ_MAX_XLEVEL ("pattern too complex")
constexpr char kEsc = '%';
constexpr const char* kSpecials = "^$*+?.([%-";

// Steps of matching between two looks at the clock (~20 ns each): a step
// is one call of the matcher or one character it scans, ~1-10 ns.
constexpr std::ptrdiff_t kStepsPerPoll = 1 << 14;

constexpr std::ptrdiff_t kUnfinished = -1;  // capture length while open
constexpr std::ptrdiff_t kPosition = -2;    // capture length of a () capture

int uchar(char c) { return static_cast<unsigned char>(c); }

// LuaJIT's character classes: ASCII only, whatever the C locale.
bool is_upper(int c) { return c >= 'A' && c <= 'Z'; }
bool is_lower(int c) { return c >= 'a' && c <= 'z'; }
bool is_digit(int c) { return c >= '0' && c <= '9'; }
bool is_alpha(int c) { return is_upper(c) || is_lower(c); }
bool is_alnum(int c) { return is_alpha(c) || is_digit(c); }
bool is_graph(int c) { return c > ' ' && c < 127; }

// Whether c is in the class named by the letter `cl` (%a, %D, %z, ...);
// any other `cl` stands for itself (%., %%).
bool match_class(int c, int cl) {
  bool in = false;
  switch (cl | 0x20) {
    case 'a': in = is_alpha(c); break;
    case 'c': in = c < ' ' || c == 127; break;
    case 'd': in = is_digit(c); break;
    case 'g': in = is_graph(c); break;
    case 'l': in = is_lower(c); break;
    case 'p': in = is_graph(c) && !is_alnum(c); break;
    case 's': in = c == ' ' || (c >= '\t' && c <= '\r'); break;
    case 'u': in = is_upper(c); break;
    case 'w': in = is_alnum(c); break;
    case 'x': in = is_digit(c) || ((c | 0x20) >= 'a' && (c | 0x20) <= 'f'); break;
    default:
      if (cl == 'z') return c == 0;  // deprecated, still in LuaJIT
      if (cl == 'Z') return c != 0;
      return cl == c;
  }
  return is_lower(cl) ? in : !in;  // %A is the complement of %a
}

// Whether c is in the set [...] that runs from `p` (at '[') to `last` (at
// its ']').
bool in_set(int c, const char* p, const char* last) {
  bool listed = true;  // the answer when c is listed; false for [^...]
  if (p[1] == '^') {
    listed = false;
    ++p;
  }
  while (++p < last) {
    if (*p == kEsc) {
      ++p;
      if (match_class(c, uchar(*p))) return listed;
    } else if (p[1] == '-' && p + 2 < last) {
      p += 2;
      if (uchar(p[-2]) <= c && c <= uchar(*p)) return listed;
    } else if (uchar(*p) == c) {
      return listed;
    }
  }
  return !listed;
}

// Whether character c matches the single-character class from p to ep
// (ep: just past it).
bool single_match(int c, const char* p, const char* ep) {
  switch (*p) {
    case '.': return true;
    case kEsc: return match_class(c, uchar(p[1]));
    case '[': return in_set(c, p, ep - 1);
    default: return uchar(*p) == c;
  }
}

// LuaJIT's conversion of a number to a 32-bit argument (lj_num2int, an x86
// cvttsd2si): truncation, and INT32_MIN for what does not fit (and NaN).
std::int32_t to_int32(lua_Number n) {
  return n > -2147483649.0 && n < 2147483648.0 ? static_cast<std::int32_t>(n) : INT32_MIN;
}

// The matcher of Lua 5.1's string library, over one subject: backtracking,
// with one level of recursion per repetition tried, as LuaJIT runs it (at
// most kMaxCaptures captures, kMaxMatchDepth levels). Errors in the pattern
// are raised like LuaJIT's, at the script line calling the string function.
// Patterns end at their first '\0' (LuaJIT's do too), and subjects are Lua
// strings, so one byte past their end is a '\0' that may be read.
class Matcher {
 public:
  Matcher(lua_State* L, const char* subject, std::size_t length)
      : L_(L), begin_(subject), end_(subject + length) {}

  // Where a match of pattern `p` starting at `s` ends, or nullptr.
  const char* match_at(const char* s, const char* p) {
    level_ = 0;
    depth_ = 0;
    return match(s, p);
  }

  // Pushes the captures of the last match (or the whole match from s to e
  // if the pattern has none and s is given); returns how many.
  int push_captures(const char* s, const char* e) {
    const int n = level_ == 0 && s != nullptr ? 1 : level_;
    luaL_checkstack(L_, n, "too many captures");
    for (int i = 0; i < n; ++i) push_capture(i, s, e);
    return n;
  }

  // Pushes capture i (0-based; 0 is the whole match s..e if there are no
  // captures).
  void push_capture(int i, const char* s, const char* e) {
    if (i >= level_) {
      if (i != 0) fail("invalid capture index");
      lua_pushlstring(L_, s, static_cast<std::size_t>(e - s));
      return;
    }
    const Capture& c = captures_[i];
    if (c.len == kUnfinished) fail("unfinished capture");
    if (c.len == kPosition) {
      lua_pushinteger(L_, c.init - begin_ + 1);
    } else {
      lua_pushlstring(L_, c.init, static_cast<std::size_t>(c.len));
    }
  }

  // Counts `n` steps of work; every kStepsPerPoll steps the sandbox's clock
  // is checked (raising its time-limit error when the time is up).
  void step(std::ptrdiff_t n = 1) {
    steps_left_ -= n;
    if (steps_left_ <= 0) {
      steps_left_ = kStepsPerPoll;
      detail::check_time(L_);
    }
  }

 private:
  struct Capture {
    const char* init;
    std::ptrdiff_t len;
  };

  [[noreturn]] void fail(const char* msg) {
    luaL_error(L_, "%s", msg);
    std::abort();  // luaL_error does not return
  }

  // Just past the single-character class starting at p.
  const char* class_end(const char* p) {
    switch (*p++) {
      case kEsc:
        if (*p == '\0') fail("malformed pattern (ends with '%')");
        return p + 1;
      case '[':
        if (*p == '^') ++p;
        do {  // the first character may be a literal ']'
          if (*p == '\0') fail("malformed pattern (missing ']')");
          if (*p++ == kEsc && *p != '\0') ++p;
        } while (*p != ']');
        return p + 1;
      default:
        return p;
    }
  }

  // One level of recursion.
  const char* match(const char* s, const char* p) {
    if (++depth_ > kMaxMatchDepth) fail("pattern too complex");
    s = match_here(s, p);
    --depth_;
    return s;
  }

  // The body of match(); what LuaJIT does by a goto to its start (the tail
  // of a pattern after a single item) is a turn of the loop here, so the
  // depth counts the same.
  const char* match_here(const char* s, const char* p) {
    for (;;) {
      step();
      switch (*p) {
        case '(':
          return p[1] == ')' ? start_capture(s, p + 2, kPosition) : start_capture(s, p + 1, kUnfinished);
        case ')':
          return end_capture(s, p + 1);
        case '\0':
          return s;
        case '$':
          if (p[1] == '\0') return s == end_ ? s : nullptr;
          break;
        case kEsc:
          if (p[1] == 'b') {
            s = balance(s, p + 2);
            if (s == nullptr) return nullptr;
            p += 4;
            continue;
          }
          if (p[1] == 'f') {
            p += 2;
            if (*p != '[') fail("missing '[' after '%f' in pattern");
            const char* ep = class_end(p);
            const int previous = s == begin_ ? 0 : uchar(s[-1]);
            if (in_set(previous, p, ep - 1) || !in_set(uchar(*s), p, ep - 1)) return nullptr;
            p = ep;
            continue;
          }
          if (is_digit(uchar(p[1]))) {
            s = back_reference(s, uchar(p[1]));
            if (s == nullptr) return nullptr;
            p += 2;
            continue;
          }
          break;
        default:
          break;
      }
      // A single-character class, maybe with a repetition after it.
      const char* ep = class_end(p);
      const bool m = s < end_ && single_match(uchar(*s), p, ep);
      switch (*ep) {
        case '?':
          if (m) {
            if (const char* res = match(s + 1, ep + 1)) return res;
          }
          p = ep + 1;
          continue;
        case '*':
          return max_expand(s, p, ep);
        case '+':
          return m ? max_expand(s + 1, p, ep) : nullptr;
        case '-':
          return min_expand(s, p, ep);
        default:
          if (!m) return nullptr;
          ++s;
          p = ep;
          continue;
      }
    }
  }

  // Greedy repetition: as many as match, then fewer until the rest does.
  const char* max_expand(const char* s, const char* p, const char* ep) {
    std::ptrdiff_t i = 0;
    while (s + i < end_ && single_match(uchar(s[i]), p, ep)) {
      ++i;
      step();
    }
    for (; i >= 0; --i) {
      if (const char* res = match(s + i, ep + 1)) return res;
    }
    return nullptr;
  }

  // Lazy repetition: as few as let the rest match.
  const char* min_expand(const char* s, const char* p, const char* ep) {
    for (;;) {
      if (const char* res = match(s, ep + 1)) return res;
      if (s < end_ && single_match(uchar(*s), p, ep)) {
        ++s;
      } else {
        return nullptr;
      }
    }
  }

  // %bxy at s: just past the x...y balanced from s, or nullptr.
  const char* balance(const char* s, const char* p) {
    if (p[0] == '\0' || p[1] == '\0') fail("unbalanced pattern");
    if (*s != p[0]) return nullptr;
    int open = 1;
    while (++s < end_) {
      step();
      if (*s == p[1]) {
        if (--open == 0) return s + 1;
      } else if (*s == p[0]) {
        ++open;
      }
    }
    return nullptr;
  }

  const char* start_capture(const char* s, const char* p, std::ptrdiff_t what) {
    if (level_ >= kMaxCaptures) fail("too many captures");
    captures_[level_] = {s, what};
    ++level_;
    const char* res = match(s, p);
    if (res == nullptr) --level_;
    return res;
  }

  const char* end_capture(const char* s, const char* p) {
    int l = level_ - 1;
    while (l >= 0 && captures_[l].len != kUnfinished) --l;
    if (l < 0) fail("invalid pattern capture");
    captures_[l].len = s - captures_[l].init;
    const char* res = match(s, p);
    if (res == nullptr) captures_[l].len = kUnfinished;
    return res;
  }

  // %1-%9 at s: just past a repeat of that capture's text, or nullptr. A
  // position capture's length, cast as LuaJIT casts it, never fits.
  const char* back_reference(const char* s, int digit) {
    const int l = digit - '1';
    if (l < 0 || l >= level_ || captures_[l].len == kUnfinished) fail("invalid capture index");
    const auto len = static_cast<std::size_t>(captures_[l].len);
    if (static_cast<std::size_t>(end_ - s) < len) return nullptr;
    step(static_cast<std::ptrdiff_t>(len / 64));
    return std::memcmp(captures_[l].init, s, len) == 0 ? s + len : nullptr;
  }

  lua_State* L_;
  const char* begin_;
  const char* end_;
  int level_ = 0;  // captures, finished or not
  int depth_ = 0;
  std::ptrdiff_t steps_left_ = kStepsPerPoll;
  Capture captures_[kMaxCaptures] = {};
};

// A string built in the Lua heap (in a userdata at a fixed stack slot), so
// the memory cap applies to it and the C stack stays small.
class HeapBuffer {
 public:
  explicit HeapBuffer(lua_State* L) : L_(L) {
    lua_pushnil(L);
    slot_ = lua_gettop(L);
  }

  void add(const char* p, std::size_t n) {
    if (n > capacity_ - size_) grow(n);
    std::memcpy(data_ + size_, p, n);
    size_ += n;
  }
  void add(char c) { add(&c, 1); }

  void push() const { lua_pushlstring(L_, data_ == nullptr ? "" : data_, size_); }

 private:
  void grow(std::size_t more) {
    if (more > kMaxString - size_) luaL_error(L_, "string length overflow");
    const std::size_t capacity = std::max({size_ + more, 2 * capacity_, std::size_t{256}});
    auto* bigger = static_cast<char*>(lua_newuserdata(L_, std::min(capacity, kMaxString)));
    if (size_ != 0) std::memcpy(bigger, data_, size_);
    lua_replace(L_, slot_);
    data_ = bigger;
    capacity_ = std::min(capacity, kMaxString);
  }

  static constexpr std::size_t kMaxString = 0x7fffff00;  // LuaJIT's LJ_MAX_STR
  lua_State* L_;
  int slot_ = 0;
  char* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

// string.find (find) and string.match (!find).
int find_or_match(lua_State* L, bool find) {
  std::size_t len = 0;
  std::size_t plen = 0;
  const char* s = luaL_checklstring(L, 1, &len);
  const char* p = luaL_checklstring(L, 2, &plen);
  // LuaJIT: a 32-bit start, negative from the end, clamped to 0..len.
  const std::int64_t start = lua_isnoneornil(L, 3) ? 1 : to_int32(luaL_checknumber(L, 3));
  const std::int64_t from = std::clamp<std::int64_t>(start < 0 ? start + static_cast<std::int64_t>(len) : start - 1,
                                                     0, static_cast<std::int64_t>(len));
  if (find && (lua_toboolean(L, 4) || std::string_view(p, plen).find_first_of(kSpecials) == std::string_view::npos)) {
    // A plain search; memmem is linear in the subject's length.
    const void* at = memmem(s + from, len - static_cast<std::size_t>(from), p, plen);
    if (at == nullptr) {
      lua_pushnil(L);
      return 1;
    }
    const std::ptrdiff_t i = static_cast<const char*>(at) - s;
    lua_pushinteger(L, i + 1);
    lua_pushinteger(L, i + static_cast<std::ptrdiff_t>(plen));
    return 2;
  }
  const bool anchored = *p == '^';
  if (anchored) ++p;
  Matcher m(L, s, len);
  const char* at = s + from;
  do {
    if (const char* e = m.match_at(at, p)) {
      if (!find) return m.push_captures(at, e);
      lua_pushinteger(L, at - s + 1);
      lua_pushinteger(L, e - s);
      return m.push_captures(nullptr, nullptr) + 2;
    }
  } while (at++ < s + len && !anchored);
  lua_pushnil(L);
  return 1;
}

int find(lua_State* L) { return find_or_match(L, true); }
int match(lua_State* L) { return find_or_match(L, false); }

// The iterator gmatch returns; upvalues: subject, pattern, where to go on.
// After an empty match it goes on one character further (LuaJIT's rule).
int gmatch_next(lua_State* L) {
  std::size_t len = 0;
  const char* s = lua_tolstring(L, lua_upvalueindex(1), &len);
  const char* p = lua_tostring(L, lua_upvalueindex(2));
  const auto pos = static_cast<std::size_t>(lua_tointeger(L, lua_upvalueindex(3)));
  Matcher m(L, s, len);
  for (const char* at = s + std::min(pos, len + 1); at <= s + len; ++at) {
    if (const char* e = m.match_at(at, p)) {
      lua_pushinteger(L, (e - s) + (e == at ? 1 : 0));
      lua_replace(L, lua_upvalueindex(3));
      return m.push_captures(at, e);
    }
  }
  return 0;
}

int gmatch(lua_State* L) {
  luaL_checkstring(L, 1);  // numbers become strings in place
  luaL_checkstring(L, 2);
  lua_settop(L, 2);
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, &gmatch_next, 3);
  return 1;
}

// Appends to `out` the replacement string at index 3 for the match s..e:
// %0 is the match, %1-%9 captures, '%' before anything else that thing
// (before the end of the string, a '\0', as in LuaJIT).
void add_expansion(lua_State* L, Matcher& m, HeapBuffer& out, const char* s, const char* e) {
  std::size_t len = 0;
  const char* r = lua_tolstring(L, 3, &len);
  for (std::size_t i = 0; i < len; ++i) {
    m.step();
    if (r[i] != kEsc) {
      out.add(r[i]);
      continue;
    }
    const int c = uchar(r[++i]);
    if (!is_digit(c)) {
      out.add(r[i]);
    } else if (c == '0') {
      out.add(s, static_cast<std::size_t>(e - s));
    } else {
      m.push_capture(c - '1', s, e);
      std::size_t n = 0;
      const char* text = lua_tolstring(L, -1, &n);
      out.add(text, n);
      lua_pop(L, 1);
    }
  }
}

// Appends to `out` the replacement for the match s..e made by the value at
// index 3 (a string or number, a function of the captures, or a table
// indexed by the first capture); false or nil keep the match.
void add_replacement(lua_State* L, Matcher& m, HeapBuffer& out, const char* s, const char* e) {
  switch (lua_type(L, 3)) {
    case LUA_TFUNCTION: {
      const detail::NestedCall nested(L);
      lua_pushvalue(L, 3);
      const int n = m.push_captures(s, e);
      lua_call(L, n, 1);
      break;
    }
    case LUA_TTABLE: {
      const detail::NestedCall nested(L);  // __index may be a function
      m.push_capture(0, s, e);
      lua_gettable(L, 3);
      break;
    }
    default:
      add_expansion(L, m, out, s, e);
      return;
  }
  if (!lua_toboolean(L, -1)) {
    out.add(s, static_cast<std::size_t>(e - s));
  } else if (!lua_isstring(L, -1)) {
    luaL_error(L, "invalid replacement value (a %s)", luaL_typename(L, -1));
  } else {
    std::size_t n = 0;
    const char* text = lua_tolstring(L, -1, &n);
    out.add(text, n);
  }
  lua_pop(L, 1);
}

// string.gsub(s, pattern, replacement [, n]) -> result, number of matches
// replaced.
int gsub(lua_State* L) {
  std::size_t len = 0;
  const char* src = luaL_checklstring(L, 1, &len);
  const char* p = luaL_checkstring(L, 2);
  const int type = lua_type(L, 3);
  // As LuaJIT: luaL_optint, i.e. the low 32 bits of a 64-bit conversion.
  const auto max_n = static_cast<int>(luaL_optinteger(L, 4, static_cast<lua_Integer>(len + 1)));
  if (type != LUA_TNUMBER && type != LUA_TSTRING && type != LUA_TFUNCTION && type != LUA_TTABLE) {
    luaL_argerror(L, 3, "string/function/table expected");
  }
  const bool anchored = *p == '^';
  if (anchored) ++p;
  HeapBuffer out(L);
  Matcher m(L, src, len);
  const char* s = src;
  const char* end = src + len;
  int n = 0;
  while (n < max_n) {
    const char* e = m.match_at(s, p);
    if (e != nullptr) {
      ++n;
      add_replacement(L, m, out, s, e);
    }
    if (e != nullptr && e > s) {
      s = e;
    } else if (s < end) {
      out.add(*s++);
    } else {
      break;
    }
    if (anchored) break;
  }
  out.add(s, static_cast<std::size_t>(end - s));
  out.push();
  lua_pushinteger(L, n);
  return 2;
}

}  // namespace

void install_string_patterns(lua_State* L) {
  lua_getglobal(L, LUA_STRLIBNAME);
  const luaL_Reg functions[] = {
      {"find", &find}, {"match", &match}, {"gmatch", &gmatch}, {"gsub", &gsub}, {nullptr, nullptr}};
  for (const luaL_Reg* f = functions; f->name != nullptr; ++f) {
    lua_pushcfunction(L, f->func);
    lua_setfield(L, -2, f->name);
  }
  lua_pop(L, 1);
}

}  // namespace lc::lua
