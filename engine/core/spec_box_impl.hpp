#pragma once
// SpecBox's members and kind_name/key/json (core/spec_box.hpp), for the one
// file beside each list that instantiates them, where the list's variant
// is complete:
//   template class SpecBox<CameraSpecKinds>;
//   template struct SpecAccess<CameraSpecKinds, PinholeParams>;  // one per kind

#include <utility>
#include <variant>

#include "core/spec_box.hpp"

namespace lc {

template <class Kinds, class P>
Kinds* SpecAccess<Kinds, P>::make(const P& params) {
  return new Kinds(params);
}

template <class Kinds, class P>
P* SpecAccess<Kinds, P>::find(Kinds& kinds) {
  return std::get_if<P>(&kinds);
}

template <class Kinds>
SpecBox<Kinds>::SpecBox() : kinds_(std::make_unique<Kinds>()) {}

template <class Kinds>
SpecBox<Kinds>::SpecBox(const Kinds& kinds) : kinds_(std::make_unique<Kinds>(kinds)) {}

template <class Kinds>
SpecBox<Kinds>::SpecBox(Adopt made) : kinds_(made.kinds) {}

template <class Kinds>
SpecBox<Kinds>::SpecBox(const SpecBox& other) : kinds_(std::make_unique<Kinds>(*other.kinds_)) {}

template <class Kinds>
SpecBox<Kinds>::SpecBox(SpecBox&& other) noexcept = default;

template <class Kinds>
SpecBox<Kinds>& SpecBox<Kinds>::operator=(const SpecBox& other) {
  if (this != &other) kinds_ = std::make_unique<Kinds>(*other.kinds_);
  return *this;
}

template <class Kinds>
SpecBox<Kinds>& SpecBox<Kinds>::operator=(SpecBox&& other) noexcept = default;

template <class Kinds>
SpecBox<Kinds>::~SpecBox() = default;

template <class Kinds>
std::size_t SpecBox<Kinds>::index() const {
  return kinds_->index();
}

template <class Kinds>
std::string_view kind_name(const SpecBox<Kinds>& spec) {
  return Kinds::Specs::name(spec.kinds());
}

template <class Kinds>
std::string kind_key(const SpecBox<Kinds>& spec) {
  return Kinds::Specs::key(spec.kinds());
}

template <class Kinds>
std::string kind_json(const SpecBox<Kinds>& spec, bool polar) {
  return Kinds::Specs::json(spec.kinds(), polar);
}

}  // namespace lc
