// The option lists a sweep takes (`rc2000sim sweep`, study files): integer lists with ranges, name
// lists, choice lists, the driver and the steps policy, each parsed in one place.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "io/choice.h"

namespace rc {

// "1-16", "5,6,8-12", "15": the values listed, ascending and distinct (so the sweep's order never
// depends on how the list was spelt). Throws std::invalid_argument naming `option` for an empty
// list or item, a non-number, a reversed range and a value outside [min, max].
std::vector<int> parse_int_list(const std::string& text, const std::string& option, int min, int max);

// "a,b,c": the names in the order given, repeats dropped. Throws for an empty list or name.
std::vector<std::string> parse_name_list(const std::string& text, const std::string& option);
// "rays,faces" -> the choices (io/choice.h); an unknown name is an error naming `option`.
template <class E>
std::vector<E> parse_choice_list(const std::string& text, const std::string& option) {
  try {
    return parse_choices<E>(parse_name_list(text, option));
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    throw std::invalid_argument(what.rfind(option, 0) == 0 ? what : option + ": " + what);
  }
}

// "off" (serial driver), "on" (concurrent driver, paper sec 4.3) or "both" (serial first).
std::vector<bool> parse_concurrency(const std::string& text);

// How many shooting steps every configuration replays.
struct StepsChoice {
  enum class Kind {
    paper,     // the paper's Table 2 count for a paper scene (its faces and patches); else converge
    converge,  // the steps our solver needs to reach the convergence target (per width)
    fixed,     // exactly `steps`
  };
  Kind kind = Kind::paper;
  int steps = 0;
};
// "paper", "converge" or a positive step count: the one parser of a steps policy (the command line,
// study files and the resolved study's JSON all read it here); to_string gives the text back.
StepsChoice parse_steps(const std::string& text);
std::string to_string(const StepsChoice& steps);

}  // namespace rc
