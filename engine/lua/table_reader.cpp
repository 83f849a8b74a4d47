#include "lua/table_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <utility>

namespace lc::lua {

namespace {

// Restores the stack top on every exit, including a thrown FieldError.
class StackGuard {
 public:
  explicit StackGuard(lua_State* L) : L_(L), top_(lua_gettop(L)) {}
  ~StackGuard() { lua_settop(L_, top_); }
  StackGuard(const StackGuard&) = delete;
  StackGuard& operator=(const StackGuard&) = delete;

 private:
  lua_State* L_;
  int top_;
};

// A value as an author would recognise it in a message: `string "1"`,
// `number 2.5`, `boolean true`, or just the type for tables and functions.
std::string describe(lua_State* L, int index) {
  switch (lua_type(L, index)) {
    case LUA_TSTRING: {
      std::size_t len = 0;
      const char* p = lua_tolstring(L, index, &len);
      constexpr std::size_t kShown = 40;
      std::string text(p, std::min(len, kShown));
      return fmt::format("string {:?}{}", text, len > kShown ? "..." : "");
    }
    case LUA_TNUMBER:
      return fmt::format("number {}", lua_tonumber(L, index));
    case LUA_TBOOLEAN:
      return lua_toboolean(L, index) != 0 ? "boolean true" : "boolean false";
    default:
      return luaL_typename(L, index);
  }
}

// Keys longer than this are never suggested nor compared (the distance
// table is quadratic), and are shortened in messages: a script's table may
// have a key of any length.
constexpr std::size_t kLongestKey = 64;

// How many __index tables deep refuse_inherited looks (a chain may loop).
constexpr int kMaxInheritance = 100;

// `key` as a message quotes it.
std::string shown_key(std::string_view key) {
  return key.size() <= kLongestKey ? std::string(key) : fmt::format("{}...", key.substr(0, kLongestKey));
}

// Optimal-string-alignment distance (Levenshtein plus adjacent swaps).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::size_t> d((n + 1) * (m + 1));
  auto at = [m, &d](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
  for (std::size_t i = 0; i <= n; ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= m; ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
      }
    }
  }
  return at(n, m);
}

}  // namespace

std::string nearest(std::string_view word, std::span<const std::string> candidates) {
  // Ranks: 1 + distance for a near spelling, kPrefixRank + the characters
  // of the shorter word past the common prefix for a shared beginning; 0
  // for no likeness.
  constexpr std::size_t kPrefixRank = 10;
  const auto rank = [word](std::string_view candidate) -> std::size_t {
    if (word.size() > kLongestKey || candidate.size() > kLongestKey) return 0;
    const std::size_t shorter = std::min(word.size(), candidate.size());
    // Short words are within distance 1 of too many unrelated names (and
    // 'inner' is 2 from 'outer').
    const std::size_t limit = shorter >= 6 ? 2 : shorter >= 3 ? 1 : 0;
    const std::size_t distance = edit_distance(word, candidate);
    if (distance == 0) return 0;
    if (distance <= limit) return 1 + distance;
    const auto [w, c] = std::mismatch(word.begin(), word.end(), candidate.begin(), candidate.end());
    const auto prefix = static_cast<std::size_t>(w - word.begin());
    if (prefix >= 4 && prefix + 1 >= shorter) return kPrefixRank + (shorter - prefix);
    return 0;
  };
  std::size_t best_rank = 0;
  const std::string* best = nullptr;
  for (const auto& candidate : candidates) {
    const std::size_t r = rank(candidate);
    if (r != 0 && (best == nullptr || r < best_rank)) {
      best_rank = r;
      best = &candidate;
    }
  }
  return best != nullptr ? *best : std::string();
}

// Where a value came from: a field (key) or an array element (index > 0).
struct TableReader::Slot {
  std::string_view key;
  std::size_t index = 0;

  std::string label() const {
    return index != 0 ? fmt::format("element [{}]", index) : fmt::format("field '{}'", key);
  }
  std::string child_context(const std::string& context) const {
    return index != 0 ? fmt::format("{}[{}]", context, index) : fmt::format("{}.{}", context, key);
  }
};

