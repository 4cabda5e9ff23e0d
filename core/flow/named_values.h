// An enum's values with their names, as one table per enum: parse a name, name a value, list
// the names. The readers, the CLI and the window's choices all take an enum's names from its
// one table, so a name is spelled once. Plain C++ (no GLM): it sits in core's lowest folder so
// that every folder of core may include it.
#pragma once

#include <cstddef>
#include <string>

namespace oflab {

// One value of an enum and the name a person types for it ("bilinear").
template <typename Enum>
struct NamedValue {
  Enum value;
  const char* name;
};

// True and `*value` set when `text` is one of `table`'s names (exact, case-sensitive);
// false and `*value` unchanged otherwise. Precondition: `value` is not null.
template <typename Enum, std::size_t N>
bool parse_named_value(const NamedValue<Enum> (&table)[N], const std::string& text, Enum* value) {
  for (const NamedValue<Enum>& entry : table) {
    if (text != entry.name) continue;
    *value = entry.value;
    return true;
  }
  return false;
}

// The name of `value` in `table`, or `otherwise` when the table does not hold it (a value
// cast from an out-of-range integer).
template <typename Enum, std::size_t N>
const char* name_of_value(const NamedValue<Enum> (&table)[N], Enum value, const char* otherwise) {
  for (const NamedValue<Enum>& entry : table) {
    if (entry.value == value) return entry.name;
  }
  return otherwise;
}

// Every name of `table` in its order, joined by `separator` ("nearest, bilinear, mipmap").
template <typename Enum, std::size_t N>
std::string named_value_list(const NamedValue<Enum> (&table)[N], const std::string& separator) {
  std::string list;
  for (const NamedValue<Enum>& entry : table) {
    list += (list.empty() ? "" : separator) + std::string(entry.name);
  }
  return list;
}

}  // namespace oflab
