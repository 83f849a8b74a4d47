#include "lua/determinism.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>

#include "lua/sandbox.hpp"

namespace lc::lua {

namespace {

// Where a key falls in the walking order (determinism.hpp): by rank first.
enum class KeyRank { integer, number, string, boolean };

// A key, orderable without Lua: strings point into the Lua string, which
// must stay alive (a key of the table being walked, or a value on the
// stack) while the Key is used.
struct Key {
  KeyRank rank = KeyRank::integer;
  double number = 0;  // numbers; booleans as 0 and 1
  const char* bytes = nullptr;
  std::size_t size = 0;
};

// Whether a sorts before b in the walking order.
bool before(const Key& a, const Key& b) {
  if (a.rank != b.rank) return a.rank < b.rank;
  if (a.rank != KeyRank::string) return a.number < b.number;
  const int c = std::memcmp(a.bytes, b.bytes, std::min(a.size, b.size));
  return c != 0 ? c < 0 : a.size < b.size;
}

// Whether the value has only its address to tell it from another (and so
// gets an identity from the sandbox instead).
bool has_address(int type) {
  return type == LUA_TTABLE || type == LUA_TFUNCTION || type == LUA_TUSERDATA || type == LUA_TTHREAD ||
         type == LUA_TLIGHTUSERDATA;
}

// The value at `index` as a Key; false for a value whose only order is its
// address (nil and NaN are no keys).
bool to_key(lua_State* L, int index, Key& out) {
  switch (lua_type(L, index)) {
    case LUA_TNUMBER: {
      out.number = lua_tonumber(L, index);
      const bool integral = std::isfinite(out.number) && std::trunc(out.number) == out.number;
      out.rank = integral ? KeyRank::integer : KeyRank::number;
      return true;
    }
    case LUA_TSTRING:
      out.rank = KeyRank::string;
      out.bytes = lua_tolstring(L, index, &out.size);
      return true;
    case LUA_TBOOLEAN:
      out.rank = KeyRank::boolean;
      out.number = lua_toboolean(L, index);
      return true;
    default:
      return false;
  }
}

// Pushes the Lua value `k` stands for.
void push_key(lua_State* L, const Key& k) {
  switch (k.rank) {
    case KeyRank::integer:
    case KeyRank::number:
      lua_pushnumber(L, k.number);
      break;
    case KeyRank::string:
      lua_pushlstring(L, k.bytes, k.size);  // interned already: no allocation
      break;
    case KeyRank::boolean:
      lua_pushboolean(L, k.number != 0);
      break;
  }
}

// The refusal of a table keyed by a value of type `type` (for `fn`,
// pairs or next); protect() puts the script line in front.
std::runtime_error unordered(const char* fn, const char* type) {
  return std::runtime_error(fmt::format(
      "{}: this table has a key that is a {} value, whose only order is its memory address, which differs between "
      "runs; the sandbox walks tables in a fixed order so that every frame renders the same (docs/shots.md): keep "
      "such values in an array (list[#list + 1] = value) and walk it with ipairs, or key them by a name or number",
      fn, type));
}

// next(t, k): the key after k in the walking order and its value, the
// first key for k == nil, nil after the last. Looks through the whole
// table: pairs is the way to walk one. Unlike LuaJIT's, any orderable k is
// accepted (a key cleared meanwhile, or none of the table's).
int ordered_next(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_settop(L, 2);
  return protect(L, [](lua_State* L) {
    const bool from_start = lua_isnil(L, 2);
    Key after;
    if (!from_start && !to_key(L, 2, after)) throw unordered("next", luaL_typename(L, 2));
    lua_pushnil(L);  // 3: the best key so far (keeps its string alive)
    bool found = false;
    Key best;
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
      lua_pop(L, 1);
      Key k;
      if (!to_key(L, -1, k)) throw unordered("next", luaL_typename(L, -1));
      if ((from_start || before(after, k)) && (!found || before(k, best))) {
        found = true;
        best = k;
        lua_pushvalue(L, -1);
        lua_replace(L, 3);
      }
    }
    if (!found) {
      lua_pushnil(L);
      return 1;
    }
    lua_pushvalue(L, 3);
    lua_pushvalue(L, 3);
    lua_rawget(L, 1);
    return 2;
  });
}

// The iterator pairs returns. Upvalues: the table, its keys in walking
// order (an array, taken when pairs was called), the position of the last
// key returned. Returns the next key whose value is not nil and that value.
// Called with another key than the last it returned (a script calling it
// itself), it goes on after that key.
int walk(lua_State* L) {
  lua_settop(L, 2);
  const int table = lua_upvalueindex(1);
  const int keys = lua_upvalueindex(2);
  const int count = static_cast<int>(lua_objlen(L, keys));
  int pos = static_cast<int>(lua_tointeger(L, lua_upvalueindex(3)));
  lua_rawgeti(L, keys, pos);
  const bool in_step = pos == 0 ? lua_isnil(L, 2) : lua_rawequal(L, -1, 2) != 0;
  lua_pop(L, 1);
  if (!in_step) {
    pos = 0;
    if (!lua_isnil(L, 2)) {
      Key after;
      if (!to_key(L, 2, after)) {
        return protect(L, [](lua_State* L) -> int { throw unordered("pairs", luaL_typename(L, 2)); });
      }
      int lo = 0, hi = count;  // the first position whose key sorts after `after` is in (lo, hi + 1]
      while (lo < hi) {
        const int mid = lo + (hi - lo + 1) / 2;
        lua_rawgeti(L, keys, mid);
        Key k;
        to_key(L, -1, k);
        const bool later = before(after, k);
        lua_pop(L, 1);
        if (later) {
          hi = mid - 1;
        } else {
          lo = mid;
        }
      }
      pos = lo;
    }
  }
  for (int j = pos + 1; j <= count; ++j) {
    lua_rawgeti(L, keys, j);
    lua_pushvalue(L, -1);
    lua_rawget(L, table);
    if (!lua_isnil(L, -1)) {
      lua_pushinteger(L, j);
      lua_replace(L, lua_upvalueindex(3));
      return 2;
    }
    lua_pop(L, 2);
  }
  lua_pushinteger(L, count);
  lua_replace(L, lua_upvalueindex(3));
  lua_pushnil(L);
  return 1;
}

// pairs(t) -> walk, t, nil, with t's keys sorted once. The keys' sort
// buffer is a userdata, so the memory limit counts it.
int ordered_pairs(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_settop(L, 1);
  return protect(L, [](lua_State* L) {
    std::size_t count = 0;
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
      lua_pop(L, 1);
      ++count;
    }
    auto* sorted = static_cast<Key*>(lua_newuserdata(L, std::max<std::size_t>(count, 1) * sizeof(Key)));
    std::size_t n = 0;
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
      lua_pop(L, 1);
      Key& k = *new (sorted + n) Key;
      if (!to_key(L, -1, k)) throw unordered("pairs", luaL_typename(L, -1));
      ++n;
    }
    std::sort(sorted, sorted + n, before);
    lua_pushvalue(L, 1);
    lua_createtable(L, static_cast<int>(n), 0);
    for (std::size_t j = 0; j < n; ++j) {
      push_key(L, sorted[j]);
      lua_rawseti(L, -2, static_cast<int>(j + 1));
    }
    lua_pushinteger(L, 0);
    lua_pushcclosure(L, &walk, 3);
    lua_pushvalue(L, 1);
    lua_pushnil(L);
    return 3;
  });
}

