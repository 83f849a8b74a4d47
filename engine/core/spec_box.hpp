#pragma once
// SpecBox<Kinds>: what a shot gave for one kind of a registry (a camera's
// parameters, say), held where the files that only keep, copy or pass a
// spec on need not see the registry's list.  `Kinds` is a struct deriving
// from the variant of every kind's Params; here it is only declared, so a
// new kind rebuilds the files that include its list and not every file
// that holds a scene (docs/architecture.md, "What a new kind rebuilds").
//
// Where the list is included (core/spec_box_impl.hpp and the registry's
// own list header) a box gives its variant, kinds(), to std::visit.  Where
// it is not, a box is made from one kind's Params and that kind read back
// with get<P>() / get_if<P>(): those go through SpecAccess<Kinds, P>,
// explicitly instantiated once per kind beside the list (camera/camera_spec.cpp).

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace lc {

// What a box does with kind P's parameters, made where the list is seen.
template <class Kinds, class P>
struct SpecAccess {
  // A new variant holding `params`, for the box to adopt: a raw pointer,
  // so that no unique_ptr of the incomplete variant is destroyed where the
  // box is made.
  static Kinds* make(const P& params);
  static P* find(Kinds& kinds);  // nullptr: the box holds another kind
};

template <class Kinds>
class SpecBox {
 public:
  SpecBox();  // the list's first kind, with its defaults
  SpecBox(const Kinds& kinds);
  template <class P>
    requires(!std::is_same_v<P, SpecBox> && !std::is_same_v<P, Kinds>)
  SpecBox(const P& params) : SpecBox(Adopt{SpecAccess<Kinds, P>::make(params)}) {}
  SpecBox(const SpecBox& other);
  SpecBox(SpecBox&& other) noexcept;
  SpecBox& operator=(const SpecBox& other);
  SpecBox& operator=(SpecBox&& other) noexcept;
  ~SpecBox();

  // The variant itself: for what visits every kind (needs the list).
  const Kinds& kinds() const { return *kinds_; }
  Kinds& kinds() { return *kinds_; }
  // Which kind, as the list numbers them.
  std::size_t index() const;

  // Kind P's parameters, if the box holds that kind.
  template <class P>
  P* get_if() {
    return SpecAccess<Kinds, P>::find(*kinds_);
  }
  template <class P>
  const P* get_if() const {
    return SpecAccess<Kinds, P>::find(*kinds_);
  }
  // Kind P's parameters; throws std::bad_variant_access if it holds another.
  template <class P>
  P& get() {
    return checked(get_if<P>());
  }
  template <class P>
  const P& get() const {
    return checked(get_if<P>());
  }

 private:
  struct Adopt {
    Kinds* kinds;
  };
  explicit SpecBox(Adopt made);
  template <class P>
  static P& checked(P* p) {
    if (!p) throw std::bad_variant_access();
    return *p;
  }
  // Null only in a moved-from box, which may only be assigned or destroyed.
  std::unique_ptr<Kinds> kinds_;
};

// Its kind's name (its Lua constructor's), "name field=value ..." exactly
// (core/registry.hpp, spec_key) and {"kind": "name", <each field>: value}
// (polar: whether the scene's positions are polar, for a field holding
// one), for a box whose list is a SpecRegistry (Kinds::Specs); compiled
// beside the list (core/spec_box_impl.hpp).
template <class Kinds>
std::string_view kind_name(const SpecBox<Kinds>& spec);
template <class Kinds>
std::string kind_key(const SpecBox<Kinds>& spec);
template <class Kinds>
std::string kind_json(const SpecBox<Kinds>& spec, bool polar = false);

}  // namespace lc
