#include "adapters/flow_renderer.h"

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3D.h>
#include <vtkGlyphSource2D.h>
#include <vtkImageData.h>
#include <vtkImageMapper3D.h>
#include <vtkImageProperty.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

#include <QPainter>

#include "flow/homography.h"
#include "scene/view_culling.h"
#include "adapters/vtk_adapters.h"

namespace oflab {
namespace {

constexpr double kDegreesPerRadian = 57.29577951308232;
constexpr double kWheelStepPx = 3.0;
constexpr double kNearPlane = 1e-3;  // world units: nearer than this counts as not seen  // wheel image resolution, image pixels per cell

vtkSmartPointer<vtkActor> line_actor() {
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(vtkSmartPointer<vtkPolyDataMapper>::New());
  return actor;
}

void set_input(vtkActor* actor, vtkPolyData* data) {
  vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->SetInputData(data);
}

// A camera at the eye looking along +Z with image rows growing downwards (Y down).
void look_from_eye(vtkCamera* camera) {
  camera->SetPosition(0.0, 0.0, 0.0);
  camera->SetFocalPoint(0.0, 0.0, 1.0);
  camera->SetViewUp(0.0, -1.0, 0.0);
}

// The plane's quad in 3D with texture coordinates, top-left texel corner at (0, 1).
vtkSmartPointer<vtkPolyData> textured_quad(const PlanePose& pose) {
  const std::array<Vec3, 4> corners = plane_corners(pose);
  auto data = closed_outline({corners.begin(), corners.end()});
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType quad[4] = {0, 1, 2, 3};
  polys->InsertNextCell(4, quad);
  data->SetPolys(polys);
  data->SetLines(nullptr);
  auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
  tcoords->SetNumberOfComponents(2);
  const float uv[5][2] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}, {0, 1}};
  for (const auto& t : uv) tcoords->InsertNextTuple(t);
  data->GetPointData()->SetTCoords(tcoords);
  return data;
}

// The display's spacing, or one that puts about 14 arrows across the plane's image.
double arrow_spacing(const FlowContext& context, const FlowDisplay& display) {
  if (display.spacing_px > 0.0) return std::max(4.0, display.spacing_px);
  Vec2 low(1e300), high(-1e300);
  for (const Vec2& c : projected_corners(context.camera, context.pose)) {
    low = glm::min(low, c);
    high = glm::max(high, c);
  }
  const double extent = std::min(std::max(high.x - low.x, high.y - low.y),
                                 double(std::max(context.camera.width, context.camera.height)));
  return std::clamp(extent / 14.0, 6.0, 48.0);
}

// The smallest 1, 2 or 5 times a power of ten at or above `value` (> 0), so the colour bar
// keeps its labels while the largest magnitude drifts from frame to frame.
double round_up_to_nice(double value) {
  if (!(value > 0.0)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  for (double step : {1.0, 2.0, 5.0, 10.0}) {
    if (step * decade >= value * (1.0 - 1e-12)) return step * decade;
  }
  return 10.0 * decade;
}

// The plane's centre is in front of the camera and projects inside the image: a plane
// seen edge-on there covers no pixel but is not outside the picture.
bool centre_in_image(const Camera& camera, const PlanePose& pose) {
  if (!(pose.point.z > 0.0)) return false;
  const Vec2 p = project_centred(camera, pose.point);
  return std::abs(p.x) <= 0.5 * camera.width && std::abs(p.y) <= 0.5 * camera.height;
}

}  // namespace