// The identity of the value at `index` (a value with an address, or a
// string): its number from the table at upvalue 1, or the next one from
// the counter at upvalue 2 if it has none yet. The table has weak keys: a
// value collected is never asked for again, and numbers are not reused.
lua_Number identity(lua_State* L, int index) {
  index = index > 0 ? index : lua_gettop(L) + index + 1;
  lua_pushvalue(L, index);
  lua_rawget(L, lua_upvalueindex(1));
  if (lua_type(L, -1) == LUA_TNUMBER) {
    const lua_Number n = lua_tonumber(L, -1);
    lua_pop(L, 1);
    return n;
  }
  lua_pop(L, 1);
  auto& counter = *static_cast<lua_Number*>(lua_touserdata(L, lua_upvalueindex(2)));
  const lua_Number n = ++counter;
  lua_pushvalue(L, index);
  lua_pushnumber(L, n);
  lua_rawset(L, lua_upvalueindex(1));
  return n;
}

// Whether the value at `index` shows its identity where LuaJIT shows its
// address: a value with an address and no __tostring.
bool shown_by_identity(lua_State* L, int index) {
  if (!has_address(lua_type(L, index))) return false;
  if (luaL_getmetafield(L, index, "__tostring") == 0) return true;
  lua_pop(L, 1);
  return false;
}

// Pushes "table: #N" for the value at `index`.
void push_identity_name(lua_State* L, int index) {
  const std::string name = fmt::format("{}: #{}", luaL_typename(L, index), identity(L, index));
  lua_pushlstring(L, name.data(), name.size());
}

