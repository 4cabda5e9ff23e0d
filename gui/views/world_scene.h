// The world view's VTK scene (gui/views/world_view.h): the offscreen render window with its
// two renderers (the paths on an overlay layer that shares the camera, so the plane never
// hides its own path), every actor made once, what a source puts into them for the whole
// loop (load_plane, load_scene) and what a frame changes in place (update_plane,
// update_scene: points, matrices and pixels, never a new actor), which parts are shown, the
// theme's colours and line widths, the labels' points and the caption (WorldTexts, painted
// by the view), and the camera's two framings (their code in gui/views/world_camera.cpp).
//
// Units: world units (the viewer frame of session/display/world_geometry.h for the plane, the
// scene's frame for a scene source); speeds per second (SceneModel::kSecondsPerFrame per
// frame); display pixels for to_display, canvas pixels for to_canvas.
#pragma once

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <QImage>
#include <QPointF>
#include <QPolygonF>
#include <QSize>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "adapters/exact_frames.h"
#include "adapters/offscreen_vtk.h"
#include "adapters/view_theme.h"
#include "adapters/world_actors.h"
#include "display/palette.h"
#include "display/world_geometry.h"
#include "flow/camera.h"
#include "flow/geometry.h"
#include "scene/viewer_script.h"
#include "views/world_texts.h"
#include "views/world_view.h"  // WorldPart

namespace oflab {

class AnimationModel;
class SceneModel;
class WindowModel;

struct WorldScene {
  // Builds the window (a plain one, never rendered, when display_problem is not empty) and
  // every actor, in the theme of view_theme(false).
  WorldScene();

  std::string display_problem = offscreen_vtk_problem();
  vtkSmartPointer<vtkRenderWindow> window =
      display_problem.empty() ? make_offscreen_window() : vtkSmartPointer<vtkRenderWindow>::New();
  vtkNew<vtkRenderer> renderer;
  // The paths, drawn over everything else with the same camera: the plane covers most of
  // its own path.
  vtkNew<vtkRenderer> overlay;
  vtkNew<vtkUnsignedCharArray> read_back;
  std::array<QImage, 2> pictures;  // used in turn: the one on screen is never written
  int next_picture = 0;
  int renders = 0;
  bool needs_render = true;  // something VTK draws changed since the last render
  QSize rendered_size;
  // The viewer's frame in the world: identity for the plane, the viewer's pose in a scene.
  vtkNew<vtkMatrix4x4> viewer_matrix;
  vtkNew<vtkActor> eye;
  PolyActor frustum, image_plane, plane, plane_outline, rays, ray_images, omega_axis;
  PolyActor path_past, path_future, polygons, polygon_edges;
  vtkNew<vtkImageData> frame_pixels, texture_pixels;
  // The reduction of the frame last copied to frame_pixels (show_frame) and its size, pixels.
  int frame_shown_reduction = 1;
  QSize frame_size;
  vtkNew<vtkTexture> frame_texture, plane_texture;
  vtkNew<vtkArrowSource> arrow_source;
  struct Arrow {
    vtkSmartPointer<vtkActor> actor;
    vtkSmartPointer<vtkMatrix4x4> matrix;
  };
  Arrow velocity, omega, normal, up;
  WorldTexts texts;          // labels, legend and caption, painted over VTK's picture
  std::string caption_body;  // what the frame shows, set by update_plane and update_scene

  ViewTheme theme = view_theme(false);
  // The camera looks through the eye (view_from_camera): the eye's ball, the image plane
  // and the rays are left out, whatever `shown` says.
  bool from_eye = false;
  std::array<bool, kWorldPartCount> shown{true, true, true, true, true, true, true, true};

  // What the source gives for every frame (rebuilt when the source changes).
  bool source_dirty = true;
  bool scene_mode = false;
  PlaneWorldLoop plane_loop;  // the plane's loop (display/world_geometry.h), set by load_plane
  SceneWorldLoop scene_loop;  // a scene's walk (display/world_geometry.h), set by load_scene
  std::vector<Vec3> path;     // plane centres, or the viewer's eye, per frame, world units
  // The plane's corners at every frame of the loop (empty for a scene), world units: what
  // the orbit camera frames.
  std::vector<Vec3> loop_corners;
  double largest_velocity = 0.0, largest_omega = 0.0;  // per second
  double depth = 1.0;                                  // image plane, world units
  double full_arrow = 1.0;                             // longest arrow, world units
  Camera camera;
  PlanePose first_pose;
  std::unique_ptr<ExactFrameRenderer> exact;
  std::string problem;  // why the image plane is empty, "" when it is not
  Vec3 centre{0.0};

  ViewerPose view;         // the viewer now (identity for the plane)
  ViewerPose first_view;   // the viewer at frame 0
  Vec3 world_centre{0.0};  // what the reset view looks at

  // An arrow actor in `colour`, added to the renderer; placed by `place`.
  Arrow add_arrow(const Rgb8& colour);
  // Points `arrow` from `origin` along `direction`, `length` world units long.
  static void place(Arrow& arrow, const Vec3& origin, const Vec3& direction, double length);
  // Label `id` names `text` at the world point `at` (painted where the camera projects it).
  void place_label(WorldLabelId id, const Vec3& at, const std::string& text);

