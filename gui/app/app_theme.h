// The Qt side of the two looks: a dark palette and normal fonts for working, a light
// palette and large fonts for presentation mode (the VTK side is gui/views/view_theme.h).
#pragma once

namespace oflab {

// Applies the palette and font to the whole application (QApplication must exist).
void apply_app_theme(bool presentation);

}  // namespace oflab