TableReader::TableReader(lua_State* L, int index, std::string context)
    : L_(L), context_(std::move(context)) {
  if (lua_type(L, index) != LUA_TTABLE) {
    throw FieldError(fmt::format("{}: expected a table, got {}", context_, describe(L, index)));
  }
  lua_pushvalue(L, index);
  ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
}

TableReader::~TableReader() {
  if (L_ != nullptr && ref_ != LUA_NOREF) luaL_unref(L_, LUA_REGISTRYINDEX, ref_);
}

TableReader::TableReader(TableReader&& other) noexcept
    : L_(std::exchange(other.L_, nullptr)),
      ref_(std::exchange(other.ref_, LUA_NOREF)),
      context_(std::move(other.context_)),
      known_(std::move(other.known_)) {}

TableReader& TableReader::operator=(TableReader&& other) noexcept {
  if (this != &other) {
    if (L_ != nullptr && ref_ != LUA_NOREF) luaL_unref(L_, LUA_REGISTRYINDEX, ref_);
    L_ = std::exchange(other.L_, nullptr);
    ref_ = std::exchange(other.ref_, LUA_NOREF);
    context_ = std::move(other.context_);
    known_ = std::move(other.known_);
  }
  return *this;
}

int TableReader::fetch(std::string_view key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
  lua_rawgeti(L_, LUA_REGISTRYINDEX, ref_);
  lua_pushlstring(L_, key.data(), key.size());
  lua_rawget(L_, -2);
  lua_remove(L_, -2);
  const int type = lua_type(L_, -1);
  if (type == LUA_TNIL) refuse_inherited(key);
  return type;
}

void TableReader::refuse_inherited(std::string_view key) const {
  const StackGuard guard(L_);
  push();
  // Each level: the metatable of the table on top, then its __index.
  for (int level = 0; level < kMaxInheritance && lua_getmetatable(L_, -1) != 0; ++level) {
    lua_pushliteral(L_, "__index");
    lua_rawget(L_, -2);
    const int type = lua_type(L_, -1);
    if (type == LUA_TNIL) return;
    if (type != LUA_TTABLE) {
      fail(fmt::format(
          "field '{}' is not in the table itself, and its metatable has an __index {}, which the engine does not "
          "call: it reads a table's own fields only; set '{}' in the table",
          shown_key(key), luaL_typename(L_, -1), shown_key(key)));
    }
    lua_pushlstring(L_, key.data(), key.size());
    lua_rawget(L_, -2);
    if (!lua_isnil(L_, -1)) {
      fail(fmt::format(
          "field '{}' is inherited through a metatable's __index, which the engine does not follow: it reads a "
          "table's own fields only; set '{}' in the table",
          shown_key(key), shown_key(key)));
    }
    lua_pop(L_, 1);
  }
}

int TableReader::fetch_at(std::size_t i) {
  if (i == 0 || i > static_cast<std::size_t>(INT_MAX)) {
    fail(fmt::format("element [{}] does not exist (elements count from 1)", i));
  }
  lua_rawgeti(L_, LUA_REGISTRYINDEX, ref_);
  lua_rawgeti(L_, -1, static_cast<int>(i));
  lua_remove(L_, -2);
  return lua_type(L_, -1);
}

void TableReader::fail(const std::string& problem) const {
  throw FieldError(fmt::format("{}: {}", context_, problem));
}

void TableReader::wrong_type(const Slot& slot, const char* expected) const {
  fail(fmt::format("{} must be {}, got {}", slot.label(), expected, describe(L_, -1)));
}

double TableReader::read_number(const Slot& slot, int type) {
  if (type != LUA_TNUMBER) wrong_type(slot, "a number");
  const double value = lua_tonumber(L_, -1);
  if (!std::isfinite(value)) {
    // 0/0 is a negative NaN on x86; the sign of a NaN means nothing to authors.
    const char* what = std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf";
    fail(fmt::format("{} is {} (numbers must be finite)", slot.label(), what));
  }
  return value;
}

