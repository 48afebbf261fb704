// One field list per struct, read by every document that carries the struct: a writer picks its
// fields by member (add), the internal codec writes and reads them all (write_all, read_all), so a
// field's JSON name is spelled once, in the struct's FieldList specialisation (run_report_json.cpp).
// A struct joins by specialising FieldList<T> with `static constexpr auto list = std::make_tuple(...)`.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <typeinfo>
#include <vector>

#include <nlohmann/json.hpp>

namespace rc::fields {

template <class T>
struct FieldList;  // specialised per struct: `list`, a tuple of the entries below

// A member under its name.
template <class T, class M>
struct Field {
  const char* name;
  M T::*member;
};
template <class T, class M>
constexpr Field<T, M> field(const char* name, M T::*member) {
  return {name, member};
}

// A flag written as one of two words ("static" / "dynamic").
template <class T>
struct WordField {
  const char* name;
  bool T::*member;
  const char* yes;
  const char* no;
};
template <class T>
constexpr WordField<T> word(const char* name, bool T::*member, const char* yes, const char* no) {
  return {name, member, yes, no};
}

// A value computed from the other fields: written, never read back.
template <class T, class R>
struct DerivedField {
  const char* name;
  R (T::*member)() const;
};
template <class T, class R>
constexpr DerivedField<T, R> derived(const char* name, R (T::*member)() const) {
  return {name, member};
}

// An array indexed by an enum, written as an object keyed by to_string(Kind(k)).
template <class Kind, class T, class E, std::size_t N>
struct TallyField {
  const char* name;
  std::array<E, N> T::*member;
};
template <class Kind, class T, class E, std::size_t N>
constexpr TallyField<Kind, T, E, N> tallies(const char* name, std::array<E, N> T::*member) {
  return {name, member};
}

template <class T, class = void>
struct HasFields : std::false_type {};
template <class T>
struct HasFields<T, std::void_t<decltype(FieldList<T>::list)>> : std::true_type {};
template <class T>
struct IsVector : std::false_type {};
template <class E>
struct IsVector<std::vector<E>> : std::true_type {};
template <class T>
struct IsOptional : std::false_type {};
template <class E>
struct IsOptional<std::optional<E>> : std::true_type {};

template <class J, class T>
J write_all(const T& value);
template <class T>
void read_all(const nlohmann::json& j, T& value);

template <class J, class X>
J out(const X& x) {
  if constexpr (HasFields<X>::value) {
    return write_all<J>(x);
  } else if constexpr (IsVector<X>::value) {
    J a = J::array();
    for (const auto& e : x) a.push_back(out<J>(e));
    return a;
  } else if constexpr (IsOptional<X>::value) {
    return x ? out<J>(*x) : J();
  } else {
    return J(x);
  }
}

template <class X>
void in(const nlohmann::json& j, X& x) {
  if constexpr (HasFields<X>::value) {
    read_all(j, x);
  } else if constexpr (IsVector<X>::value) {
    x.clear();
    for (const auto& e : j) in(e, x.emplace_back());
  } else if constexpr (IsOptional<X>::value) {
    if (j.is_null()) {
      x.reset();
    } else {
      in(j, x.emplace());
    }
  } else {
    x = j.get<X>();
  }
}

template <class J, class T, class M>
void put(J& j, const T& v, const Field<T, M>& f) {
  j[f.name] = out<J>(v.*f.member);
}
template <class J, class T>
void put(J& j, const T& v, const WordField<T>& f) {
  j[f.name] = v.*f.member ? f.yes : f.no;
}
template <class J, class T, class R>
void put(J& j, const T& v, const DerivedField<T, R>& f) {
  j[f.name] = (v.*f.member)();
}
template <class J, class Kind, class T, class E, std::size_t N>
void put(J& j, const T& v, const TallyField<Kind, T, E, N>& f) {
  J o = J::object();
  for (std::size_t k = 0; k < N; ++k) o[to_string(Kind(k))] = out<J>((v.*f.member)[k]);
  j[f.name] = o;
}

template <class T, class M>
void take(const nlohmann::json& j, T& v, const Field<T, M>& f) {
  in(j.at(f.name), v.*f.member);
}
template <class T>
void take(const nlohmann::json& j, T& v, const WordField<T>& f) {
  const std::string w = j.at(f.name).template get<std::string>();
  if (w != f.yes && w != f.no) {
    throw std::invalid_argument(std::string("\"") + f.name + "\" is \"" + w + "\", not \"" + f.yes + "\" or \"" + f.no + "\"");
  }
  v.*f.member = w == f.yes;
}
template <class T, class R>
void take(const nlohmann::json&, T&, const DerivedField<T, R>&) {}
template <class Kind, class T, class E, std::size_t N>
void take(const nlohmann::json& j, T& v, const TallyField<Kind, T, E, N>& f) {
  const nlohmann::json& o = j.at(f.name);
  for (std::size_t k = 0; k < N; ++k) in(o.at(to_string(Kind(k))), (v.*f.member)[k]);
}

template <class J, class T>
J write_all(const T& value) {
  J j = J::object();
  std::apply([&](const auto&... f) { (put(j, value, f), ...); }, FieldList<T>::list);
  return j;
}

template <class T>
void read_all(const nlohmann::json& j, T& value) {
  std::apply([&](const auto&... f) { (take(j, value, f), ...); }, FieldList<T>::list);
}

// The entry of a list that holds `member`, written into j (found: whether it was there).
template <class J, class T, class F, class P>
void put_if(J& j, const T& value, const F& f, P member, bool& found) {
  if constexpr (std::is_same_v<std::decay_t<decltype(f.member)>, P>) {
    if (!found && f.member == member) {
      put(j, value, f);
      found = true;
    }
  }
}

template <class F, class P>
void name_if(const F& f, P member, const char*& name) {
  if constexpr (std::is_same_v<std::decay_t<decltype(f.member)>, P>) {
    if (!name && f.member == member) name = f.name;
  }
}

// Writes into j the fields of `value` that hold the given members, in that order, under their names.
template <class J, class T, class... P>
void add(J& j, const T& value, P... members) {
  auto one = [&](auto member) {
    bool found = false;
    std::apply([&](const auto&... f) { (put_if(j, value, f, member, found), ...); }, FieldList<T>::list);
    if (!found) throw std::logic_error(std::string("a member without a field in its FieldList: ") + typeid(member).name());
  };
  (one(members), ...);
}

// The name a member is written under.
template <class T, class P>
const char* name_of(P member) {
  const char* name = nullptr;
  std::apply([&](const auto&... f) { (name_if(f, member, name), ...); }, FieldList<T>::list);
  if (!name) throw std::logic_error(std::string("a member without a field in its FieldList: ") + typeid(member).name());
  return name;
}

}  // namespace rc::fields
