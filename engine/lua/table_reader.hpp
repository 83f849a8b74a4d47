#pragma once
// Strict reading of one Lua table into C++ values, with errors that tell a
// shot author exactly which field is wrong and how.

#include <lua.hpp>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lc::lua {

// A script value does not have the expected shape. what() is
// "<context>: <problem>", e.g. "shot.lua:4: spacetime: missing field 'mass'".
class FieldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The candidate `word` most likely misspells, or "" if none is close enough.
// Close enough: an edit distance (Damerau, adjacent transpositions count 1)
// of at most 2 when both words have 6+ characters, 1 when the shorter has
// 3-5, none for shorter ones; or, less close, a common prefix of 4+
// characters that leaves at most one of the shorter word (frame_count ~
// frames). Ties go to the earlier candidate; `word` itself is no candidate.
std::string nearest(std::string_view word, std::span<const std::string> candidates);

// Reads one table strictly. All access is raw (no Lua code runs) and every
// call leaves the Lua stack as it found it. A field the table lacks but a
// metatable's __index would give is refused, naming it, rather than read
// or ignored: a field absent where the __index is a table that holds it,
// or absent at all where the __index is a function (which would run
// unprotected). The
// reader pins the table with a registry reference, so readers and their child
// readers may live in any order, but none may outlive the lua_State.
// Getters throw FieldError; inside a lua_CFunction wrap them in protect().
// Keys starting with "__" are the engine's own and never count as unknown.
class TableReader {
 public:
  // The value at `index` must be a table; `context` prefixes every error.
  TableReader(lua_State* L, int index, std::string context);
  ~TableReader();
  TableReader(const TableReader&) = delete;
  TableReader& operator=(const TableReader&) = delete;
  TableReader(TableReader&& other) noexcept;
  TableReader& operator=(TableReader&& other) noexcept;

  const std::string& context() const { return context_; }
  lua_State* state() const { return L_; }

  // True if the field is present (not nil); marks it known.
  bool has(std::string_view key);

  // Required getters throw on a missing field; optional ones return nullopt
  // (or the fallback) when it is nil, and throw when it has the wrong type.
  // Numbers must be finite; integers must also be integral and fit int64.
  double number(std::string_view key);
  std::optional<double> optional_number(std::string_view key);
  double number_or(std::string_view key, double fallback);
  std::int64_t integer(std::string_view key);
  std::optional<std::int64_t> optional_integer(std::string_view key);
  std::int64_t integer_or(std::string_view key, std::int64_t fallback);
  std::string string(std::string_view key);
  std::optional<std::string> optional_string(std::string_view key);
  std::string string_or(std::string_view key, std::string_view fallback);
  bool boolean(std::string_view key);
  std::optional<bool> optional_boolean(std::string_view key);
  bool boolean_or(std::string_view key, bool fallback);

  // Nested tables; the child's context is context + "." + key.
  TableReader table(std::string_view key);
  std::optional<TableReader> optional_table(std::string_view key);

  // Pushes the raw value of a field (nil if absent) and marks it known: for
  // values the engine reads itself, like functions.
  void push_field(std::string_view key);
  // Pushes the table itself.
  void push() const;

  // The array part: length as by the # operator; elements are 1-based and
  // required. Element errors name "element [i]"; a child table's context is
  // context + "[i]".
  std::size_t length() const;
  double number_at(std::size_t i);
  std::int64_t integer_at(std::size_t i);
  std::string string_at(std::size_t i);
  TableReader table_at(std::size_t i);

  // Accepts keys the caller handles some other way.
  void mark_known(std::initializer_list<std::string_view> keys);

  // Strict check after reading: throws if the table holds a string key that
  // no getter, has() or mark_known() touched (suggesting the nearest known
  // key, one the table lacks if any is near), or a non-string key outside
  // the array part 1..length().
  void finish() const;

 private:
  struct Slot;  // where a value came from, for messages
  int fetch(std::string_view key);        // pushes the field value; marks known
  int fetch_at(std::size_t i);            // pushes element i
  double read_number(const Slot& slot, int type);
  std::int64_t read_integer(const Slot& slot, int type);
  std::string read_string(const Slot& slot, int type);
  TableReader read_table(const Slot& slot, int type);
  [[noreturn]] void fail(const std::string& problem) const;
  [[noreturn]] void missing(std::string_view key) const;
  void refuse_inherited(std::string_view key) const;  // throws if a metatable's __index may give the field  // "missing field", with a near-miss hint
  [[noreturn]] void wrong_type(const Slot& slot, const char* expected) const;

  lua_State* L_ = nullptr;
  int ref_ = LUA_NOREF;
  std::string context_;
  std::vector<std::string> known_;
};

}  // namespace lc::lua