FlowRenderer::FlowRenderer(vtkRenderWindow* window) : window_(window), theme_(view_theme(false)) {
  scene_ = vtkSmartPointer<vtkRenderer>::New();
  overlay_ = vtkSmartPointer<vtkRenderer>::New();
  overlay_->SetLayer(1);
  overlay_->InteractiveOff();
  // The colour-wheel legend: a unit disc in a small square viewport of its own, so it
  // stays round and in view at any zoom.
  legend_ = vtkSmartPointer<vtkRenderer>::New();
  legend_->SetLayer(1);
  legend_->InteractiveOff();
  legend_->GetActiveCamera()->ParallelProjectionOn();
  legend_->GetActiveCamera()->SetPosition(0.0, 0.0, -5.0);
  legend_->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  legend_->GetActiveCamera()->SetViewUp(0.0, -1.0, 0.0);  // y down, as in the image
  legend_->GetActiveCamera()->SetParallelScale(1.05);
  legend_->GetActiveCamera()->SetClippingRange(1.0, 10.0);
  // The legend strip on the right: the scalar bar above, the wheel legend below, so
  // neither covers the flow.
  side_ = vtkSmartPointer<vtkRenderer>::New();
  side_->InteractiveOff();
  window_->SetNumberOfLayers(2);
  window_->AddRenderer(side_);
  window_->AddRenderer(scene_);
  window_->AddRenderer(overlay_);
  window_->AddRenderer(legend_);
  look_from_eye(scene_->GetActiveCamera());
  look_from_eye(overlay_->GetActiveCamera());
  overlay_->GetActiveCamera()->SetClippingRange(0.5, 2.0);
  fit_callback_ = vtkSmartPointer<vtkCallbackCommand>::New();
  fit_callback_->SetCallback(&FlowRenderer::on_render_start);
  fit_callback_->SetClientData(this);
  window_->AddObserver(vtkCommand::StartEvent, fit_callback_);
  create_actors();
  set_theme(theme_);
}

FlowRenderer::~FlowRenderer() {
  window_->RemoveObserver(fit_callback_);
  window_->RemoveRenderer(scene_);
  window_->RemoveRenderer(overlay_);
  window_->RemoveRenderer(legend_);
  window_->RemoveRenderer(side_);
}

void FlowRenderer::create_actors() {
  plane_ = line_actor();
  texture_ = vtkSmartPointer<vtkTexture>::New();
  texture_->InterpolateOn();
  plane_->SetTexture(texture_);
  plane_->GetProperty()->LightingOff();
  scene_->AddActor(plane_);
  frame_ = line_actor();
  outline_ = line_actor();
  centre_mark_ = line_actor();
  streamlines_ = line_actor();
  wheel_legend_ = line_actor();
  wheel_legend_->GetProperty()->LightingOff();
  wheel_image_ = vtkSmartPointer<vtkImageActor>::New();
  wheel_image_->GetProperty()->SetInterpolationTypeToLinear();
  wheel_data_ = vtkSmartPointer<vtkImageData>::New();
  wheel_image_->GetMapper()->SetInputData(wheel_data_);
  wheel_image_->VisibilityOff();
  create_arrow_pipeline();
  create_legend_and_text();
  for (vtkProp* prop :
       std::initializer_list<vtkProp*>{wheel_image_, frame_, outline_, centre_mark_, streamlines_,
                                       arrows_, caption_, wheel_caption_}) {
    overlay_->AddViewProp(prop);
  }
  wheel_legend_->GetMapper()->SetInputDataObject(
      coloured_disc(1.0, [](const Vec2& offset) { return flow_wheel_colour(offset, 1.0); }));
  legend_->AddActor(wheel_legend_);
  side_->AddViewProp(scalar_bar_);
  side_->AddViewProp(scalar_title_);
}

// Arrow glyphs: each input point carries its flow vector (world units, already scaled)
// and its magnitude (px/s, coloured through the lookup table).
void FlowRenderer::create_arrow_pipeline() {
  auto glyph = vtkSmartPointer<vtkGlyphSource2D>::New();
  glyph->SetGlyphTypeToArrow();
  glyph->FilledOn();
  glyph->SetCenter(0.5, 0.0, 0.0);  // the arrow starts at the sample point
  arrow_input_ = vtkSmartPointer<vtkPolyData>::New();
  auto glyphs = vtkSmartPointer<vtkGlyph3D>::New();
  glyphs->SetSourceConnection(glyph->GetOutputPort());
  glyphs->SetInputData(arrow_input_);
  glyphs->SetVectorModeToUseVector();
  glyphs->SetScaleModeToScaleByVector();
  glyphs->SetColorModeToColorByScalar();
  glyphs->OrientOn();
  auto arrow_mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  arrow_mapper->SetInputConnection(glyphs->GetOutputPort());
  arrows_ = vtkSmartPointer<vtkActor>::New();
  arrows_->SetMapper(arrow_mapper);
  arrows_->GetProperty()->LightingOff();
}

