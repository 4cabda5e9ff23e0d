// View 3, "Animation, side by side": the animation model's frame beside the exact projection
// of the same frame, drawn by the chosen exact renderer (gui/adapters/exact_frames.h): by
// default core's exact re-render of the scene with the engine's content (the picture the
// engine's re-render level and the analysis's baseline draw), or independently by VTK as
// textured 3D polygons with the matching camera. Made for a projector: the panels are painted at
// the view's own size and fill it, every panel shows the same part of the camera image (zoom to fit
// on the plane over its whole loop, or, framing what is drawn (WindowState::framing, the default
// in presentation mode), over the frames around the one shown, so a far plane fills its panel;
// times a zoom the teacher sets with the Zoom box or the mouse wheel), every panel outlines the
// exact polygons, and titles, numbers and legends sit in bands around the images, never over them.
//
// Layouts (PanelDisplay): side by side (engine | exact); the difference heat map; blink
// (engine and exact in turn); and the comparison, which plays several reuse policies at
// once on the same frames (session/player/policy_comparison.h; affine and perspective by
// default) beside the exact projection, each approximation with its level outlines,
// measured error and cost, and under each its difference heat map against the exact frame.
// Beside the panels, the frame inspector (not in the comparison, which has no single
// engine); under them, the readout of the pixel under the cursor and the zoom.
//
// What plays is the animation model's source (gui/models/animation_model.h): the scene
// panel's plane, a motion script, a multi-plane scene walked through by a viewer script, or
// scene shifting of such a scene, all through one Animator. The controls edit the model;
// the view redraws on its signals. The engines run only while a view asks for their frames.
#pragma once

#include <QImage>
#include <QRectF>
#include <QStringList>
#include <cstdint>
#include <memory>
#include <vector>

#include "adapters/painted_text.h"
#include "adapters/text_cache.h"
#include "image/image.h"
#include "views/animation_controls.h"
#include "views/panel_layout.h"
#include "views/view_page.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPainter;
class QScrollArea;
class QTimer;

namespace oflab {

class AnimationModel;
class Animator;
struct ComparedRun;
class ExactFrameRenderer;
class ImageCanvas;
class PolicyComparison;
class WindowModel;
struct ExactRendererKind;

// One panel: a camera-sized picture (premultiplied; painted over the view's background),
// the level outlines drawn on it, and the lines under it.
struct PanelContent {
  QString title;
  QImage image;
  std::vector<LayerOutline> levels;
  QStringList caption;
};

class AnimationView : public ViewPage {
  Q_OBJECT

 public:
  // Shows the window model's animation model and its layout, compared policies, exact
  // renderer and zoom (edited there); the model must outlive the view.
  explicit AnimationView(WindowModel* window, QWidget* parent = nullptr);
  ~AnimationView() override;

  // The panels as the canvas shows them, painted at the canvas's size.
  QImage render_image() override;
  void set_external_clock(bool on) override;
  void set_theme(const ViewTheme& theme) override;
  QString scene_panel_note() const override;

  AnimationModel* model() const { return model_; }
  PanelDisplay display() const;  // the window model's panel display
  // Blink shows the engine's frame (phase false) or the exact one (true), each for
  // kBlinkIntervalMs while it plays on its own clock.
  bool blink_phase() const { return blink_phase_; }
  void set_blink_phase(bool exact);
  static constexpr int kBlinkIntervalMs = 500;
  // The blink phase of frame `frame` of an export at `fps` frames per second, so the
  // exported animation blinks as the screen does: the engine's frame first, then
  // kBlinkIntervalMs of each in turn. Preconditions: frame >= 0, fps > 0.
  static bool blink_phase_at(int frame, int fps);
  bool external_clock() const { return external_clock_; }

