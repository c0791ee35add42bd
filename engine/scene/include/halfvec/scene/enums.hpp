// String names for every enum in scene.hpp, as used by scene files (docs/scene-format.md), the UI
// and the stats output. Names are lower_snake_case; each enum's values are contiguous from 0, so
// the tables below are indexed by the underlying value.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "halfvec/scene/scene.hpp"

namespace hv {

// EnumNames<E> (declared in render_settings.hpp, specialised there for the settings' enums and
// below for the others): static constexpr std::array<std::string_view, N> names.

#define HV_ENUM_NAMES(E, ...)                                                           \
  template <>                                                                           \
  struct EnumNames<E> {                                                                 \
    static constexpr std::array names = std::to_array<std::string_view>({__VA_ARGS__}); \
  }

HV_ENUM_NAMES(ShadingModel, "background", "unlit", "default_lit", "clear_coat");
HV_ENUM_NAMES(Wrap, "repeat", "clamp_to_edge", "mirrored_repeat");
HV_ENUM_NAMES(Filter, "nearest", "linear");
HV_ENUM_NAMES(AlphaMode, "opaque", "mask", "blend");
HV_ENUM_NAMES(LightType, "point", "sphere", "tube", "spot", "directional");
HV_ENUM_NAMES(EnvironmentKind, "none", "uniform", "sky", "hdr");

#undef HV_ENUM_NAMES

// All names of E, in value order.
template <class E>
constexpr std::span<const std::string_view> enumNames() {
  return EnumNames<E>::names;
}

// The name of e; "?" for a value outside the enum.
template <class E>
constexpr std::string_view toString(E e) {
  const auto i = static_cast<std::size_t>(e);
  return i < EnumNames<E>::names.size() ? EnumNames<E>::names[i] : std::string_view("?");
}

// The value named s (exact, case-sensitive match); nullopt if none.
template <class E>
constexpr std::optional<E> fromString(std::string_view s) {
  for (std::size_t i = 0; i < EnumNames<E>::names.size(); ++i) {
    if (EnumNames<E>::names[i] == s) return static_cast<E>(i);
  }
  return std::nullopt;
}

// "a", "b" or "c": the names of E for error messages.
std::string joinNames(std::span<const std::string_view> names);
template <class E>
std::string enumNamesJoined() {
  return joinNames(enumNames<E>());
}

}  // namespace hv
