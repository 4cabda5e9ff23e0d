// The VTK scene of the flow view: the image frame, the plane's projected outline and faint
// texture, the chosen part of the flow as arrows (coloured by magnitude, with a scalar
// bar), streamlines, and the colour-wheel coding with its legend.
//
// Two renderer layers share one viewpoint, the eye of core's pinhole camera: layer 0 draws
// the textured plane in 3D (so the texture is projected exactly, perspective-correct),
// layer 1 draws the overlays on the image plane Z = 1 (see gui/adapters/vtk_adapters.h). Before
// every render the view angle (and, zoomed to the plane, the off-axis window centre) is
// refitted so the chosen region of the image shows whole at any window aspect.
#pragma once

#include <vtkActor.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTexture.h>

#include <QImage>
#include <QString>

#include "adapters/flow_display.h"
#include "views/view_theme.h"

class vtkRenderWindow;
class vtkCallbackCommand;

namespace oflab {

class FlowRenderer {
 public:
  // Adds the renderers to `window` (which must outlive this object) and sets its layers.
  explicit FlowRenderer(vtkRenderWindow* window);
  ~FlowRenderer();
  FlowRenderer(const FlowRenderer&) = delete;
  FlowRenderer& operator=(const FlowRenderer&) = delete;

  void set_texture(const QImage& texture);
  void set_theme(const ViewTheme& theme);

  // Rebuilds every actor for the context and options; `frame_caption` is appended to the
  // caption line. The caller renders the window afterwards.
  void update(const FlowContext& context, const FlowDisplay& display, const QString& frame_caption);

  // Largest magnitude of the shown part on the arrow grid after the last update (px/s).
  double shown_max_magnitude() const { return shown_max_; }
  // The smallest font of its captions, colour-bar title and labels, screen pixels (VTK
  // font points at the window's DPI).
  double smallest_text_px() const;
  // False when no part of the plane is seen inside the image (scene/view_culling.h's
  // plane_meets_image) and its centre is not in the image either (a plane seen edge-on in
  // the picture is not outside), after the last update: only the caption is drawn then.
  bool plane_in_image() const { return plane_in_image_; }
  // The caption line(s) drawn at the top left after the last update.
  const QString& caption() const { return caption_text_; }

 private:
  void update_faded_texture();
  void create_actors();
  void create_arrow_pipeline();
  void create_legend_and_text();
  void update_plane(const FlowContext& context, const FlowDisplay& display);
  void update_arrows(const std::vector<FlowSample>& samples, double arrow_seconds,
                     const FlowDisplay& display);
  void update_streamlines(const FlowContext& context, const FlowDisplay& display,
                          double arrow_seconds);
  void update_wheel(const FlowContext& context, const FlowDisplay& display);
  void update_caption(const FlowDisplay& display, const QString& frame_caption);
  void choose_view_region(const FlowContext& context, const FlowDisplay& display);
  void fit_view_angle();
  void place_legend();
  double side_width_px() const;   // width of the legend strip on the right
  double scene_fraction() const;  // fraction of the window width left for the image
  static void on_render_start(vtkObject* caller, unsigned long event, void* self, void* data);

  vtkRenderWindow* window_;
  Camera camera_;
  Vec2 view_centre_{0.0, 0.0};         // centred pixels shown at the middle of the view
  Vec2 view_half_size_{400.0, 300.0};  // half the image region that must stay visible, px
  ViewTheme theme_;
  double shown_max_ = 0.0;
  bool plane_in_image_ = true;
  int shown_samples_ = 0;  // arrow-grid samples inside the plane's image
  QString caption_text_;
  double bar_max_ = -1.0;           // colour bar's upper end (px/s), a 1-2-5 step
  bool bar_presentation_ = false;   // theme the bar's table was made for
  QImage texture_image_;            // the plane's texture as given
  vtkSmartPointer<vtkRenderer> scene_, overlay_, legend_, side_;
  vtkSmartPointer<vtkCallbackCommand> fit_callback_;
  vtkSmartPointer<vtkActor> plane_, frame_, outline_, centre_mark_, arrows_, streamlines_,
      wheel_legend_;
  vtkSmartPointer<vtkTexture> texture_;
  vtkSmartPointer<vtkPolyData> arrow_input_;
  vtkSmartPointer<vtkImageActor> wheel_image_;
  vtkSmartPointer<vtkImageData> wheel_data_;  // the wheel's colours, reused
  vtkSmartPointer<vtkScalarBarActor> scalar_bar_;
  vtkSmartPointer<vtkTextActor> caption_, wheel_caption_, scalar_title_;
};

}  // namespace oflab