  // Takes what every loop gives (display/world_geometry.h PlaneWorldLoop, SceneWorldLoop):
  // the camera, the path, the largest speeds, the image plane's depth, the longest arrow and
  // the centre the reset view looks at.
  template <class Loop>
  void take_loop(const Loop& loop);
  // The whole loop of the window model's plane (its path, largest speeds, image depth, the
  // texture and the exact renderer of the image plane; `problem` says why it cannot start).
  void load_plane(WindowModel& window);
  // The whole loop of the animation model's scene source: its polygons, the viewer's path
  // and largest speeds; `problem` says why nothing plays.
  void load_scene(AnimationModel& animation);
  // The scene model's current frame: plane, rays, arrows, path split, image plane, caption.
  void update_plane(const SceneModel& scene);
  // The animator's current frame: viewer, polygon colours, arrows, path split, caption.
  void update_scene(AnimationModel& animation);
  // `frame` (the frame now, premultiplied) on the image plane: copy_frame_pixels over the
  // theme's image background, reduced by frame_reduction. Call after place_viewer.
  void show_frame(const Image& frame);
  // The power of two r (1 .. kMaxFrameReduction) by which a frame of width x height pixels is
  // reduced on the image plane: the largest that keeps at least one texel per pixel of the
  // picture along both of the image's axes, as the camera now projects the image plane into
  // the render window (its longer top or bottom edge against the texels across, its longer
  // side against the texels down); 1 when a corner is behind the camera. Fewer texels than
  // that would blur the picture; more are minified by OpenGL's bilinear lookup, which skips
  // pixels (aliasing) and costs a copy and an upload per frame for nothing shown.
  int frame_reduction(int width, int height) const;
  static constexpr int kMaxFrameReduction = 64;
  // The eye, frustum, image plane and their labels at the viewer pose `pose`.
  void place_viewer(const ViewerPose& pose);
  // The V and Omega arrows and Omega's axis as `arrows` (display/world_geometry.h) place
  // them, with their labels (none for an arrow not drawn).
  void place_motion(const MotionArrows& arrows);
  // The path up to `frame` (past) and from it (future).
  void split_path(int frame);
  // Shows the parts `shown` asks for that the mode (plane or scene) has.
  void show_parts();
  // The caption under the picture: caption_body, after a line saying so when the camera
  // looks through the eye.
  std::string caption() const;
  // Colours and line widths of `theme`.
  void apply_theme();
  // Where world point `at` lands as the camera projects it now, in the render window's
  // display pixels (VTK's: x to the right, y upwards from the bottom row); false when it is
  // behind the camera or past the far plane (its depth outside [0, 1]).
  bool to_display(const Vec3& at, QPointF* display) const;
  // Where world point `at` lands in the last render (canvas pixels); false when it is behind
  // the camera or outside the picture.
  bool to_canvas(const Vec3& at, QPointF* canvas) const;
  // The image plane's corners at the viewer now (image_plane_corners at `depth`, through
  // `view`), world units: top-left, top-right, bottom-right, bottom-left.
  std::array<Vec3, 4> image_plane_in_world() const;
  // The share (0..1) of the last render's picture between its legend and caption
  // (WorldTexts::free_area; the whole picture before the texts are laid out) inside the
  // convex hull of what it draws now: the plane's corners (the scene's polygons in a scene) and,
  // unless the camera looks through the eye, the eye and its image plane's corners; points behind
  // the camera are left out.
  double drawn_share() const;
  // The drawn pictures the labels leave clear, as the last render's camera projects them
  // (canvas pixels): the image plane's quad when it shows and the textured plane's when it
  // shows (plane mode); a quad with a corner behind the camera is left out.
  std::vector<QPolygonF> content_outlines() const;

  // The camera framing everything drawn, seen from behind, above and left of the first
  // frame's eye; for the plane, of a few such vantages the one with the largest drawn_share.
  void reset_camera();
  // The orbit camera looking at the middle of the first frame's eye and the world's centre
  // from `side` (world units per their distance apart) with `view_up`, fitted by VTK's
  // ResetCamera.
  void place_orbit(const Vec3& side, const Vec3& view_up);
  // place_orbit, then the plane's framing: centred (centre_framed_points) and zoomed so that
  // the framed points fill 90 % of the picture (fit_zoom).
  void frame_plane_from(const Vec3& side, const Vec3& view_up);
  // What the orbit camera frames the plane in, canvas pixels: the picture between its legend and
  // caption as the texts were last laid out (WorldTexts::free_area), the whole picture before.
  QRectF framed_picture() const;
  // The zoom (VTK's Camera::Zoom factor, 0.5 .. 3) after which the eye, its image plane and
  // every corner of the plane over the loop (loop_corners) fill `fill` of framed_picture's
  // half width or half height about its centre, whichever they reach first, as the current
  // camera projects them (reset_camera's framing of the plane).
  double fit_zoom(double fill) const;
  // What the orbit camera frames: the first frame's eye, its image plane's corners and the
  // plane's corners over the loop (a scene's viewer path instead), world units.
  std::vector<Vec3> framed_points() const;
  // Pans the camera (its position and focal point together, in the picture's plane through
  // the focal point) so that the box of framed_points as projected now is centred in
  // framed_picture.
  void centre_framed_points();
  // The camera at the eye now (the viewer's in a scene), looking along its line of sight
  // with its up, its field of view wide enough that the whole image and a margin of
  // kEyeViewMargin of it on each side fit the render's shape. Call after the window's size.
  void view_from_camera();
  // The camera stays where it is but no longer looks through the eye (a mouse move).
  void leave_eye();
  static constexpr double kEyeViewMargin = 0.12;

 private:
  // Called by the constructor in this order, the order the renderers keep their actors in.
  void add_viewer_actors();  // the eye, the frustum and the image plane with its texture
  void add_plane_actors();   // the textured plane, its outline, the rays and Omega's axis
  void add_scene_actors();   // the paths (on the overlay) and the scene's polygons
  void name_labels();        // the labels' texts and colours
};

}  // namespace oflab
