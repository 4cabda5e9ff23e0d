// The window's exports: the animation view as numbered PNGs, a video (MP4, GIF or Ogg
// Theora), the per-frame CSV or the current frame as ParaView data. File dialogs live in the
// window; these functions never overwrite an existing file unless told to, and write each
// file whole (analysis/formats/atomic_file.h: a temporary beside it, renamed into place). (Sessions
// are the window model's state: session/state/window_state_file.h.)
#pragma once

#include <QString>

namespace oflab {

class MainWindow;

// Plays the animation view's source from frame 0 to its last frame and writes the whole
// view as on screen for each frame (every panel of its layout, grabbed with
// app/screenshot.h's grab_with_vtk, so images are as wide as the view): `directory`/
// frame-0000.png ... (PNG) or one video file at kExportFps, MP4, GIF or Ogg Theora by the
// extension of `path` (analysis/formats/video_file.h). In the blink layout the frames
// blink as the screen does (AnimationView::blink_phase_at at kExportFps): the engine's
// frame, then the exact one, in turn. A progress dialog counts the frames
// and can cancel. Refuses existing files unless `overwrite`. Returns false with *error set
// on failure or cancel, and then removes what it wrote (no partial set of frames, no
// partial video). The window's frame is restored.
constexpr int kExportFps = 30;
bool export_frames_png(MainWindow* window, const QString& directory, bool overwrite,
                       QString* error);
bool export_video(MainWindow* window, const QString& path, bool overwrite, QString* error);

// The per-frame CSV of the single-plane source (the plane kind of analysis/runs/source_kinds.h)
// over its whole script, the exact re-render run alongside for the PSNR column. False with
// *error for a scene source, an existing file or one that cannot be written.
bool export_frame_csv(MainWindow* window, const QString& path, bool overwrite, QString* error);

// The window's current frame as ParaView data (analysis/formats/vtk_export.h) in the
// directory `directory`, written whole (a temporary directory beside it renamed into place;
// a non-empty one is replaced whole only when `overwrite`): flow.vti, the flow field of the
// scene model's current pose (camera, plane and motion as the flow view shows them; px/s on
// a grid every kDefaultVtkGridStep px, centred pixels) and, when the animation view has a
// source, its current frame as a one-step series: frame_NNNNN_shown.vti (the engine's
// frame), _exact.vti (the exact panel's), _difference.vti, _layers.vtp and shown.pvd,
// exact.pvd, difference.pvd, layers.pvd. False with *error naming the path and the reason
// on any failure; the directory is then as it was.
bool export_paraview_data(MainWindow* window, const QString& directory, bool overwrite,
                          QString* error);

}  // namespace oflab