  // The teacher's zoom on top of zoom-to-fit (the window model's; limits::kZoom): 1 fits the
  // plane's whole loop, or the frames around the one shown when the framing is content. The mouse
  // wheel over the panels multiplies it by kWheelZoomStep per notch, stopping at the ends of the
  // range.
  static constexpr double kWheelZoomStep = 1.25;

  // What the last render showed: the part of the camera image (camera pixels) every panel
  // frames, and the canvas rectangles of the panels' images in panel order (for the
  // comparison: the policies, the exact panel, then the heat maps).
  QRectF shown_frame() const { return shown_frame_; }
  const std::vector<QRectF>& panel_rects() const { return panel_rects_; }
  // What the panels draw of the frame: the bounding box (canvas pixels) of the exact outlines
  // of the frame shown (the plane's or the polygons' images) as drawn in each panel of
  // panel_rects(), clipped to that panel; empty rectangles when nothing is seen. Of the last
  // render.
  std::vector<QRectF> drawn_content_rects();
  // The share (0..1) of the exact panel's image that what it shows covers as drawn in the
  // last render: the area inside the exact outlines of the frame shown (exact_outlines: the
  // plane's or the polygons' images, whatever their textures' alpha) within shown_frame(),
  // over its area, rasterised 400 cells across. Display only: no error figure depends on it.
  double content_fill();
  // Hole pixels marked on the comparison's heat maps in the last render (adapters/hole_map.h:
  // the depth-reprojection policy's holes on its frame shown now); 0 in other layouts.
  std::int64_t hole_map_pixels() const { return hole_map_pixels_; }
  // How many heat maps the view has computed: a render of a frame already on screen computes
  // none (for tests).
  int map_passes() const { return map_passes_; }
  // Compared run `index`'s heat map as the last render drew it (null: none; for tests).
  QImage heat_map(std::size_t index) const;
  // Every text the view paints now, at its canvas's size, with its box in canvas pixels
  // (titles, captions, legends, colour-bar labels); for checks of legibility.
  std::vector<PaintedText> painted_texts();
  // What is wrong with those texts (adapters/painted_text.h text_problems): elided, off the
  // canvas or overlapping; empty when every text is legible.
  std::vector<QString> text_problems();

  // Whether the panels' pictures are painted on core's worker threads (the default) or one
  // after another on the window's thread: the same pixels either way (a test compares them).
  void set_panels_in_parallel(bool on) { panels_in_parallel_ = on; }
  // Whether panels share one drawing of their common marks (shared_marks; on; for tests).
  void set_shared_marks(bool on) { shared_marks_ = on; }

  // Who draws the exact panel, the difference heat maps' reference and the readout's exact
  // pixel: the entry of exact_renderers() the window model names.
  const ExactRendererKind& exact_renderer() const { return *exact_kind_; }

  // The animator's frame and the exact frame at the current frame (camera-sized; empty
  // when nothing can be played).
  const Image& engine_image();
  const Image& exact_image();
  // The frame of a compared run that re-renders a scene, when the comparison is shown, it is
  // on the current frame and core draws the exact panel: that frame is the exact frame (a
  // scene engine re-rendering as it advances shows the bytes of one started afresh at the
  // frame's view, tests/core/scene), so it is not drawn twice. nullptr otherwise.
  const Image* compared_exact_frame();

  // Redraws when visible.
  void refresh();
  // Hides (compact) or shows the engine's rows of controls and the readout line.
  void show_compact(bool compact);