std::int64_t TableReader::read_integer(const Slot& slot, int type) {
  if (type != LUA_TNUMBER) wrong_type(slot, "an integer");
  const double value = read_number(slot, type);
  if (std::trunc(value) != value) wrong_type(slot, "an integer");
  // 2^63 is exact in a double; every integral double below it fits.
  constexpr double kLimit = 9223372036854775808.0;
  if (value < -kLimit || value >= kLimit) wrong_type(slot, "an integer in the 64-bit range");
  return static_cast<std::int64_t>(value);
}

std::string TableReader::read_string(const Slot& slot, int type) {
  // No number-to-string coercion: strict means what the author wrote.
  if (type != LUA_TSTRING) wrong_type(slot, "a string");
  std::size_t len = 0;
  const char* p = lua_tolstring(L_, -1, &len);
  return std::string(p, len);
}

TableReader TableReader::read_table(const Slot& slot, int type) {
  if (type != LUA_TTABLE) wrong_type(slot, "a table");
  return TableReader(L_, -1, slot.child_context(context_));
}

bool TableReader::has(std::string_view key) {
  const StackGuard guard(L_);
  return fetch(key) != LUA_TNIL;
}

double TableReader::number(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) missing(key);
  return read_number(Slot{key}, type);
}

std::optional<double> TableReader::optional_number(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) return std::nullopt;
  return read_number(Slot{key}, type);
}

double TableReader::number_or(std::string_view key, double fallback) {
  return optional_number(key).value_or(fallback);
}

std::int64_t TableReader::integer(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) missing(key);
  return read_integer(Slot{key}, type);
}

std::optional<std::int64_t> TableReader::optional_integer(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) return std::nullopt;
  return read_integer(Slot{key}, type);
}

std::int64_t TableReader::integer_or(std::string_view key, std::int64_t fallback) {
  return optional_integer(key).value_or(fallback);
}

std::string TableReader::string(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) missing(key);
  return read_string(Slot{key}, type);
}

std::optional<std::string> TableReader::optional_string(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) return std::nullopt;
  return read_string(Slot{key}, type);
}

std::string TableReader::string_or(std::string_view key, std::string_view fallback) {
  auto value = optional_string(key);
  return value ? std::move(*value) : std::string(fallback);
}

bool TableReader::boolean(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) missing(key);
  if (type != LUA_TBOOLEAN) wrong_type(Slot{key}, "a boolean");
  return lua_toboolean(L_, -1) != 0;
}

std::optional<bool> TableReader::optional_boolean(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) return std::nullopt;
  if (type != LUA_TBOOLEAN) wrong_type(Slot{key}, "a boolean");
  return lua_toboolean(L_, -1) != 0;
}

bool TableReader::boolean_or(std::string_view key, bool fallback) {
  return optional_boolean(key).value_or(fallback);
}

TableReader TableReader::table(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) missing(key);
  return read_table(Slot{key}, type);
}

std::optional<TableReader> TableReader::optional_table(std::string_view key) {
  const StackGuard guard(L_);
  const int type = fetch(key);
  if (type == LUA_TNIL) return std::nullopt;
  return read_table(Slot{key}, type);
}

void TableReader::push_field(std::string_view key) { fetch(key); }

void TableReader::push() const { lua_rawgeti(L_, LUA_REGISTRYINDEX, ref_); }

std::size_t TableReader::length() const {
  const StackGuard guard(L_);
  push();
  return lua_objlen(L_, -1);
}

double TableReader::number_at(std::size_t i) {
  const StackGuard guard(L_);
  const int type = fetch_at(i);
  if (type == LUA_TNIL) fail(fmt::format("missing element [{}]", i));
  return read_number(Slot{{}, i}, type);
}

std::int64_t TableReader::integer_at(std::size_t i) {
  const StackGuard guard(L_);
  const int type = fetch_at(i);
  if (type == LUA_TNIL) fail(fmt::format("missing element [{}]", i));
  return read_integer(Slot{{}, i}, type);
}

std::string TableReader::string_at(std::size_t i) {
  const StackGuard guard(L_);
  const int type = fetch_at(i);
  if (type == LUA_TNIL) fail(fmt::format("missing element [{}]", i));
  return read_string(Slot{{}, i}, type);
}

