#pragma once
// How a task's result reads in the timeline, in summaries and in failure messages: printable().

#include "frob/fwd.hpp"
#include "frob/geometry.hpp"

#include <optional>
#include <ostream>
#include <ranges>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

namespace frob::detail {

namespace print {
// Matches an enum exactly, so that `os << v` picks it over the enum's promotion to int or char,
// but loses to an operator<< the enum's author wrote (a function beats a template). Never defined.
struct NoOperator {};
template <class E>
  requires std::is_enum_v<E>
NoOperator operator<<(std::ostream&, const E&);
// A value with an operator<< of its own (or the standard one of a number or string).
template <class R>
concept Streamable = requires(std::ostream& os, const R& v) {
  { os << v } -> std::same_as<std::ostream&>;
};
// "a, b, c"; at most the first eight, then "...".
[[nodiscard]] std::string joined(const std::vector<std::string>& items);
}  // namespace print

// "frob::Wheels" from the signature of typeName<frob::Wheels>() (its __PRETTY_FUNCTION__).
[[nodiscard]] std::string typeNameIn(std::string_view signature);
template <class T>
std::string typeName() {
  return typeNameIn(__PRETTY_FUNCTION__);
}

// Printable form of a task's result for the timeline and summaries, as the value reads: its
// operator<< (a bool as true or false), its toString; else, for the usual std types, what they hold
// (an optional's value or "none", "(a, b)" for a pair or tuple, "[a, b]" for a container, a
// variant's value, a point's "(x, y)"), a withTask Outcome as "returned X" or "failed: why", an
// enum's type and number "Side(1)", else the type's name.
template <class R>
std::string printable(const R& v) {
  if constexpr (std::is_same_v<R, Unit>) {
    return "";
  } else if constexpr (std::is_base_of_v<Eigen::DenseBase<R>, R>) {  // Eigen's own << writes a column
    std::string out = "(";
    for (Eigen::Index k = 0; k < v.size(); ++k) out += (k == 0 ? "" : ", ") + printable(v(k));
    return out + ")";
  } else if constexpr (print::Streamable<R>) {
    std::ostringstream os;
    os << std::boolalpha << v;
    return os.str();
  } else if constexpr (requires { toString(v); }) {
    return toString(v);
  } else if constexpr (requires {
                         v.has_value();
                         *v;
                       }) {
    return v.has_value() ? printable(*v) : std::string("none");
  } else if constexpr (requires {
                         v.ok();
                         v.value;
                         v.error->what();
                       }) {
    if (!v.ok()) return "failed: " + std::string(v.error ? v.error->what() : "");
    const std::string value = v.value ? printable(*v.value) : "";
    return value.empty() ? "returned" : "returned " + value;
  } else if constexpr (requires { std::tuple_size<R>::value; }) {
    return std::apply([](const auto&... x) { return "(" + print::joined({printable(x)...}) + ")"; }, v);
  } else if constexpr (requires { std::variant_size<R>::value; }) {
    return std::visit([](const auto& x) { return printable(x); }, v);
  } else if constexpr (std::ranges::input_range<const R>) {
    std::vector<std::string> items;
    for (const auto& x : v) items.push_back(printable(x));
    return "[" + print::joined(items) + "]";
  } else if constexpr (std::is_enum_v<R>) {
    return typeName<R>() + "(" + std::to_string(static_cast<long long>(v)) + ")";
  } else {
    return typeName<R>();
  }
}

}  // namespace frob::detail
