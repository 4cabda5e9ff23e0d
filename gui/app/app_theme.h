// The Qt side of the two looks: a dark palette and normal fonts for working, a light
// palette and large fonts for presentation mode (the VTK side is gui/views/view_theme.h).
#pragma once

#include "adapters/view_theme.h"

namespace oflab {

// Applies the palette and font of `theme` (view_theme: its look and, in presentation mode,
// its control font size) to the whole application (QApplication must exist).
void apply_app_theme(const ViewTheme& theme);

}  // namespace oflab
