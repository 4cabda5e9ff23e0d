// The picture of the flow view, painted with Qt into one reused image: the image frame, the
// plane's projected outline and faint texture, the chosen part of the flow as arrows
// (coloured by magnitude, with a colour bar), streamlines, and the colour-wheel coding with
// its legend.
//
// Everything is drawn in centred image pixels (core/flow/camera.h) mapped onto the view by
// one scale and shift, refitted at every paint so the chosen region of the image shows
// whole at any view aspect. The texture is core's exact perspective warp of the plane
// (core/engine/exact_render.h's exact_texture_warp), the same projection the animation engine
// uses. Drawing on the CPU into a reused image keeps a frame to a few milliseconds on a
// software-rendered display: no OpenGL widget, no per-frame scene rebuild.
#pragma once

#include <QColor>
#include <QImage>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QString>
#include <QTransform>
#include <vector>

#include "adapters/view_theme.h"
#include "display/flow_display.h"
#include "image/image.h"
#include "image/layer.h"

class QPainter;

namespace oflab {

class FlowRenderer {
 public:
  FlowRenderer();
  FlowRenderer(const FlowRenderer&) = delete;
  FlowRenderer& operator=(const FlowRenderer&) = delete;

  void set_texture(const QImage& texture);
  void set_theme(const ViewTheme& theme);

  // Recomputes what is drawn (plane image, arrows, streamlines, wheel, captions) for the
  // context and options; `frame_caption` is appended to the caption line. Paint shows it.
  void update(const FlowContext& context, const FlowDisplay& display, const QString& frame_caption);

  // Paints the last update at `size` (view pixels; at least 1 x 1) into one of two reused
  // images and returns it. Precondition: update has been called.
  const QImage& paint(const QSize& size);
  // Whether paint() paints the scene's lines in strips of rows on core's worker threads (the
  // default) or in one piece on the calling thread.
  void set_paint_in_parallel(bool on) { paint_in_parallel_ = on; }
  // The strips of rows paint() paints the scene's lines in (the same on any number of threads).
  static constexpr int kLineStrips = 2;

  // Largest magnitude of the shown part after the last update (px/s): over the arrow grid
  // and the plane's corners inside the image; the caption and the wheel both print it.
  double shown_max_magnitude() const { return shown_max_; }
  // The smallest font of its captions, colour-bar title and labels, screen pixels.
  double smallest_text_px() const;
  // False when no part of the plane is seen inside the image (scene/view_culling.h's
  // plane_meets_image) and its centre is not in the image either (a plane seen edge-on in
  // the picture is not outside), after the last update: only the caption is drawn then.
  bool plane_in_image() const { return plane_in_image_; }
  // The caption line(s) drawn at the top left after the last update.
  const QString& caption() const { return caption_text_; }
  // The colour wheel's caption (bottom left; empty without the wheel) after the last update.
  const QString& wheel_caption() const { return wheel_caption_; }
  // True when the shown part is zero up to rounding after the last update: its largest
  // magnitude is at most 1e-9 of the full flow's (a residual such as exact - homography).
  // The side strip then says so in words instead of drawing a colour bar over that noise.
  bool rounding_only() const { return rounding_only_; }

  // One streamline of the last update, centred pixels: the path and the arrow head at its
  // end (empty when the path is too short to carry one). The head is never longer than
  // half the path, so it always sits on a shaft.
  struct Streamline {
    QPolygonF line, head;
  };
  const std::vector<Streamline>& streamlines() const { return streamlines_; }

  // One arrow of the last update: from the sample point to where its flow points, centred
  // pixels. An arrow whose tip would leave the plane's outline (plane in front of the eye)
  // is not drawn, so no arrow points into space the plane does not cover.
  struct Arrow {
    QPointF from, to;
    QColor colour;
  };
  const std::vector<Arrow>& arrows() const { return arrows_; }
  // Arrow-grid samples of the shown part inside the plane's image after the last update.
  int shown_samples() const { return shown_samples_; }
  // The plane's projected corners, centred pixels, after the last update.
  const QPolygonF& outline() const { return outline_; }

