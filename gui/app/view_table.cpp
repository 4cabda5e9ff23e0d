#include "app/view_table.h"

#include "views/analysis_view.h"
#include "views/animation_view.h"
#include "views/basis_view.h"
#include "views/flow_view.h"
#include "views/slices_view.h"
#include "views/world_view.h"

namespace oflab {

const std::vector<ViewEntry>& view_table() {
  static const std::vector<ViewEntry> table = {
      {"flow", "Flow field", [](WindowModel* m) -> ViewPage* { return new FlowView(m); }},
      {"world", "World (the cause)", [](WindowModel* m) -> ViewPage* { return new WorldView(m); }},
      {"basis", "Basis deformations", [](WindowModel* m) -> ViewPage* { return new BasisView(m); }},
      {"animation", "Animation, side by side",
       [](WindowModel* m) -> ViewPage* { return new AnimationView(m); }},
      {"analysis", "Analysis", [](WindowModel* m) -> ViewPage* { return new AnalysisView(m); }},
      {"slices", "Scene shifting", [](WindowModel* m) -> ViewPage* { return new SlicesView(m); }},
  };
  return table;
}

std::vector<std::string> view_table_names() {
  std::vector<std::string> names;
  for (const ViewEntry& entry : view_table()) names.push_back(entry.name);
  return names;
}

const ViewEntry* find_view_entry(const std::string& name) {
  for (const ViewEntry& entry : view_table()) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

}  // namespace oflab