void FlowRenderer::create_legend_and_text() {
  scalar_bar_ = vtkSmartPointer<vtkScalarBarActor>::New();
  scalar_bar_->SetTitle("");  // the title sits in scalar_title_, clear of the labels
  scalar_bar_->SetLookupTable(magnitude_lookup_table(1.0));
  scalar_bar_->SetLabelFormat("%.3g");
  scalar_bar_->SetVerticalTitleSeparation(8);
  scalar_bar_->SetNumberOfLabels(5);
  scalar_bar_->SetPosition(0.08, 0.30);
  scalar_bar_->SetWidth(0.9);
  scalar_bar_->SetHeight(0.58);
  scalar_bar_->SetBarRatio(0.3);
  scalar_bar_->UnconstrainedFontSizeOn();
  caption_ = vtkSmartPointer<vtkTextActor>::New();
  caption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  caption_->SetPosition(0.01, 0.99);
  caption_->GetTextProperty()->SetVerticalJustificationToTop();
  scalar_title_ = vtkSmartPointer<vtkTextActor>::New();
  scalar_title_->SetInput("|v| px/s");
  scalar_title_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  scalar_title_->SetPosition(0.04, 0.90);
  wheel_caption_ = vtkSmartPointer<vtkTextActor>::New();
  wheel_caption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  wheel_caption_->SetPosition(0.01, 0.015);
}

void FlowRenderer::set_texture(const QImage& texture) {
  texture_image_ = texture;
  update_faded_texture();
}

// The texture faded towards the background, drawn opaque: the same picture as a
// translucent plane, without VTK's translucent pass (several full-window passes on a
// software renderer).
void FlowRenderer::update_faded_texture() {
  if (texture_image_.isNull()) return;
  QImage faded(texture_image_.size(), QImage::Format_RGB32);
  faded.fill(QColor::fromRgbF(theme_.background[0], theme_.background[1], theme_.background[2]));
  QPainter painter(&faded);
  painter.setOpacity(theme_.presentation ? 0.6 : 0.45);
  painter.drawImage(0, 0, texture_image_);
  painter.end();
  texture_->SetInputData(image_data_from_qimage(faded));
}

void FlowRenderer::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  for (vtkRenderer* r : {scene_.Get(), side_.Get()}) {
    r->SetBackground(theme.background[0], theme.background[1], theme.background[2]);
  }
  set_line_style(frame_->GetProperty(), theme.muted, theme.line_width);
  set_line_style(outline_->GetProperty(), theme.outline, theme.line_width + 1.0);
  set_line_style(centre_mark_->GetProperty(), theme.outline, theme.line_width);
  set_line_style(streamlines_->GetProperty(), theme.streamline, theme.line_width);
  arrows_->GetProperty()->SetLineWidth(static_cast<float>(theme.line_width));
  set_text_style(caption_->GetTextProperty(), theme.text, theme.font_size);
  set_text_style(wheel_caption_->GetTextProperty(), theme.text, theme.label_size);
  set_text_style(scalar_title_->GetTextProperty(), theme.text, theme.label_size);
  for (vtkTextProperty* p :
       {scalar_bar_->GetTitleTextProperty(), scalar_bar_->GetLabelTextProperty()}) {
    set_text_style(p, theme.text, theme.label_size);
    p->BoldOff();
    p->ItalicOff();
    p->ShadowOff();
  }
  update_faded_texture();
}

double FlowRenderer::smallest_text_px() const {
  int points = caption_->GetTextProperty()->GetFontSize();
  for (vtkTextProperty* p : {wheel_caption_->GetTextProperty(), scalar_title_->GetTextProperty(),
                             scalar_bar_->GetLabelTextProperty()}) {
    points = std::min(points, p->GetFontSize());
  }
  return font_points_to_px(points, window_);
}

