// The views of the window, as one table: each entry's command-line name, tab title and
// factory. The main window builds its tabs from it in this order; --view, --help, the
// screenshot code and session files take their view names from it. Adding a view is adding
// an entry here (and its page in manual/gui.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

class QWidget;

namespace oflab {

class ViewPage;
class WindowModel;

struct ViewEntry {
  std::string name;   // command-line name, lower case: "flow"
  std::string title;  // tab title: "Flow field"
  // Makes the view (parentless; the window takes ownership) over the window's model, which
  // outlives every view.
  std::function<ViewPage*(WindowModel*)> make;
};

// Every view, in tab order.
const std::vector<ViewEntry>& view_table();

// The names of view_table(), in order.
std::vector<std::string> view_table_names();

// The entry with this name, or nullptr.
const ViewEntry* find_view_entry(const std::string& name);

}  // namespace oflab
