// The window state's field table (session/state/state_fields.h): the writer, the reader, the
// equality, the schema handed to the browser page and the manual's table all list exactly
// the table's fields.
#include "state/state_fields.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "state/window_state_file.h"

namespace oflab {
namespace {

using nlohmann::json;

std::set<std::string> table_paths() {
  std::set<std::string> paths;
  for (const StateField& field : state_fields()) paths.insert(field.path);
  return paths;
}

// The dotted paths of the leaves of `j` (objects are parts; anything else is a value).
void leaf_paths(const json& j, const std::string& prefix, std::set<std::string>* out) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string path = prefix + it.key();
    if (it.value().is_object()) {
      leaf_paths(it.value(), path + ".", out);
    } else {
      out->insert(path);
    }
  }
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SessionError& e) {
    return e.what();
  }
  return "";
}

// A valid value of `field` other than `value`, of the same JSON type.
json another_value(const StateField& field, const json& value) {
  if (value.is_boolean()) return !value.get<bool>();
  if (value.is_number())
    return value.get<double>() == 0.0 ? json(1) : json(value.get<double>() * 2);
  if (value.is_string() && field.range.rfind("one of ", 0) == 0) {
    std::stringstream names(field.range.substr(7));
    std::string name;
    while (std::getline(names, name, ',')) {
      name.erase(0, name.find_first_not_of(' '));
      if (name != value.get<std::string>()) return name;
    }
  }
  if (value.is_string()) return value.get<std::string>() + "x";
  json changed = value;
  if (changed.size() > 0 && changed[0].is_number()) changed[0] = changed[0].get<double>() + 1.0;
  if (changed.size() > 0 && changed[0].is_string()) changed = json::array({"exact"});
  return changed;
}

TEST(StateFields, TheWriterWritesExactlyTheTablesFields) {
  std::set<std::string> written;
  leaf_paths(window_state_object(WindowState()), "", &written);
  EXPECT_EQ(written, table_paths());
  EXPECT_EQ(written.size(), state_fields().size()) << "each path once";
}

TEST(StateFields, TheReaderTakesEveryFieldAndRefusesAnyOther) {
  const json object = window_state_object(WindowState());
  EXPECT_TRUE(read_window_state_object(object, "s.json", "", WindowState()) == WindowState());
  // An unknown member at every part the table has is refused, naming it and the part.
  std::set<std::string> parts = {""};
  for (const std::string& path : table_paths()) {
    for (size_t dot = path.find('.'); dot != std::string::npos; dot = path.find('.', dot + 1)) {
      parts.insert(path.substr(0, dot));
    }
  }
  for (const std::string& part : parts) {
    json edited = object;
    json& at = part.empty() ? edited : edited[json::json_pointer("/" + [&] {
      std::string p = part;
      std::replace(p.begin(), p.end(), '.', '/');
      return p;
    }())];
    at["misspelt"] = 1;
    const std::string error =
        error_of([&] { read_window_state_object(edited, "s.json", "", WindowState()); });
    const std::string expected =
        "s.json: " + (part.empty() ? "" : part + ": ") + "field 'misspelt': unknown field";
    EXPECT_EQ(error.rfind(expected, 0), 0u) << error;
  }
}

TEST(StateFields, EqualityAndEachFieldsReadAndWriteCoverEveryField) {
  const WindowState base;
  for (const StateField& field : state_fields()) {
    const json value = another_value(field, field.get(base));
    WindowState changed = base;
    field.set(value, {"s.json", ""}, field.path, &changed);
    EXPECT_EQ(field.get(changed), value) << field.path << ": set and get reach one member";
    EXPECT_FALSE(changed == base) << field.path << " is not compared";
    for (const StateField& other : state_fields()) {
      if (&other == &field || other.path.rfind("plane.camera.", 0) == 0) continue;
      EXPECT_EQ(other.get(changed), other.get(base))
          << "setting " << field.path << " changed " << other.path;
    }
  }
}

TEST(StateFields, TheSchemaForThePageIsTheTable) {
  const json schema = state_schema();
  ASSERT_EQ(schema.size(), state_fields().size());
  for (size_t k = 0; k < schema.size(); ++k) {
    EXPECT_EQ(schema[k]["name"], state_fields()[k].path);
    EXPECT_EQ(schema[k]["default"], state_fields()[k].get(WindowState()));
    EXPECT_FALSE(schema[k]["doc"].get<std::string>().empty()) << state_fields()[k].path;
  }
}

TEST(StateFields, TheManualsTableIsTheTable) {
  std::ifstream in(OFLAB_SOURCE_DIR "/manual/gui.md");
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  const std::string begin = "<!-- state-fields: oflab-cli lesson fields --markdown -->\n";
  const std::string end = "<!-- /state-fields -->";
  const size_t from = text.find(begin), to = text.find(end);
  ASSERT_NE(from, std::string::npos) << "manual/gui.md lacks the field table's markers";
  ASSERT_NE(to, std::string::npos);
  EXPECT_EQ(text.substr(from + begin.size(), to - from - begin.size()), state_fields_markdown())
      << "regenerate the table with `oflab-cli lesson fields --markdown`";
}

}  // namespace
}  // namespace oflab