// identity_name(v) -> "table: #N" where tostring(v) would show an address,
// else nil (tostring then goes to LuaJIT's).
int identity_name(lua_State* L) {
  if (lua_gettop(L) < 1 || !shown_by_identity(L, 1)) return 0;
  push_identity_name(L, 1);
  return 1;
}

// format_args(fmt, ...) -> fmt, ... as string.format should see them: each
// argument of a %s that would show an address replaced by its identity
// name, each %p of a string or a value with an address made a %s of "#N".
// The conversions are parsed as LuaJIT does (flags, width, precision, one
// letter); a malformed one is left for LuaJIT's format to refuse.
int format_args(lua_State* L) {
  const int top = lua_gettop(L);
  if (lua_type(L, 1) != LUA_TSTRING) return top;
  std::size_t size = 0;
  const char* text = lua_tolstring(L, 1, &size);
  const std::string_view in(text, size);
  std::string out;
  bool changed = false;
  int arg = 1;
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (in[i] != '%') continue;
    if (i + 1 < in.size() && in[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < in.size() && std::strchr("-+ #0", in[j]) != nullptr) ++j;
    while (j < in.size() && (std::isdigit(static_cast<unsigned char>(in[j])) != 0 || in[j] == '.')) ++j;
    if (j >= in.size()) break;
    ++arg;
    i = j;
    if (arg > top) continue;
    if (in[j] == 's' && shown_by_identity(L, arg)) {
      push_identity_name(L, arg);
      lua_replace(L, arg);
    } else if (in[j] == 'p' && (has_address(lua_type(L, arg)) || lua_type(L, arg) == LUA_TSTRING)) {
      if (!changed) out.assign(in);
      changed = true;
      out[j] = 's';
      const std::string id = fmt::format("#{}", identity(L, arg));
      lua_pushlstring(L, id.data(), id.size());
      lua_replace(L, arg);
    }
  }
  if (changed) {
    lua_pushlstring(L, out.data(), out.size());
    lua_replace(L, 1);
  }
  return top;
}

// The replacements written in Lua (see determinism.hpp for why tostring
// must be one). `pairs` and `type` are captured: a script may reassign the
// globals.
constexpr const char* kPrelude = R"lua(
local tostring_builtin, identity_name, format_builtin, format_args, pairs = ...
local type, error = type, error
local setmetatable_builtin, rawget = setmetatable, rawget
-- What a weak table keeps depends on when the collector runs, and that on
-- how the state's tables grew (its hash seed): refused, like address order.
function setmetatable(t, mt)
  if type(mt) == "table" and rawget(mt, "__mode") ~= nil then
    error("setmetatable: weak tables (a metatable with __mode) are refused: what they keep depends on when the "
          .. "garbage collector runs, which differs between runs; the sandbox keeps every frame the same "
          .. "(docs/shots.md): keep the values in an ordinary table", 2)
  end
  return setmetatable_builtin(t, mt)
end
function tostring(...)
  local name = identity_name(...)
  if name ~= nil then return name end
  return tostring_builtin(...)
end
function string.format(...) return format_builtin(format_args(...)) end
function table.foreach(t, f)
  if type(t) ~= "table" then error("bad argument #1 to 'foreach' (table expected, got " .. type(t) .. ")", 2) end
  for k, v in pairs(t) do
    local r = f(k, v)
    if r ~= nil then return r end
  end
end
)lua";

}  // namespace

void install_determinism(lua_State* L) {
  lua_pushcfunction(L, &ordered_next);
  lua_setglobal(L, "next");
  lua_pushcfunction(L, &ordered_pairs);
  lua_setglobal(L, "pairs");

  if (luaL_loadbuffer(L, kPrelude, std::strlen(kPrelude), "=[sandbox]") != 0) {
    throw std::logic_error(lua_tostring(L, -1));
  }
  lua_getglobal(L, "tostring");
  // Shared by both closures: the identities and their counter.
  lua_newtable(L);
  lua_createtable(L, 0, 1);
  lua_pushliteral(L, "k");
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
  *static_cast<lua_Number*>(lua_newuserdata(L, sizeof(lua_Number))) = 0;
  lua_pushvalue(L, -2);
  lua_pushvalue(L, -2);
  lua_pushcclosure(L, &identity_name, 2);
  lua_insert(L, -3);
  lua_getglobal(L, LUA_STRLIBNAME);
  lua_getfield(L, -1, "format");
  lua_replace(L, -2);
  lua_insert(L, -3);
  lua_pushcclosure(L, &format_args, 2);
  lua_getglobal(L, "pairs");
  lua_call(L, 5, 0);
}

}  // namespace lc::lua
