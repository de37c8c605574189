#pragma once
// A family's settings as one table: for every user setting its key, kind, range, help and the
// member it lives in. Defaults are the settings struct's own member initializers, read from a
// default-constructed struct, so each default is written once, in the struct. Everything else a
// setting needs comes from the table: validation (C++), parsing "key=value" text (CLI, scene files,
// the method registry, through io/TextNumbers), PrintSelf, --help, and what the Python and ParaView
// layers expose.
//
//   const Schema<ObscuranceSettings>& obscuranceSchema() {
//     static const Schema<ObscuranceSettings> s = [] {
//       using S = ObscuranceSettings;
//       Schema<S> t("obscurance");
//       t.integer("samples", &S::samples, 1, 64, "rays per pixel");
//       return t;
//     }();
//     return s;
//   }
//
// Members are reached by a member pointer or by a generic lambda, `[](auto& s) -> auto& { return
// s.common.radius; }`, which serves const and non-const structs alike; a sub-struct's table is
// included with include().
#include <algorithm>
#include <functional>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/TextNumbers.h"
#include "settings/SettingInfo.h"

namespace aokit {

// A rule between settings that no single range says ("combine=cone needs kind=cube").
template <class S>
struct SettingRule {
  std::function<bool(const S&)> holds;
  std::string message;  // said after "<family>: " when it does not hold
};

// The type of the member an accessor (member pointer or generic lambda) reaches in an S.
template <class S, class A>
struct MemberType {
  using type = std::decay_t<decltype(std::declval<A&>()(std::declval<S&>()))>;
};
template <class S, class T>
struct MemberType<S, T S::*> {
  using type = T;
};

template <class S>
class Schema {
 public:
  struct Entry {
    SettingInfo info;
    std::function<std::string(const S&)> get;                  // the value as text
    std::function<bool(S&, const std::string&)> set;           // false: not a valid value
    std::function<std::optional<std::string>(const S&)> check;  // the value's text when out of range
  };

  explicit Schema(std::string family) : family_(std::move(family)) {}

  const std::string& family() const { return family_; }
  const std::vector<Entry>& entries() const { return entries_; }
  std::vector<SettingInfo> infos() const {
    std::vector<SettingInfo> out;
    for (const Entry& e : entries_) out.push_back(e.info);
    return out;
  }

  // --- building the table -------------------------------------------------------------------

  // An integer member (int, unsigned, ...) in [lo, hi]; zeroMeans: 0 is accepted too and means
  // that; zeroWord: a word for that 0 in text ("auto").
  template <class A>
  Schema& integer(std::string key, A member, long long lo, long long hi, std::string help, std::string zeroMeans = "",
                  std::string zeroWord = "") {
    SettingInfo i = info(std::move(key), SettingKind::Integer, std::move(help));
    i.range = Interval::closed(static_cast<double>(lo), static_cast<double>(hi));
    i.zeroMeans = std::move(zeroMeans);
    i.zeroWord = zeroWord;
    const auto at = access(member);
    add(std::move(i),
        [at, word = std::move(zeroWord)](const S& s) {
          const long long v = static_cast<long long>(at(s));
          return v == 0 && !word.empty() ? word : std::to_string(v);
        },
        [at](S& s, const std::string& text, const SettingInfo& si) {
          long long v = 0;
          if (!(text == si.zeroWord && !text.empty()) && (!parseIntegerSetting(text, v) || !si.accepts(static_cast<double>(v))))
            return false;
          at(s) = static_cast<std::decay_t<decltype(at(s))>>(v);
          return true;
        },
        [at](const S& s, const SettingInfo& si) { return si.accepts(static_cast<double>(at(s))); });
    return *this;
  }

  // A double member in `range`; zeroMeans as for integer().
  template <class A>
  Schema& number(std::string key, A member, Interval range, std::string help, std::string zeroMeans = "") {
    SettingInfo i = info(std::move(key), SettingKind::Number, std::move(help));
    i.range = range;
    i.zeroMeans = std::move(zeroMeans);
    const auto at = access(member);
    add(std::move(i), [at](const S& s) { return numberText(at(s)); },
        [at](S& s, const std::string& text, const SettingInfo& si) {
          double v = 0.0;
          if (!parseNumberSetting(text, v) || !si.accepts(v)) return false;
          at(s) = v;
          return true;
        },
        [at](const S& s, const SettingInfo& si) { return si.accepts(at(s)); });
    return *this;
  }

  // A bool member: 0/1, off/on, false/true.
  template <class A>
  Schema& flag(std::string key, A member, std::string help) {
    SettingInfo i = info(std::move(key), SettingKind::Flag, std::move(help));
    const auto at = access(member);
    add(std::move(i), [at](const S& s) { return std::string(at(s) ? "1" : "0"); },
        [at](S& s, const std::string& text, const SettingInfo&) {
          bool v = false;
          if (!parseFlagSetting(text, v)) return false;
          at(s) = v;
          return true;
        },
        [](const S&, const SettingInfo&) { return true; });
    return *this;
  }

  // A member of any comparable type (an enum, an optional, a number) that takes the listed values
  // by name; a value outside the list fails validation.
  template <class A, class T = typename MemberType<S, A>::type>
  Schema& choice(std::string key, A member, std::vector<std::pair<std::string, typename MemberType<S, A>::type>> names,
                 std::string help) {
    SettingInfo i = info(std::move(key), SettingKind::Choice, std::move(help));
    for (const auto& n : names) i.choices.push_back(n.first);
    const auto at = access(member);
    auto find = [names](const T& v) -> const std::string* {
      for (const auto& n : names)
        if (n.second == v) return &n.first;
      return nullptr;
    };
    add(std::move(i),
        [at, find](const S& s) {
          const std::string* name = find(at(s));
          return name ? *name : std::string("(none of them)");
        },
        [at, names](S& s, const std::string& text, const SettingInfo&) {
          for (const auto& n : names)
            if (n.first == text) {
              at(s) = n.second;
              return true;
            }
          return false;
        },
        [at, find](const S& s, const SettingInfo&) { return find(at(s)) != nullptr; });
    return *this;
  }

