// How many frames a source of the animation view plays, read from its files without making
// its animator: the frame clock's loop while it plays (player/plane_panel.h
// set_loop_override). The desktop's run player takes the same number from the animator
// (Animator::frame_count), and a test holds the two equal on every shipped lesson; the
// browser page, which cannot make every animator, reads it here. Plain C++ over
// analysis/formats (the script and viewer-script readers).
#pragma once

#include "state/source_choice.h"

namespace oflab {

class PlanePanel;

// 0 for a source that follows the plane panel (its own loop); the script's frames for a
// plane script; the viewer script's frames for a scene or scene shifting. Throws
// std::runtime_error (the reader's message) when a file cannot be read, std::invalid_argument
// for an unknown kind.
int source_frame_count(const SourceChoice& choice, const PlanePanel& panel);

}  // namespace oflab