 protected:
  void showEvent(QShowEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  // The canvas with the frame inspector beside it, the readout under them, then the Exact
  // picker and the zoom.
  static constexpr int kDifferenceScale = 128;  // grey levels at the colour bar's top
  static const double kNear;  // near plane of the exact render: SceneSettings{}.near, as the page's
  static constexpr double kCaptionLine = 1.4;  // caption line height, times the text size

  QWidget* make_panels();
  // The frame inspector's label in a scroll area of fixed width, returned.
  QScrollArea* make_inspector(QWidget* parent);
  // The zoom box, wired to the window model's zoom (a refused value puts the model's back).
  QDoubleSpinBox* make_zoom_box(QWidget* parent);
  // The canvas's hover (the readout), wheel (the zoom) and resize (a redraw).
  void connect_canvas();
  QComboBox* make_exact_box(QWidget* parent);    // the Exact picker, wired to set_exact_renderer
  QComboBox* make_framing_box(QWidget* parent);  // the Framing picker, wired to set_framing
  void show_model_state();
  // The controls show the window model's layout, compared policies, exact renderer and zoom;
  // the blink timer follows the layout; redraws.
  void show_panels();
  // The canvas's size, or kDefaultCanvas for a view never shown (too small to paint).
  QSize canvas_size() const;
  QImage compose(const QSize& size);
  // Paints the panels, their texts and the legends for a canvas of `size` (already cleared).
  void paint_canvas(QPainter& painter, const QSize& size);
  std::vector<PanelContent> panels();
  std::vector<PanelContent> comparison_panels();
  PanelContent engine_panel();
  PanelContent exact_panel();
  // Paints `panel`'s picture (its image framed by shown_frame_, the exact outlines in camera
  // pixels, its level outlines) into `target` (the painter's logical pixels), clipped to it.
  // `marks`, when given, is paint_marks's drawing for this panel, made beforehand
  // (MarksOverlay): it is drawn instead of stroking the marks again.
  void paint_picture(QPainter& painter, const PanelContent& panel, const QRectF& target,
                     const std::vector<std::vector<Vec2>>& outlines,
                     const QImage* marks = nullptr) const;
  // The marks every panel of one size draws alike: the image rectangle's dotted frame
  // (`image_size`: the panel's image, camera pixels) and the exact outlines dashed, in
  // `target` (the painter's logical pixels). The caller clips the painter to `target`.
  void paint_marks(QPainter& painter, const QSize& image_size, const QRectF& target,
                   const std::vector<std::vector<Vec2>>& outlines) const;
  // The title above the panel's image and its caption lines below it.
  // Caption lines the bands under the frames (top) and under the heat maps must hold, and the
  // titles' one pixel size and lines.
  struct CaptionLines {
    int top = 2;
    int heat = 1;
    int title_px = 12;
    int title_lines = 1;
  };
  // Breaks the panels' captions into lines that fit their cells on a canvas `canvas_width`
  // pixels wide (cells `gap` apart) at the theme's text size, so no number is elided; picks
  // one title size for every panel, the largest of 1.15, 1 and 0.85 times the text size at
  // which every title fits its cell on one line, else the text size with titles broken
  // (wrapped_caption) onto as many lines as the longest needs.
  CaptionLines wrap_captions(std::vector<PanelContent>& contents, int canvas_width, double gap,
                             bool heat_row) const;
  // Where the panels go on a canvas: their contents (captions wrapped for their cells), cells,
  // the legends' rectangle and the caption and title lines.
  struct PanelPlan {
    std::vector<PanelContent> contents;
    std::vector<PanelCell> cells;
    QRectF legends;
    CaptionLines lines;
  };
  // `contents` on a canvas of `size`: with `heat_row`, the comparison's heat maps in a second
  // row, each under its policy, and the legends in the spare cell under the exact panel; else
  // every panel in one row and the legends in a band below it.
  PanelPlan plan_panels(std::vector<PanelContent> contents, const QSize& size, bool heat_row) const;
  // Per panel of `plan` (in `targets`, painted in `windows`: paint_panels), its marks
  // (paint_marks) drawn once into a transparent image of its window's size for every panel
  // that draws the same, else a null image (QPainter's antialiased strokes are dear).
  std::vector<QImage> shared_marks(const PanelPlan& plan, const std::vector<QRectF>& targets,
                                   const std::vector<QRect>& windows,
                                   const std::vector<std::vector<Vec2>>& outlines) const;
  // Paints the pictures of `plan`'s panels (paint_picture), then their texts; records their
  // canvas rectangles in panel_rects_. On a canvas image (Format_RGB32, untransformed) the
  // pictures are painted on core's worker threads, each into its own window of the canvas.
  void paint_panels(QPainter& painter, const PanelPlan& plan,
                    const std::vector<std::vector<Vec2>>& outlines);
  // Whether every title and caption line of `plan` fits its cell's width whole and its
  // images are at least a few text lines high.
  bool texts_fit(const PanelPlan& plan) const;
  // Canvas pixels per camera pixel at which `plan`'s panels draw `content` (zoom 1).
  double content_scale(const PanelPlan& plan, const QRectF& content) const;
  void paint_texts(QPainter& painter, const PanelContent& panel, const PanelCell& cell);
  void paint_band(QPainter& painter, const QRectF& band, bool levels, bool heat);
  // The plane's (scene's) image bounds over the whole loop, and what the framing frames now.
  QRectF fit_content();
  QRectF framed_content();
  void show_readout(QPointF pixel);

  WindowModel* window_;
  AnimationModel* model_;
  AnimationControls* controls_;
  PolicyComparison* comparison_;  // the window model's
  ImageCanvas* canvas_ = nullptr;
  QLabel* inspector_ = nullptr;
  QScrollArea* inspector_area_ = nullptr;
  QLabel* readout_ = nullptr;
  QDoubleSpinBox* zoom_box_ = nullptr;
  QComboBox* exact_box_ = nullptr;
  QComboBox* framing_box_ = nullptr;
  QTimer* blink_timer_;
  const ExactRendererKind* exact_kind_;
  std::unique_ptr<ExactFrameRenderer> exact_;  // of the model's source; null after a change
  Image exact_frame_;
  int exact_frame_index_ = -1;
  PanelDisplay shown_display_ = PanelDisplay::kSideBySide;  // the layout show_panels last showed
  ViewTheme theme_;
  bool blink_phase_ = false;
  bool external_clock_ = false;
  bool panels_in_parallel_ = true;  // paint_panels's threads (set_panels_in_parallel)
  bool shared_marks_ = true;        // set_shared_marks
  bool fit_known_ = false;          // fit_ is up to date with the model's source
  QRectF fit_;                      // the plane's image over its loop (empty: the whole image)
  FrameBounds frame_bounds_;        // what is seen at each frame of the loop
  QRectF shown_frame_;
  std::vector<QRectF> panel_rects_;
  QImage buffers_[2];  // the composed view, painted into in turn (compose)
  // A heat map as last computed, with its caption's figures and what it was computed of: a
  // compared run's frame already on screen (the same run, frame and exact frame) is not mapped
  // again (comparison_heat_map).
  struct HeatMap {
    QImage image;
    QStringList agreement;    // agreement_caption's lines
    std::int64_t holes = -1;  // hole pixels marked; -1 for a policy without holes
    const Animator* animator = nullptr;
    int frame = -1;
    double time_ms = 0.0;
    std::int64_t pixels_written = 0;
    const Pixel* exact = nullptr;
    int exact_frame = -1;
    bool blank = false;  // the map of a frame against itself: one colour, not painted again
  };
  // Run `index`'s heat map against `exact` (the current exact frame), computed when it is not
  // the one already computed.
  const HeatMap& comparison_heat_map(std::size_t index, const ComparedRun& run, const Image& exact);
  std::vector<HeatMap> heat_maps_;  // the heat maps of the last frame, reused
  int map_passes_ = 0;              // heat maps computed (map_passes)
  std::int64_t hole_map_pixels_ = 0;
  int next_buffer_ = 0;
  CaptionLines lines_;  // of the last paint: the titles' size and lines
  // The panels' titles and captions as measured, wrapped and elided before (layout is const).
  mutable TextCache text_cache_;
};

}  // namespace oflab
