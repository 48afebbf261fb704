// A choice named in text (a visibility backend, a card split, a form factor, ...) is an enum inside
// the program; its names live in one list, beside the enum, and are parsed and printed here only, so
// adding a choice is one edit to that list (and the switch the compiler then asks for).
//
// Beside each choice enum E, in enum order:
//   template <> struct ChoiceNames<E> {
//     static constexpr std::string_view what = "card split";                  // for error messages
//     static constexpr std::array<std::string_view, 2> names = {"rays", "faces"};
//   };
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rc {

template <class E>
struct ChoiceNames;

// The name of `value` (its enum order in ChoiceNames<E>::names).
template <class E>
std::string choice_name(E value) {
  return std::string(ChoiceNames<E>::names.at(static_cast<std::size_t>(value)));
}

// Every name, in enum order: what a command-line option accepts.
template <class E>
std::vector<std::string> choice_names() {
  return {ChoiceNames<E>::names.begin(), ChoiceNames<E>::names.end()};
}

// "a, b, c": the names, for messages and help texts.
template <class E>
std::string choice_name_list() {
  std::string list;
  for (std::string_view name : ChoiceNames<E>::names) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
}

// The choice named `text`, if one is (the lookup both parsers below share).
template <class E>
std::optional<E> find_choice(std::string_view text) {
  const auto& names = ChoiceNames<E>::names;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == text) return static_cast<E>(i);
  }
  return std::nullopt;
}

// The choice named `text`; std::invalid_argument naming the text and every name otherwise.
template <class E>
E parse_choice(std::string_view text) {
  if (const std::optional<E> value = find_choice<E>(text)) return *value;
  throw std::invalid_argument(std::string(ChoiceNames<E>::what) + " '" + std::string(text) +
                              "' is not one of: " + choice_name_list<E>());
}

// `option` NAME parsed as a choice, refused in CLI11's words for a name outside the list ("--resources:
// yosys not in {paper,synthesis}", what the command line's add_choice_option says): for front ends that
// check the same option without CLI11 (the Python module). Throws std::invalid_argument.
template <class E>
E parse_choice_option(const std::string& option, std::string_view text) {
  if (const std::optional<E> value = find_choice<E>(text)) return *value;
  std::string list;
  for (std::string_view name : ChoiceNames<E>::names) list += (list.empty() ? "" : ",") + std::string(name);
  throw std::invalid_argument(option + ": " + std::string(text) + " not in {" + list + "}");
}

// Each of `texts` parsed (parse_choice), in order.
template <class E>
std::vector<E> parse_choices(const std::vector<std::string>& texts) {
  std::vector<E> values;
  for (const std::string& text : texts) values.push_back(parse_choice<E>(text));
  return values;
}

// The names of `values`, in order.
template <class E>
std::vector<std::string> choice_name_vector(const std::vector<E>& values) {
  std::vector<std::string> names;
  for (E value : values) names.push_back(choice_name(value));
  return names;
}

}  // namespace rc