void FlowRenderer::update(const FlowContext& context, const FlowDisplay& display,
                          const QString& frame_caption) {
  camera_ = context.camera;
  plane_in_image_ = plane_meets_image(context.camera, context.pose, kNearPlane) ||
                    centre_in_image(context.camera, context.pose);
  // With the plane out of the picture, the whole image is shown (there is nothing to zoom to).
  FlowDisplay framing = display;
  if (!plane_in_image_) framing.zoom_to_plane = false;
  choose_view_region(context, framing);
  update_plane(context, display);
  const double spacing = arrow_spacing(context, display);
  const std::vector<FlowSample> full = sample_flow_grid(context, FlowPart::kFull, spacing);
  const std::vector<FlowSample> shown =
      display.part == FlowPart::kFull ? full : sample_flow_grid(context, display.part, spacing);
  shown_max_ = max_flow_magnitude(shown);
  shown_samples_ = static_cast<int>(shown.size());
  // Each part fills the grid unless the common scale is asked for, or the part is zero up
  // to rounding (a residual): then the full flow sets the scale, so parts compare by length
  // and rounding noise is never blown up into arrows.
  const double full_max = max_flow_magnitude(full);
  const bool rounding_only = shown_max_ <= 1e-9 * full_max;
  const double scale_max = display.common_scale || rounding_only ? full_max : shown_max_;
  const double arrow_seconds = scale_max > 0.0 ? 0.9 * spacing / scale_max : 0.0;
  // A plane that has left the picture has no flow to show: no arrows, lines, wheel or
  // colour bar, and the caption says so (the side table's terms are those of the plane
  // extended beyond the image).
  FlowDisplay drawn = display;
  if (!plane_in_image_) drawn.arrows = drawn.streamlines = drawn.colour_wheel = false;
  update_arrows(shown, arrow_seconds, drawn);
  update_streamlines(context, drawn, arrow_seconds);
  update_wheel(context, drawn);
  update_caption(display, frame_caption);
}

void FlowRenderer::update_plane(const FlowContext& context, const FlowDisplay& display) {
  const std::array<Vec2, 4> corners = projected_corners(context.camera, context.pose);
  std::vector<Vec3> outline;
  for (const Vec2& c : corners) outline.push_back(image_plane_point(context.camera, c));
  set_input(outline_, closed_outline(outline));
  const double hw = 0.5 * context.camera.width, hh = 0.5 * context.camera.height;
  std::vector<Vec3> frame;
  for (const Vec2& c : {Vec2(-hw, -hh), Vec2(hw, -hh), Vec2(hw, hh), Vec2(-hw, hh)}) {
    frame.push_back(image_plane_point(context.camera, c));
  }
  set_input(frame_, closed_outline(frame));
  // The principal point, where the coefficients of the side table are taken.
  const double r = 8.0;
  set_input(centre_mark_, polylines({{image_plane_point(context.camera, Vec2(-r, 0.0)),
                                      image_plane_point(context.camera, Vec2(r, 0.0))},
                                     {image_plane_point(context.camera, Vec2(0.0, -r)),
                                      image_plane_point(context.camera, Vec2(0.0, r))}}));
  set_input(plane_, textured_quad(context.pose));
  plane_->SetVisibility(display.texture);
  double near = 1e300, far = 0.0;
  for (const Vec3& c : plane_corners(context.pose)) {
    near = std::min(near, c.z);
    far = std::max(far, c.z);
  }
  scene_->GetActiveCamera()->SetClippingRange(0.5 * near, 2.0 * far + 1.0);
}

void FlowRenderer::update_arrows(const std::vector<FlowSample>& samples, double arrow_seconds,
                                 const FlowDisplay& display) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto vectors = vtkSmartPointer<vtkDoubleArray>::New();
  vectors->SetNumberOfComponents(3);
  auto magnitudes = vtkSmartPointer<vtkDoubleArray>::New();
  const double to_world = arrow_seconds / camera_.focal_px;
  for (const FlowSample& s : samples) {
    const Vec3 p = image_plane_point(camera_, s.position);
    points->InsertNextPoint(p.x, p.y, p.z);
    vectors->InsertNextTuple3(s.flow.x * to_world, s.flow.y * to_world, 0.0);
    magnitudes->InsertNextValue(glm::length(s.flow));
  }
  arrow_input_->SetPoints(points);
  arrow_input_->GetPointData()->SetVectors(vectors);
  arrow_input_->GetPointData()->SetScalars(magnitudes);
  arrow_input_->Modified();
  // A new table only when the bar's rounded range changes: rebuilding the scalar bar is
  // a large part of a frame.
  const double bar_max = round_up_to_nice(shown_max_);
  if (bar_max != bar_max_ || bar_presentation_ != theme_.presentation) {
    bar_max_ = bar_max;
    bar_presentation_ = theme_.presentation;
    auto table = magnitude_lookup_table(bar_max, theme_.presentation ? 0.8 : 1.0);
    auto* mapper = arrows_->GetMapper();
    mapper->SetLookupTable(table);
    mapper->SetScalarRange(table->GetRange());
    scalar_bar_->SetLookupTable(table);
  }
  arrows_->SetVisibility(display.arrows);
  scalar_bar_->SetVisibility(display.arrows);
  scalar_title_->SetVisibility(display.arrows);
}

