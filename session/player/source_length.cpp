#include "player/source_length.h"

#include <stdexcept>

#include "formats/datasets.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "player/plane_panel.h"

namespace oflab {

int source_frame_count(const SourceChoice& choice, const PlanePanel& /*panel*/) {
  if (choice.kind == "plane") return 0;
  if (choice.kind == "script") {
    return int(read_script_file(resolve_script_path(choice.name)).frames.size());
  }
  if (choice.kind == "scene" || choice.kind == "scene-shifting") {
    return int(read_viewer_script_file(resolve_viewer_script_path(choice.viewer)).frames.size());
  }
  throw std::invalid_argument("unknown source kind '" + choice.kind + "'");
}

}  // namespace oflab
