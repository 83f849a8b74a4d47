// Tests of lc::lua::TableReader: typed getters, exact error messages, nested
// contexts, strict finish() with suggestions, and Lua stack hygiene.

#include "lua/sandbox.hpp"
#include "lua/table_reader.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "test_errors.hpp"

namespace {

using lc::lua::FieldError;
using lc::lua::TableReader;
using lc::test::error_of;

class TableReaderTest : public ::testing::Test {
 protected:
  TableReaderTest() : sandbox_({}), L(sandbox_.state()) {}

  // Pushes the value of a Lua expression (test-only loading of a string).
  void push(const std::string& expression) {
    const std::string chunk = "return " + expression;
    ASSERT_EQ(luaL_loadstring(L, chunk.c_str()), 0) << lua_tostring(L, -1);
    sandbox_.call(0, 1);
  }

  lc::lua::Sandbox sandbox_;
  lua_State* L;
};

TEST_F(TableReaderTest, RejectsNonTables) {
  push("3");
  EXPECT_EQ(error_of<FieldError>([&] { TableReader r(L, -1, "spec.lua:4: spacetime"); }),
            "spec.lua:4: spacetime: expected a table, got number 3");
  push("'kerr'");
  EXPECT_EQ(error_of<FieldError>([&] { TableReader r(L, -1, "ctx"); }), "ctx: expected a table, got string \"kerr\"");
  EXPECT_EQ(lua_gettop(L), 2);
}

TEST_F(TableReaderTest, TypedGetters) {
  push("{mass = 1.5, frames = 900, name = 'dihole', preview = true, none = false}");
  TableReader r(L, -1, "shot");
  EXPECT_EQ(r.number("mass"), 1.5);
  EXPECT_EQ(r.integer("frames"), 900);
  EXPECT_EQ(r.string("name"), "dihole");
  EXPECT_TRUE(r.boolean("preview"));
  EXPECT_FALSE(r.boolean("none"));
  EXPECT_TRUE(r.has("mass"));
  EXPECT_FALSE(r.has("spin"));
  EXPECT_EQ(r.optional_number("spin"), std::nullopt);
  EXPECT_EQ(r.optional_number("mass"), 1.5);
  EXPECT_EQ(r.number_or("spin", 0.25), 0.25);
  EXPECT_EQ(r.number_or("mass", 0.25), 1.5);
  EXPECT_EQ(r.optional_integer("fps"), std::nullopt);
  EXPECT_EQ(r.integer_or("fps", 25), 25);
  EXPECT_EQ(r.optional_string("title"), std::nullopt);
  EXPECT_EQ(r.string_or("title", "untitled"), "untitled");
  EXPECT_EQ(r.optional_boolean("preview"), true);
  EXPECT_EQ(r.boolean_or("none", true), false);
  EXPECT_EQ(r.boolean_or("absent", true), true);
  EXPECT_EQ(r.context(), "shot");
  r.finish();
}

TEST_F(TableReaderTest, WrongTypeAndMissingMessages) {
  push("{mass = '1', name = 3, flag = 1, sub = 5, f = function() end}");
  TableReader r(L, -1, "spec.lua:4: spacetime");
  EXPECT_EQ(error_of<FieldError>([&] { r.number("mass"); }),
            "spec.lua:4: spacetime: field 'mass' must be a number, got string \"1\"");
  EXPECT_EQ(error_of<FieldError>([&] { r.optional_number("mass"); }),
            "spec.lua:4: spacetime: field 'mass' must be a number, got string \"1\"");
  EXPECT_EQ(error_of<FieldError>([&] { r.number("spin"); }), "spec.lua:4: spacetime: missing field 'spin'");
  EXPECT_EQ(error_of<FieldError>([&] { r.string("name"); }),
            "spec.lua:4: spacetime: field 'name' must be a string, got number 3");
  EXPECT_EQ(error_of<FieldError>([&] { r.boolean("flag"); }),
            "spec.lua:4: spacetime: field 'flag' must be a boolean, got number 1");
  EXPECT_EQ(error_of<FieldError>([&] { r.table("sub"); }),
            "spec.lua:4: spacetime: field 'sub' must be a table, got number 5");
  EXPECT_EQ(error_of<FieldError>([&] { r.number("f"); }),
            "spec.lua:4: spacetime: field 'f' must be a number, got function");
  EXPECT_EQ(error_of<FieldError>([&] { r.string("missing"); }), "spec.lua:4: spacetime: missing field 'missing'");
  EXPECT_EQ(error_of<FieldError>([&] { r.table("missing"); }), "spec.lua:4: spacetime: missing field 'missing'");
}

TEST_F(TableReaderTest, MissingFieldPointsAtANearMiss) {
  push("{mass = 1, spinn = 0.5, colour = 2}");
  TableReader r(L, -1, "kerr");
  r.number("mass");
  EXPECT_EQ(error_of<FieldError>([&] { r.number("spin"); }), "kerr: missing field 'spin' (there is a field 'spinn': misspelt?)");
  EXPECT_EQ(error_of<FieldError>([&] { r.number("radius"); }), "kerr: missing field 'radius'");
}

TEST_F(TableReaderTest, NumbersMustBeFinite) {
  push("{a = 0/0, b = 1/0, c = -1/0, d = -(0/0)}");
  TableReader r(L, -1, "observer");
  EXPECT_EQ(error_of<FieldError>([&] { r.number("a"); }),
            "observer: field 'a' is nan (numbers must be finite)");
  EXPECT_EQ(error_of<FieldError>([&] { r.number("b"); }),
            "observer: field 'b' is inf (numbers must be finite)");
  EXPECT_EQ(error_of<FieldError>([&] { r.number_or("c", 0); }),
            "observer: field 'c' is -inf (numbers must be finite)");
  EXPECT_EQ(error_of<FieldError>([&] { r.integer("d"); }),
            "observer: field 'd' is nan (numbers must be finite)");
}

TEST_F(TableReaderTest, IntegerChecks) {
  push("{half = 2.5, big = 2^63, low = -2^63, exact = 2^53, neg = -7, text = '3', huge = 1e300}");
  TableReader r(L, -1, "shot");
  EXPECT_EQ(error_of<FieldError>([&] { r.integer("half"); }),
            "shot: field 'half' must be an integer, got number 2.5");
  EXPECT_EQ(error_of<FieldError>([&] { r.integer("big"); }),
            "shot: field 'big' must be an integer in the 64-bit range, got number 9.223372036854776e+18");
  EXPECT_NE(error_of<FieldError>([&] { r.integer("huge"); }).find("64-bit range"), std::string::npos);
  EXPECT_EQ(r.integer("low"), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(r.integer("exact"), std::int64_t{1} << 53);
  EXPECT_EQ(r.integer("neg"), -7);
  EXPECT_EQ(error_of<FieldError>([&] { r.integer("text"); }),
            "shot: field 'text' must be an integer, got string \"3\"");
}

TEST_F(TableReaderTest, NestedContexts) {
  push("{observer = {position = {r = 'far', theta = 1}}, objects = {{radius = 1}, {radius = 'x'}}}");
  TableReader shot(L, -1, "shot 'dihole' frame 12");
  TableReader observer = shot.table("observer");
  EXPECT_EQ(observer.context(), "shot 'dihole' frame 12.observer");
  TableReader position = observer.table("position");
  EXPECT_EQ(error_of<FieldError>([&] { position.number("r"); }),
            "shot 'dihole' frame 12.observer.position: field 'r' must be a number, got string \"far\"");
  EXPECT_FALSE(shot.optional_table("camera").has_value());
  auto objects = shot.optional_table("objects");
  ASSERT_TRUE(objects.has_value());
  ASSERT_EQ(objects->length(), 2u);
  EXPECT_EQ(objects->table_at(1).number("radius"), 1);
  TableReader second = objects->table_at(2);
  EXPECT_EQ(second.context(), "shot 'dihole' frame 12.objects[2]");
  EXPECT_EQ(error_of<FieldError>([&] { second.number("radius"); }),
            "shot 'dihole' frame 12.objects[2]: field 'radius' must be a number, got string \"x\"");
}

TEST_F(TableReaderTest, ArrayElements) {
  push("{1, 2.5, 'x', {a = 1}, 7}");
  TableReader r(L, -1, "path");
  EXPECT_EQ(r.length(), 5u);
  EXPECT_EQ(r.number_at(1), 1);
  EXPECT_EQ(r.number_at(2), 2.5);
  EXPECT_EQ(r.integer_at(5), 7);
  EXPECT_EQ(r.string_at(3), "x");
  EXPECT_EQ(error_of<FieldError>([&] { r.number_at(3); }), "path: element [3] must be a number, got string \"x\"");
  EXPECT_EQ(error_of<FieldError>([&] { r.integer_at(2); }), "path: element [2] must be an integer, got number 2.5");
  EXPECT_EQ(error_of<FieldError>([&] { r.number_at(6); }), "path: missing element [6]");
  EXPECT_EQ(error_of<FieldError>([&] { r.number_at(0); }),
            "path: element [0] does not exist (elements count from 1)");
  EXPECT_EQ(error_of<FieldError>([&] { r.table_at(1); }), "path: element [1] must be a table, got number 1");
  EXPECT_EQ(error_of<FieldError>([&] { r.table_at(4).number("b"); }), "path[4]: missing field 'b'");
  r.finish();  // the array part is always accepted
}

TEST_F(TableReaderTest, FinishSuggestsNearestKnownField) {
  push("{mass = 1, spinn = 0.9}");
  TableReader r(L, -1, "spec.lua:4: spacetime");
  r.number("mass");
  r.optional_number("spin");
  EXPECT_EQ(error_of<FieldError>([&] { r.finish(); }),
            "spec.lua:4: spacetime: unknown field 'spinn' (did you mean 'spin'?)");
}

// An unknown field most likely stands for a known one the table lacks:
// frame_count for frames, though frame is a field too.
TEST_F(TableReaderTest, FinishPrefersMissingFields) {
  push("{frame = 1, frame_count = 2, width = 3, widht = 4}");
  TableReader r(L, -1, "shot");
  r.optional_number("frames");
  r.number("frame");
  r.number("width");
  r.optional_number("height");
  EXPECT_EQ(error_of<FieldError>([&] { r.finish(); }),
            "shot: unknown field 'frame_count' (did you mean 'frames'?); "
            "unknown field 'widht' (did you mean 'width'?)");  // no missing field is near it
}

// A missing field's hint names the nearest unread key, whatever order
// lua_next gives, and never one that only shares a letter count.
TEST_F(TableReaderTest, MissingFieldHintsTheNearestKey) {
  push("{outer = 10}");
  TableReader disk(L, -1, "disk");
  EXPECT_EQ(error_of<FieldError>([&] { disk.number("inner"); }), "disk: missing field 'inner'");
  push("{iner = 6, outer = 10, innr = 5, inner_radius = 4}");
  TableReader typo(L, -1, "disk");
  EXPECT_EQ(error_of<FieldError>([&] { typo.number("inner"); }),
            "disk: missing field 'inner' (there is a field 'iner': misspelt?)");
  push("{frame_count = 3, frame = 1}");
  TableReader shot(L, -1, "shot.lua");
  shot.mark_known({"frame"});
  EXPECT_EQ(error_of<FieldError>([&] { shot.integer("frames"); }),
            "shot.lua: missing field 'frames' (there is a field 'frame_count': misspelt?)");
}

// A script's table may have a key of any length: messages show 64
// characters of it.
TEST_F(TableReaderTest, LongUnknownKeysAreShortened) {
  push("{[string.rep('k', 1e6)] = 1}");
  TableReader r(L, -1, "camera");
  EXPECT_EQ(error_of<FieldError>([&] { r.finish(); }), "camera: unknown field '" + std::string(64, 'k') + "...'");
}

TEST_F(TableReaderTest, FinishWithoutCloseMatchAndSorted) {
  push("{mass = 1, colour = 'red', zzz = 1, mas = 2, ams = 3}");
  TableReader r(L, -1, "kerr");
  r.number("mass");
  EXPECT_EQ(error_of<FieldError>([&] { r.finish(); }),
            "kerr: unknown field 'ams'; unknown field 'colour'; "
            "unknown field 'mas' (did you mean 'mass'?); unknown field 'zzz'");
}

TEST_F(TableReaderTest, FinishAcceptsKnownAndEngineKeys) {
  push("{mass = 1, __kind = 'kerr', __where = 'a.lua:1', frame = function() end, extra = 2}");
  TableReader r(L, -1, "shot");
  r.number("mass");
  EXPECT_TRUE(r.has("extra"));  // has() counts as reading
  r.push_field("frame");
  EXPECT_TRUE(lua_isfunction(L, -1));
  lua_pop(L, 1);
  r.finish();

  push("{mass = 1, spin = 2}");
  TableReader m(L, -1, "kerr");
  m.mark_known({"mass", "spin"});
  m.finish();
}

TEST_F(TableReaderTest, FinishRejectsStrayNonStringKeys) {
  push("{1, 2, [10] = 3, [true] = 4, [2.5] = 5, [{}] = 6}");
  TableReader r(L, -1, "list");
  const std::string msg = error_of<FieldError>([&] { r.finish(); });
  EXPECT_EQ(msg.rfind("list: unexpected key [10] (only named fields and list elements 1..2 are allowed)", 0), 0u)
      << msg;
  EXPECT_NE(msg.find("unexpected key [2.5]"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unexpected key [true]"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unexpected key of type table"), std::string::npos) << msg;
}

TEST_F(TableReaderTest, MetamethodsNeverRun) {
  push("setmetatable({}, {__index = function() error('must not run') end})");
  TableReader r(L, -1, "spec");
  EXPECT_EQ(error_of<FieldError>([&] { r.number("mass"); }),
            "spec: field 'mass' is not in the table itself, and its metatable has an __index function, which the "
            "engine does not call: it reads a table's own fields only; set 'mass' in the table");
  r.finish();
}

// Fields a metatable's __index would give were ignored without a word
// (issue 43): the reader reads own fields only, so it refuses them, naming
// the field; a table whose __index gives nothing it reads is fine.
TEST_F(TableReaderTest, FieldsInheritedThroughIndexAreRefused) {
  push("setmetatable({mass = 1}, {__index = setmetatable({}, {__index = {spin = 0.5}})})");
  TableReader r(L, -1, "spacetime");
  EXPECT_EQ(r.number("mass"), 1);
  EXPECT_EQ(error_of<FieldError>([&] { r.optional_number("spin"); }),
            "spacetime: field 'spin' is inherited through a metatable's __index, which the engine does not follow: "
            "it reads a table's own fields only; set 'spin' in the table");
  EXPECT_EQ(r.optional_number("charge"), std::nullopt);  // inherited from nowhere
  push("setmetatable({}, {__index = function() return 3 end})");
  TableReader f(L, -1, "camera");
  EXPECT_EQ(error_of<FieldError>([&] { f.number_or("fov", 60); }),
            "camera: field 'fov' is not in the table itself, and its metatable has an __index function, which the "
            "engine does not call: it reads a table's own fields only; set 'fov' in the table");
  push("setmetatable({fov = 30}, {__index = function() error('never') end})");
  TableReader own(L, -1, "camera");
  EXPECT_EQ(own.number_or("fov", 60), 30);  // an own field: no __index asked
  push("setmetatable({}, {__tostring = function() return 'x' end})");
  TableReader plain(L, -1, "camera");
  EXPECT_EQ(plain.number_or("fov", 60), 60);
  EXPECT_EQ(lua_gettop(L), 4);
}

TEST_F(TableReaderTest, NoStackLeaks) {
  push("{a = 1, b = 'x', c = {d = {1, 2}, u = 1}, e = 0/0, u = 2}");
  const int top = lua_gettop(L);
  {
    TableReader r(L, -1, "t");
    r.number("a");
    r.has("z");
    r.optional_string("b");
    TableReader c = r.table("c");
    TableReader d = c.table("d");
    d.number_at(2);
    d.length();
    for (int i = 0; i < 3; ++i) {
      EXPECT_THROW(r.number("b"), FieldError);
      EXPECT_THROW(r.integer("e"), FieldError);
      EXPECT_THROW(r.table("a"), FieldError);
      EXPECT_THROW(d.table_at(1), FieldError);
      EXPECT_THROW(c.finish(), FieldError);
      EXPECT_THROW(r.finish(), FieldError);
    }
    EXPECT_EQ(lua_gettop(L), top);
  }
  EXPECT_EQ(lua_gettop(L), top);
}

// The readers pin their tables with registry references and release them.
TEST_F(TableReaderTest, ReferencesPinAndRelease) {
  // Sees whether a table is alive: a weak table made through the C API
  // (the sandbox refuses them to scripts, whose frames must not follow the
  // collector's timing; this test is about that timing).
  lua_newtable(L);
  lua_createtable(L, 0, 1);
  lua_pushliteral(L, "v");
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
  const int weak = lua_gettop(L);
  const auto alive = [&](int i) {
    lua_gc(L, LUA_GCCOLLECT, 0);
    lua_rawgeti(L, weak, i);
    const bool is_alive = !lua_isnil(L, -1);
    lua_pop(L, 1);
    return is_alive;
  };
  push("{child = {}}");
  lua_pushvalue(L, -1);
  lua_rawseti(L, weak, 1);
  lua_getfield(L, -1, "child");
  lua_rawseti(L, weak, 2);
  {
    std::optional<TableReader> parent(std::in_place, L, -1, "t");
    lua_pop(L, 1);  // from here on only the readers hold the tables
    TableReader child = parent->table("child");
    EXPECT_TRUE(alive(1));
    EXPECT_TRUE(alive(2));
    { TableReader moved = std::move(*parent); }
    EXPECT_FALSE(alive(1));
    EXPECT_TRUE(alive(2));
    parent.reset();  // a moved-from reader releases nothing
    EXPECT_TRUE(alive(2));
    EXPECT_EQ(child.length(), 0u);
  }
  EXPECT_FALSE(alive(2));
  EXPECT_EQ(lua_gettop(L), weak);
}

TEST_F(TableReaderTest, ChildrenOutliveParentsAndMovesWork) {
  push("{camera = {fov = 60}}");
  std::optional<TableReader> camera;
  {
    TableReader shot(L, -1, "shot");
    camera = shot.table("camera");
  }
  lua_settop(L, 0);                      // the table is only pinned by the reader now
  lua_gc(L, LUA_GCCOLLECT, 0);
  EXPECT_EQ(camera->number("fov"), 60);
  TableReader moved = std::move(*camera);
  EXPECT_EQ(moved.number("fov"), 60);
  EXPECT_EQ(moved.context(), "shot.camera");
  moved.finish();
  camera.reset();  // destroying the moved-from reader releases nothing twice
  TableReader assigned = std::move(moved);
  EXPECT_EQ(assigned.number("fov"), 60);
}

TEST(TableReaderNearest, Distances) {
  const std::vector<std::string> keys = {"mass", "spin", "fov", "inclination", "r_out"};
  EXPECT_EQ(lc::lua::nearest("spinn", keys), "spin");
  EXPECT_EQ(lc::lua::nearest("sipn", keys), "spin");        // transposition
  EXPECT_EQ(lc::lua::nearest("mas", keys), "mass");
  EXPECT_EQ(lc::lua::nearest("fvo", keys), "fov");
  EXPECT_EQ(lc::lua::nearest("inclinaton", keys), "inclination");
  EXPECT_EQ(lc::lua::nearest("incilnatoin", keys), "inclination");  // two swaps
  EXPECT_EQ(lc::lua::nearest("rout", keys), "r_out");
  EXPECT_EQ(lc::lua::nearest("colour", keys), "");
  EXPECT_EQ(lc::lua::nearest("msa", keys), "");  // short words: distance 1 only
  EXPECT_EQ(lc::lua::nearest("x", {std::vector<std::string>{"y"}}), "");
  EXPECT_EQ(lc::lua::nearest("mass", keys), "");  // an exact match is no suggestion
  EXPECT_EQ(lc::lua::nearest("spin", {}), "");
}

// 'outer' is no misspelling of 'inner' (two of five letters differ); a
// name that extends a field's (frame_count, inner_radius) likely means it.
TEST(TableReaderNearest, ShortWordsAndSharedBeginnings) {
  const std::vector<std::string> disk = {"inner", "outer", "rings", "sectors"};
  EXPECT_EQ(lc::lua::nearest("outer", {std::vector<std::string>{"inner"}}), "");
  EXPECT_EQ(lc::lua::nearest("iner", disk), "inner");
  EXPECT_EQ(lc::lua::nearest("inner_radius", disk), "inner");
  EXPECT_EQ(lc::lua::nearest("frame_count", {std::vector<std::string>{"fps", "frames"}}), "frames");
  EXPECT_EQ(lc::lua::nearest("colour", {std::vector<std::string>{"colors"}}), "colors");
  EXPECT_EQ(lc::lua::nearest("rotation", {std::vector<std::string>{"rotate"}}), "rotate");
  EXPECT_EQ(lc::lua::nearest("cam", {std::vector<std::string>{"camera"}}), "");  // a prefix of 3 says little
  EXPECT_EQ(lc::lua::nearest("sectorz", disk), "sectors");  // a near spelling beats a shared beginning
  EXPECT_EQ(lc::lua::nearest(std::string(100, 'k') + "x", {std::vector<std::string>{std::string(100, 'k')}}), "");
}

}  // namespace