TableReader TableReader::table_at(std::size_t i) {
  const StackGuard guard(L_);
  const int type = fetch_at(i);
  if (type == LUA_TNIL) fail(fmt::format("missing element [{}]", i));
  return read_table(Slot{{}, i}, type);
}

void TableReader::mark_known(std::initializer_list<std::string_view> keys) {
  for (const auto key : keys) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
  }
}

void TableReader::missing(std::string_view key) const {
  // A required field is absent: if the table has an unread key that is a
  // near miss of it, the author most likely misspelt it; say so (the
  // nearest one, whatever order lua_next gives).
  std::vector<std::string> candidates;
  {
    const StackGuard guard(L_);
    push();
    lua_pushnil(L_);
    while (lua_next(L_, -2) != 0) {
      if (lua_type(L_, -2) == LUA_TSTRING) {
        std::size_t n = 0;
        const char* p = lua_tolstring(L_, -2, &n);
        const std::string_view k(p, n);
        if (!k.starts_with("__") && k.size() <= kLongestKey &&
            std::find(known_.begin(), known_.end(), k) == known_.end())
          candidates.emplace_back(k);
      }
      lua_pop(L_, 1);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  if (const std::string c = nearest(key, candidates); !c.empty()) {
    fail(fmt::format("missing field '{}' (there is a field '{}': misspelt?)", key, c));
  }
  fail(fmt::format("missing field '{}'", key));
}

void TableReader::finish() const {
  std::vector<std::string> unknown;
  std::vector<std::string> stray;  // non-string keys outside the array part
  std::vector<std::string> absent;   // known keys the table lacks
  std::vector<std::string> present;  // and those it has
  std::size_t len = 0;
  {
    const StackGuard guard(L_);
    push();
    len = lua_objlen(L_, -1);
    for (const auto& key : known_) {
      lua_pushlstring(L_, key.data(), key.size());
      lua_rawget(L_, -2);
      (lua_isnil(L_, -1) ? absent : present).push_back(key);
      lua_pop(L_, 1);
    }
    lua_pushnil(L_);
    while (lua_next(L_, -2) != 0) {
      // Never lua_tolstring a number key: it would change the key mid-walk.
      switch (lua_type(L_, -2)) {
        case LUA_TSTRING: {
          std::size_t n = 0;
          const char* p = lua_tolstring(L_, -2, &n);
          const std::string_view key(p, n);
          if (!key.starts_with("__") && std::find(known_.begin(), known_.end(), key) == known_.end()) {
            unknown.push_back(shown_key(key));
          }
          break;
        }
        case LUA_TNUMBER: {
          const double k = lua_tonumber(L_, -2);
          if (!(k >= 1 && k <= static_cast<double>(len) && std::trunc(k) == k)) {
            stray.push_back(fmt::format("[{}]", k));
          }
          break;
        }
        case LUA_TBOOLEAN:
          stray.push_back(lua_toboolean(L_, -2) != 0 ? "[true]" : "[false]");
          break;
        default:
          stray.push_back(fmt::format("of type {}", luaL_typename(L_, -2)));
          break;
      }
      lua_pop(L_, 1);
    }
  }
  if (unknown.empty() && stray.empty()) return;
  // lua_next order is arbitrary; sorted messages are reproducible.
  std::sort(unknown.begin(), unknown.end());
  std::sort(stray.begin(), stray.end());
  std::vector<std::string> problems;
  for (const auto& key : unknown) {
    // An unknown field most likely stands for a known one the table lacks
    // (frame_count for frames, when frame is there too).
    std::string suggestion = nearest(key, absent);
    if (suggestion.empty()) suggestion = nearest(key, present);
    problems.push_back(suggestion.empty()
                           ? fmt::format("unknown field '{}'", key)
                           : fmt::format("unknown field '{}' (did you mean '{}'?)", key, suggestion));
  }
  for (const auto& key : stray) {
    problems.push_back(fmt::format(
        "unexpected key {} (only named fields and list elements 1..{} are allowed)", key, len));
  }
  fail(fmt::format("{}", fmt::join(problems, "; ")));
}

}  // namespace lc::lua