  // A string member, any text without ',' (a folder, a file). The word "empty" stands for the
  // empty text, as help and listings print an empty default.
  template <class A>
  Schema& text(std::string key, A member, std::string help) {
    SettingInfo i = info(std::move(key), SettingKind::Text, std::move(help));
    const auto at = access(member);
    add(std::move(i), [at](const S& s) { return std::string(at(s)); },
        [at](S& s, const std::string& t, const SettingInfo&) {
          at(s) = t == "empty" ? std::string() : t;
          return true;
        },
        [](const S&, const SettingInfo&) { return true; });
    return *this;
  }

  // Every entry and rule of a sub-struct's table, reached through `member` (its keys unchanged),
  // but the keys in `except` (which this table spells its own way).
  template <class T, class A>
  Schema& include(const Schema<T>& sub, A member, const std::vector<std::string>& except = {}) {
    const auto at = access(member);
    for (const auto& e : sub.entries()) {
      if (std::find(except.begin(), except.end(), e.info.key) != except.end()) continue;
      if (find(e.info.key)) throw std::logic_error(family_ + ": setting '" + e.info.key + "' is listed twice");
      Entry mine;
      mine.info = e.info;
      mine.get = [at, g = e.get](const S& s) { return g(at(s)); };
      mine.set = [at, f = e.set](S& s, const std::string& t) { return f(at(s), t); };
      mine.check = [at, c = e.check](const S& s) { return c(at(s)); };
      entries_.push_back(std::move(mine));
    }
    for (const auto& r : sub.rules()) rule([at, h = r.holds](const S& s) { return h(at(s)); }, r.message);
    refreshDefaults();
    return *this;
  }

  Schema& rule(std::function<bool(const S&)> holds, std::string message) {
    rules_.push_back({std::move(holds), std::move(message)});
    return *this;
  }
  const std::vector<SettingRule<S>>& rules() const { return rules_; }

  // --- using it -----------------------------------------------------------------------------

  const Entry* find(const std::string& key) const {
    for (const Entry& e : entries_)
      if (e.info.key == key) return &e;
    return nullptr;
  }
  const Entry& entry(const std::string& key) const {
    if (const Entry* e = find(key)) return *e;
    std::vector<std::string> keys;
    for (const Entry& e : entries_) keys.push_back(e.info.key);
    throw std::invalid_argument(unknownSettingMessage(family_, key, keys));
  }

  // Sets one setting from text. Throws std::invalid_argument, one line: "obscurance: samples must
  // be an integer in 1..64, got '0'", or naming an unknown key and the known ones.
  void set(S& s, const std::string& key, const std::string& value) const {
    const Entry& e = entry(key);
    if (!e.set(s, value)) throw std::invalid_argument(family_ + ": " + key + " must be " + e.info.rangeText() + ", got '" + printable(value) + "'");
  }
  std::string get(const S& s, const std::string& key) const { return entry(key).get(s); }

  // Every range, then every rule. Throws std::invalid_argument with one line naming the key.
  void validate(const S& s) const {
    for (const Entry& e : entries_)
      if (auto bad = e.check(s))
        throw std::invalid_argument(family_ + ": " + e.info.key + " must be " + e.info.rangeText() + ", got " + *bad);
    for (const auto& r : rules_)
      if (!r.holds(s)) throw std::invalid_argument(family_ + ": " + r.message);
  }

  // A default struct with `values` applied in key order, validated.
  S parse(const SettingMap& values) const {
    S s{};
    for (const auto& [key, value] : values) set(s, key, value);
    validate(s);
    return s;
  }

  // "  key: help; range (default d)" lines, one per setting.
  std::string help() const { return settingsHelpText(infos()); }
  // "key = value" lines (PrintSelf: indent is a vtkIndent, or any text).
  template <class Indent>
  void print(std::ostream& os, const S& s, const Indent& indent) const {
    for (const Entry& e : entries_) os << indent << e.info.key << " = " << e.get(s) << "\n";
  }

 private:
  template <class A>
  static auto access(A member) {
    if constexpr (std::is_member_object_pointer_v<A>) {
      return [member](auto& s) -> auto& { return s.*member; };
    } else {
      return member;
    }
  }

  SettingInfo info(std::string key, SettingKind kind, std::string help) const {
    if (find(key)) throw std::logic_error(family_ + ": setting '" + key + "' is listed twice");
    SettingInfo i;
    i.key = std::move(key);
    i.kind = kind;
    i.help = std::move(help);
    return i;
  }

  template <class Get, class Set, class Check>
  void add(SettingInfo i, Get get, Set set, Check check) {
    Entry e;
    e.get = get;
    e.set = [set, i](S& s, const std::string& t) { return set(s, t, i); };
    e.check = [get, check, i](const S& s) -> std::optional<std::string> {
      if (check(s, i)) return std::nullopt;
      return get(s);
    };
    e.info = std::move(i);
    entries_.push_back(std::move(e));
    refreshDefaults();
  }

  void refreshDefaults() {
    const S defaults{};
    for (Entry& e : entries_) {
      e.info.defaultText = e.get(defaults);
      if (e.info.defaultText.empty()) e.info.defaultText = "empty";
    }
  }

  std::string family_;
  std::vector<Entry> entries_;
  std::vector<SettingRule<S>> rules_;
};

}  // namespace aokit