void FlowRenderer::update_streamlines(const FlowContext& context, const FlowDisplay& display,
                                      double arrow_seconds) {
  std::vector<std::vector<Vec3>> lines;
  if (display.streamlines && arrow_seconds > 0.0) {
    const double seed_spacing = 2.0 * arrow_spacing(context, display);
    for (const FlowSample& seed : sample_flow_grid(context, FlowPart::kTranslation, seed_spacing)) {
      const std::vector<Vec2> path =
          trace_streamline(context, display.part, seed.position, 2.5 * arrow_seconds, 16);
      // The line, then an arrow head at its end so the direction reads.
      for (const std::vector<Vec2>& part : {path, streamline_arrow_head(path, 0.3 * seed_spacing)}) {
        if (part.size() < 2) continue;
        std::vector<Vec3> line;
        for (const Vec2& p : part) line.push_back(image_plane_point(context.camera, p));
        lines.push_back(line);
      }
    }
  }
  set_input(streamlines_, polylines(lines));
  streamlines_->SetVisibility(display.streamlines);
}

void FlowRenderer::update_wheel(const FlowContext& context, const FlowDisplay& display) {
  wheel_image_->SetVisibility(display.colour_wheel);
  wheel_legend_->SetVisibility(display.colour_wheel);
  wheel_caption_->SetVisibility(display.colour_wheel);
  if (!display.colour_wheel) return;
  const int nx = static_cast<int>(std::ceil(context.camera.width / kWheelStepPx));
  const int ny = static_cast<int>(std::ceil(context.camera.height / kWheelStepPx));
  std::vector<Vec2> flows(static_cast<size_t>(nx) * ny);
  std::vector<bool> inside(flows.size());
  double largest = 0.0;
  auto centre_of = [&](int i, int j) {
    return Vec2(-0.5 * context.camera.width + (i + 0.5) * kWheelStepPx,
                -0.5 * context.camera.height + (j + 0.5) * kWheelStepPx);
  };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const size_t k = static_cast<size_t>(j) * nx + i;
      inside[k] = sees_plane(context, centre_of(i, j));
      if (!inside[k]) continue;
      flows[k] = flow_part_at(context, display.part, centre_of(i, j));
      largest = std::max(largest, glm::length(flows[k]));
    }
  }
  // One image kept from frame to frame, opaque (RGB, the background where the plane is
  // not seen): a translucent image would cost VTK's translucent pass every frame.
  vtkImageData* image = wheel_data_;
  if (image->GetDimensions()[0] != nx || image->GetDimensions()[1] != ny) {
    image->SetDimensions(nx, ny, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  }
  // Slightly behind the image plane (same projection), so arrows and lines draw on top.
  constexpr double kBehind = 1.002;
  const Vec3 origin = kBehind * image_plane_point(context.camera, centre_of(0, 0));
  image->SetOrigin(origin.x, origin.y, origin.z);
  const double step = kBehind * kWheelStepPx / context.camera.focal_px;
  image->SetSpacing(step, step, 1.0);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  const Rgb8 background{static_cast<unsigned char>(std::lround(255.0 * theme_.background[0])),
                        static_cast<unsigned char>(std::lround(255.0 * theme_.background[1])),
                        static_cast<unsigned char>(std::lround(255.0 * theme_.background[2]))};
  for (size_t k = 0; k < flows.size(); ++k) {
    const Rgb8 c = inside[k] ? flow_wheel_colour(flows[k], largest) : background;
    rgb[3 * k] = c.r, rgb[3 * k + 1] = c.g, rgb[3 * k + 2] = c.b;
  }
  image->Modified();
  wheel_caption_->SetInput(QStringLiteral("Colour wheel (bottom right): hue = direction, "
                                          "white to full colour = 0 to %1 px/s")
                               .arg(largest, 0, 'g', 3)
                               .toUtf8()
                               .constData());
}