  // Where `paint` at `size` puts the caption (view pixels): the strip at the top that the
  // scene is kept out of, and where it maps the plane's projected outline.
  QRectF caption_rect(const QSize& size) const;
  QRectF outline_rect(const QSize& size) const;
  // The share (0..1) of the region `paint` at `size` fits the scene into (left of the legend
  // strip, between the caption and the wheel's caption) that the plane's projected outline
  // covers, after the last update.
  double plane_share(const QSize& size) const;
  // The region `paint` at `size` fits the scene into, view pixels.
  QRectF scene_rect(const QSize& size) const;

 private:
  void update_faded_texture();
  void update_plane_image(const FlowContext& context, bool wanted);
  void update_arrows(const std::vector<FlowSample>& samples, double arrow_seconds, bool shown);
  void update_streamlines(const FlowContext& context, const FlowDisplay& display,
                          double arrow_seconds);
  void update_wheel(const FlowContext& context, const FlowDisplay& display);
  void update_caption(const FlowDisplay& display, const QString& frame_caption);
  void choose_view_region(const FlowContext& context, const FlowDisplay& display);
  QTransform image_to_view(const QSize& size) const;
  double wheel_caption_height() const;  // view pixels at the bottom, 0 without the wheel
  // The scene in the view's pixels (`to_view` maps centred camera pixels there): its images
  // (the plane's, the colour wheel), then its lines (frame, outline, principal point,
  // streamlines, arrows). The lines paint no text and may run on several threads at once.
  void paint_scene_images(QPainter& painter, const QTransform& to_view) const;
  void paint_scene_lines(QPainter& painter, const QTransform& to_view) const;
  void paint_arrows(QPainter& painter, const QTransform& to_view) const;
  void paint_side(QPainter& painter, const QRectF& side);
  void paint_colour_bar(QPainter& painter, const QRectF& side);
  void paint_rounding_note(QPainter& painter, const QRectF& side);
  void paint_wheel_legend(QPainter& painter, const QRectF& square);
  double side_width_px(int view_width) const;  // width of the legend strip on the right

  ViewTheme theme_;
  Camera camera_;
  FlowDisplay display_;                // what the last update drew
  Vec2 view_centre_{0.0, 0.0};         // centred pixels shown at the middle of the view
  Vec2 view_half_size_{400.0, 300.0};  // half the image region that must stay visible, px
  // Largest magnitude of the shown part (px/s): over the arrow grid and the plane's corners
  // in the image. The caption, the colour bar and the colour wheel all use this one value.
  double shown_max_ = 0.0;
  bool rounding_only_ = false;
  bool paint_in_parallel_ = true;  // set_paint_in_parallel
  double bar_max_ = 1.0;           // colour bar's upper end (px/s), a 1-2-5 step
  bool plane_in_image_ = true;
  int shown_samples_ = 0;  // arrow-grid samples inside the plane's image
  QString caption_text_, wheel_caption_;
  QPolygonF outline_;             // the plane's projected corners, centred pixels
  bool outline_in_front_ = true;  // every corner in front of the eye: outline_ bounds the plane
  QImage texture_image_;          // the plane's texture as given
  Layer faded_texture_;           // the texture faded towards the background, opaque
  Image plane_image_;             // camera-sized: the background with the faded plane warped in
  QRect plane_box_;               // the part of plane_image_ worth drawing (top-left pixels)
  bool plane_drawn_ = false;
  std::vector<Arrow> arrows_;
  std::vector<Streamline> streamlines_;
  QImage wheel_;         // the wheel's colours, one texel per cell
  QRectF wheel_rect_;    // where wheel_ lies, centred pixels
  QImage wheel_legend_;  // the legend disc at its last drawn size
  QImage buffers_[2];    // painted views, used in turn so the shown one is not copied
  int next_buffer_ = 0;
};

}  // namespace oflab
