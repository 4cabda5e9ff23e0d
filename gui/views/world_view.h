// The world view, "World (the cause)": the 3D scene whose motion makes the flow the other
// views show, drawn by VTK offscreen (gui/adapters/offscreen_vtk.h) into an image that a
// plain widget shows, with its labels and caption painted over it by Qt.
//
// For the scene panel's plane (and any single-plane source) the world is the viewer frame
// (session/display/world_geometry.h): the eye at the origin and the camera's frustum out to the
// image plane (drawn at half the plane's nearest depth, d / f world units per pixel) showing
// the exact frame (the window model's exact renderer, gui/adapters/exact_frames.h); the
// textured plane at its pose with its up U and normal N; V (the velocity of the body point at
// the eye, eq. 21) and Omega (the rotation about the eye, the theory's convention, said on
// screen) as labelled arrows at the plane's centre, each scaled between 0.35 and 1 of 0.6
// plane diagonals by its size over the loop; the rays from the eye through the plane's
// corners and where they cross the image plane; and the path of the plane's centre over the
// whole loop, past solid and thick, future thin and muted. It follows the scene model, as the
// flow view does.
//
// For a scene source (a viewer script walking through polygons) the world is the scene's:
// every polygon in its layer's current level colour (session/display/palette.h), culled polygons
// pale and hidden ones dark, the viewer's path past and future, the viewer's frustum and
// image plane (the engine's frame) at its pose, and the scene's motion seen by the viewer as
// the V and Omega arrows at the eye. It follows the animation model.
//
// Mouse: orbit (left), pan (middle or Shift+left), zoom (wheel or right), the rules of VTK's
// trackball camera (gui/adapters/camera_moves.h). "Reset view" frames the whole world; "View
// from the camera" looks through the eye, following it, with a field of view a little wider
// than the camera's so that the image's border shows as a frame; the eye's ball, the image
// plane and the rays are left out there (the ball would enclose the view, the image plane
// would cover the plane). The two are the window model's world camera
// (WindowState::world_camera, "orbit" and "eye"); a drag makes it "orbit" again. Every actor is
// made once: frames replace points, transforms and pixels in place. VTK renders only when something
// it draws changed (the frame, the source, a part shown, the theme, the camera, the size).
//
// Texts. The labels (eye, image plane, V, Omega, N, U) are painted next to the projection of
// the point they name, placed so that none covers another or the caption, nor, where a place
// near their point allows, the image plane's picture or the textured plane
// (gui/adapters/label_layout.h), with a leader line when pushed away from it; the caption is
// wrapped to the view's width.
#pragma once

#include <memory>
#include <vector>

#include "adapters/painted_text.h"
#include "flow/geometry.h"
#include "state/window_state.h"
#include "views/view_page.h"

class QLabel;
class vtkRenderer;

namespace oflab {

class ImageCanvas;
class WindowModel;
struct WorldScene;

// What the world view draws, part by part (set_part_shown; all shown by default).
enum class WorldPart { kFrustum, kImagePlane, kPlane, kVelocity, kOmega, kRays, kPath, kScene };
constexpr int kWorldPartCount = 8;

class WorldView : public ViewPage {
  Q_OBJECT

 public:
  // Shows the window model's scene; the model must outlive the view.
  explicit WorldView(WindowModel* window, QWidget* parent = nullptr);
  ~WorldView() override;

  // The picture at the view's canvas size: VTK's render with the texts painted over it.
  QImage render_image() override;
  void set_theme(const ViewTheme& theme) override;
  double smallest_text_px() const override;

  // The VTK camera framing everything drawn, seen from behind, above and left of the eye
  // (the model's world camera becomes "orbit").
  void reset_camera();
  // The VTK camera at the eye (the viewer's in a scene), looking through it (the model's
  // world camera becomes "eye").
  void view_from_camera();
  // True while the camera looks through the eye.
  bool from_eye() const;

  // Hides or shows a part (screenshots that leave a part out; the image tests' controls).
  void set_part_shown(WorldPart part, bool shown);

  // The renderer holding every actor (tests count its actors and check they stay the same).
  vtkRenderer* renderer() const;
  // True when a scene source plays (the scene's world), false for the plane's viewer frame.
  bool scene_mode() const;
  // The drawn plane's centre (plane mode) or the viewer's eye (scene mode), world units, as
  // of the last update.
  Vec3 drawn_centre() const;
  // The depth of the image plane, world units, as of the last update.
  double image_depth() const;
  // The VTK scene as last updated (tests compare its actors' points and matrices with the
  // teaching layer's world, session/display/world_geometry.h).
  const WorldScene& drawn_scene() const { return *world_; }

  // The texts the last picture painted (labels, caption, legend) with their boxes, canvas
  // pixels, and what is wrong with them (text_problems of gui/adapters/painted_text.h:
  // elided, off the canvas, overlapping); render_image first for the current frame.
  std::vector<PaintedText> painted_texts() const;
  std::vector<QString> text_problems() const;
  // The labels of the picture drawn now that cover the image plane's picture or the textured
  // plane (WorldTexts::labels_over_content), after a render at the canvas size.
  std::vector<QString> labels_over_content();
  // The share (0..1) of the picture inside the convex hull of what it draws (the plane or the
  // scene's polygons, and the eye with its image plane unless seen through the eye) after a
  // render at the canvas size (WorldScene::drawn_share).
  double drawn_share();
  // How many times VTK has rendered since the view was made (tests check that nothing
  // renders again when nothing changed).
  int render_count() const;

  // Brings the drawing up to date with the model and renders when the view is visible.
  void refresh();

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  QWidget* make_button_bar();
  // The canvas VTK's picture is shown on; its drags and wheel turns move the camera.
  ImageCanvas* make_canvas();
  // Redraws on the scene model's, the animation model's and the window model's signals (a new
  // source or texture, or another exact renderer, reloads the whole loop).
  void follow_models();
  void update_now();
  void draw();          // renders VTK at the canvas's size and shows it with its texts
  void camera_moved();  // draws again after a mouse move or a button
  // Places the VTK camera as the model's world camera says (after the canvas has its size).
  void place_camera();
  // A mouse move leaves the view through the eye: the model's world camera becomes "orbit"
  // without moving the camera.
  void leave_eye();

  WindowModel* window_;
  ImageCanvas* canvas_ = nullptr;
  QLabel* note_ = nullptr;
  std::unique_ptr<WorldScene> world_;  // the VTK window, its actors and the camera
  bool dirty_ = true;
  bool camera_placed_ = false;
  WorldCamera placed_camera_ = WorldCamera::kOrbit;  // the framing the camera was placed by
};

}  // namespace oflab