void FlowRenderer::update_caption(const FlowDisplay& display, const QString& frame_caption) {
  if (!plane_in_image_ || shown_samples_ == 0) {
    // Outside, or seen so nearly edge-on that no grid sample falls inside it: there is no
    // flow to show and no residual to call zero.
    caption_text_ = plane_in_image_
                        ? QStringLiteral("%1: no grid sample falls inside the plane's image (seen "
                                         "edge-on or too small), so there is nothing to compare")
                              .arg(QString::fromUtf8(flow_part_title(display.part)))
                        : QStringLiteral("The plane is outside the image: no flow to show");
    if (!frame_caption.isEmpty()) caption_text_ += QStringLiteral("\n") + frame_caption;
    caption_->SetInput(caption_text_.toUtf8().constData());
    return;
  }
  const bool residual =
      display.part == FlowPart::kExactMinusHomography || display.part == FlowPart::kExactMinusAffine;
  QString text = QStringLiteral("%1   max |v| = %2 px/s")
                     .arg(QString::fromUtf8(flow_part_title(display.part)))
                     .arg(shown_max_, 0, 'g', 3);
  if (residual && shown_max_ < 1e-6) text += QStringLiteral(" (zero up to rounding)");
  if (!frame_caption.isEmpty()) text += QStringLiteral("\n") + frame_caption;
  caption_text_ = text;
  caption_->SetInput(text.toUtf8().constData());
}

void FlowRenderer::choose_view_region(const FlowContext& context, const FlowDisplay& display) {
  const Vec2 image_half(0.5 * context.camera.width, 0.5 * context.camera.height);
  if (!display.zoom_to_plane) {
    view_centre_ = Vec2(0.0);
    view_half_size_ = image_half;
    return;
  }
  Vec2 low(0.0), high(0.0);  // start from the principal point, so it stays in view
  for (const Vec2& c : projected_corners(context.camera, context.pose)) {
    low = glm::min(low, c);
    high = glm::max(high, c);
  }
  low = glm::max(low, -image_half);
  high = glm::min(high, image_half);
  view_centre_ = 0.5 * (low + high);
  view_half_size_ = glm::max(0.5 * (high - low), Vec2(40.0));
}

void FlowRenderer::fit_view_angle() {
  const int* size = window_->GetSize();
  if (size[0] < 1 || size[1] < 1 || camera_.focal_px <= 0.0) return;
  const double aspect = scene_fraction() * size[0] / size[1];
  // Half-height of the view in image pixels, with a margin for captions and the legend.
  const double half_h = 1.12 * std::max(view_half_size_.y, view_half_size_.x / aspect);
  const double angle = 2.0 * std::atan(half_h / camera_.focal_px) * kDegreesPerRadian;
  // Off-axis window centre, in units of the view's half extent: screen x follows X, screen
  // y is -Y (image rows grow downwards).
  const double wx = view_centre_.x / (half_h * aspect), wy = -view_centre_.y / half_h;
  for (vtkRenderer* r : {scene_.Get(), overlay_.Get()}) {
    r->GetActiveCamera()->SetViewAngle(angle);
    r->GetActiveCamera()->SetWindowCenter(wx, wy);
  }
}

double FlowRenderer::side_width_px() const {
  return std::clamp(0.14 * window_->GetSize()[0], 80.0, 130.0);
}

double FlowRenderer::scene_fraction() const {
  const int width = window_->GetSize()[0];
  return width > 0 ? 1.0 - side_width_px() / width : 1.0;
}

void FlowRenderer::place_legend() {
  const int* size = window_->GetSize();
  if (size[0] < 1 || size[1] < 1) return;
  const double split = scene_fraction();
  scene_->SetViewport(0.0, 0.0, split, 1.0);
  overlay_->SetViewport(0.0, 0.0, split, 1.0);
  side_->SetViewport(split, 0.0, 1.0, 1.0);
  const double side = std::min(side_width_px() - 8.0, 0.28 * size[1]);
  legend_->SetViewport(1.0 - (side + 4.0) / size[0], 0.03, 1.0 - 4.0 / size[0],
                       0.03 + side / size[1]);
}

void FlowRenderer::on_render_start(vtkObject*, unsigned long, void* self, void*) {
  static_cast<FlowRenderer*>(self)->place_legend();
  static_cast<FlowRenderer*>(self)->fit_view_angle();
}

}  // namespace oflab
