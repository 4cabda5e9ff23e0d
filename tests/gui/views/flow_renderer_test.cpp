// The flow view's picture (gui/views/flow_renderer.h): streamline heads on their shafts at
// the common scale, the scene kept out of the caption, a residual that is zero up to
// rounding said in words instead of a colour bar, and one largest magnitude printed by the
// caption and by the colour wheel.
#include "views/flow_renderer.h"

#include <gtest/gtest.h>

#include <QRegularExpression>
#include <algorithm>
#include <cmath>

#include "display/flow_parts.h"
#include "display/palette.h"
#include "flow/plane_scene.h"
#include "image/thread_pool.h"

namespace oflab::test {
namespace {

FlowContext demo_context() {
  const PlaneScene demo = default_demo_scene();
  return make_flow_context(demo.camera, demo.pose, demo.motion);
}

double length_of(const QPolygonF& line) {
  double length = 0.0;
  for (int k = 1; k < line.size(); ++k) {
    length += std::hypot(line[k].x() - line[k - 1].x(), line[k].y() - line[k - 1].y());
  }
  return length;
}

TEST(FlowRenderer, StreamlineHeadsSitOnTheirShaftsAtTheCommonScale) {
  FlowRenderer renderer;
  FlowDisplay display;
  display.part = FlowPart::kTranslation;  // small next to the full flow that sets the scale
  display.common_scale = true;
  display.streamlines = true;
  renderer.update(demo_context(), display, QString());
  ASSERT_FALSE(renderer.streamlines().empty());
  double shortest = 1e300;
  for (const FlowRenderer::Streamline& s : renderer.streamlines()) {
    const double line = length_of(s.line);
    shortest = std::min(shortest, line);
    if (s.head.isEmpty()) continue;
    ASSERT_EQ(s.head.size(), 3);
    // Each arm of the head runs from the line's end (the middle point) backwards.
    const double arm = std::hypot(s.head[0].x() - s.head[1].x(), s.head[0].y() - s.head[1].y());
    EXPECT_LE(arm, 0.5 * line + 1e-9) << "a head longer than half its line floats";
    EXPECT_EQ(s.head[1], s.line.back());
  }
  // The case that matters: lines far shorter than a head of fixed size (0.3 of the seed
  // spacing, several pixels) would be.
  EXPECT_LT(shortest, 5.0);
}

// No arrowhead sticks out past the plane's outline: an arrow whose tip would leave the
// plane is not drawn (the demo's screw motion pushes the edge rows' tips outside).
TEST(FlowRenderer, EveryArrowEndsInsideThePlanesOutline) {
  FlowRenderer renderer;
  FlowDisplay display;
  display.arrows = true;
  renderer.update(demo_context(), display, QString());
  ASSERT_FALSE(renderer.arrows().empty());
  for (const FlowRenderer::Arrow& a : renderer.arrows()) {
    EXPECT_TRUE(renderer.outline().containsPoint(a.from, Qt::OddEvenFill));
    EXPECT_TRUE(renderer.outline().containsPoint(a.to, Qt::OddEvenFill));
  }
  // The negative control: some samples of this motion had tips outside, and were dropped.
  EXPECT_LT(int(renderer.arrows().size()), renderer.shown_samples());
  EXPECT_GT(int(renderer.arrows().size()), renderer.shown_samples() / 2);
}

// The scene's lines painted in strips of rows: the same picture on 1 thread and on 2 (arrows,
// streamlines and the colour wheel clipped to the plane, at a projector's size); against the
// lines painted in one piece, differences only on the rows either side of a seam, by at most
// one level. The control: the picture of a later frame of the motion differs.
TEST(FlowRenderer, TheLinesInStripsAreTheSamePictureOnAnyThreads) {
  FlowDisplay display;
  display.arrows = true;
  display.streamlines = true;
  display.colour_wheel = true;
  const QSize size(1900, 800);
  FlowRenderer renderer;
  renderer.update(demo_context(), display, QString());
  const QImage one = renderer.paint(size).copy();
  set_worker_threads(2);
  const QImage two = renderer.paint(size).copy();
  renderer.set_paint_in_parallel(false);
  const QImage whole = renderer.paint(size).copy();
  renderer.set_paint_in_parallel(true);
  const PlaneScene demo = default_demo_scene();
  PlanePose later = demo.pose;
  later.point += 0.05 * demo.motion.velocity;
  renderer.update(make_flow_context(demo.camera, later, demo.motion), display, QString());
  const QImage other = renderer.paint(size).copy();
  set_worker_threads(1);
  EXPECT_TRUE(one == two);
  EXPECT_FALSE(other == two);
  int largest = 0, off_seam = 0;
  const int seam = size.height() / FlowRenderer::kLineStrips;
  for (int y = 0; y < size.height(); ++y) {
    for (int x = 0; x < size.width(); ++x) {
      const QRgb a = two.pixel(x, y), b = whole.pixel(x, y);
      const int d = std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                              std::abs(qBlue(a) - qBlue(b))});
      largest = std::max(largest, d);
      off_seam += d > 0 && std::abs(y - seam) > 2;
    }
  }
  EXPECT_LE(largest, 1);
  EXPECT_EQ(off_seam, 0);
}

TEST(FlowRenderer, ZoomToPlaneKeepsTheSceneOutOfTheCaption) {
  for (bool presentation : {false, true}) {
    FlowRenderer renderer;
    renderer.set_theme(view_theme(presentation));
    FlowDisplay display;
    display.zoom_to_plane = true;
    display.colour_wheel = true;
    renderer.update(demo_context(), display, QStringLiteral("frame 0, t = 0.00 s"));
    for (const QSize size : {QSize(1400, 900), QSize(900, 500), QSize(1600, 700)}) {
      const QRectF caption = renderer.caption_rect(size), outline = renderer.outline_rect(size);
      ASSERT_FALSE(caption.isEmpty());
      ASSERT_GT(outline.width(), 0.3 * size.width() - 200) << "the plane fills the view";
      EXPECT_GT(outline.top(), caption.bottom())
          << "outline through the caption at " << size.width() << " x " << size.height();
      EXPECT_LT(outline.bottom(), size.height()) << presentation;
    }
  }
}

// Twice the signed area of `polygon` (shoelace).
double twice_area(const QPolygonF& polygon) {
  double sum = 0.0;
  for (int k = 0; k < polygon.size(); ++k) {
    const QPointF& a = polygon[k];
    const QPointF& b = polygon[(k + 1) % polygon.size()];
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

// The panel_fill measure of the flow view: the plane's image over the scene region. The plane
// zoomed to fit lies inside the region, so the share is its outline's area (shoelace over the
// corners in centred pixels, times the square of the view's scale read off the outline's box)
// over the region's (the view left of the legend strip, under the caption). The control:
// without the zoom to the plane the share is smaller.
TEST(FlowRenderer, PlaneShareIsThePlanesImageOverTheSceneRegion) {
  const QSize size(1400, 900);
  double shares[2] = {0, 0};
  for (bool zoom : {true, false}) {
    FlowRenderer renderer;
    renderer.set_theme(view_theme(true));
    FlowDisplay display;
    display.zoom_to_plane = zoom;
    renderer.update(demo_context(), display, QStringLiteral("frame 0, t = 0.00 s"));
    shares[zoom ? 0 : 1] = renderer.plane_share(size);
    if (!zoom) continue;
    const double scale =
        renderer.outline_rect(size).width() / renderer.outline().boundingRect().width();
    const QRectF region = renderer.scene_rect(size);
    EXPECT_TRUE(region.contains(renderer.outline_rect(size)));
    EXPECT_NEAR(region.left(), 0.0, 1e-9);
    EXPECT_GT(region.top(), renderer.caption_rect(size).bottom());
    const double expected = std::abs(twice_area(renderer.outline())) / 2.0 * scale * scale /
                            (region.width() * region.height());
    EXPECT_NEAR(shares[0], expected, 1e-6);
  }
  EXPECT_GT(shares[0], 0.25);
  EXPECT_LT(shares[1], shares[0]) << "the control: the whole image framed";
}

// Pixels of `image` inside `rect` whose colour is the colour bar's lowest (viridis at 0).
int bar_bottom_pixels(const QImage& image, const QRect& rect) {
  const Rgb8 c = magnitude_colour(0.0);
  int n = 0;
  for (int y = rect.top(); y <= rect.bottom(); ++y) {
    for (int x = rect.left(); x <= rect.right(); ++x) {
      const QColor p = image.pixelColor(x, y);
      n += std::abs(p.red() - c.r) + std::abs(p.green() - c.g) + std::abs(p.blue() - c.b) < 12;
    }
  }
  return n;
}

TEST(FlowRenderer, ExactMinusHomographySaysZeroInsteadOfAColourBar) {
  const QSize size(1200, 800);
  const QRect side(size.width() - 130, 0, 130, size.height());
  FlowRenderer renderer;
  FlowDisplay display;
  display.texture = false;
  renderer.update(demo_context(), display, QString());
  EXPECT_FALSE(renderer.rounding_only());
  EXPECT_GT(bar_bottom_pixels(renderer.paint(size), side), 50) << "negative control: a bar";
  display.part = FlowPart::kExactMinusHomography;
  renderer.update(demo_context(), display, QString());
  EXPECT_TRUE(renderer.rounding_only());
  EXPECT_LT(renderer.shown_max_magnitude(), 1e-6);
  EXPECT_TRUE(renderer.caption().contains(QStringLiteral("zero up to rounding")));
  EXPECT_EQ(bar_bottom_pixels(renderer.paint(size), side), 0) << "a colour bar of rounding";
  display.part = FlowPart::kExactMinusAffine;  // a true residual keeps its bar
  renderer.update(demo_context(), display, QString());
  EXPECT_FALSE(renderer.rounding_only());
  EXPECT_FALSE(renderer.caption().contains(QStringLiteral("rounding")));
}

// The number after `before` in `text`.
double number_after(const QString& text, const QString& before) {
  const QRegularExpression re(QRegularExpression::escape(before) + QStringLiteral("([0-9.eE+-]+)"));
  const QRegularExpressionMatch m = re.match(text);
  return m.hasMatch() ? m.captured(1).toDouble() : std::nan("");
}

TEST(FlowRenderer, CaptionAndWheelPrintOneLargestMagnitude) {
  for (FlowPart part : {FlowPart::kFull, FlowPart::kFirstOrder, FlowPart::kSecondOrder}) {
    FlowRenderer renderer;
    FlowDisplay display;
    display.part = part;
    display.colour_wheel = true;
    const FlowContext context = demo_context();
    renderer.update(context, display, QString());
    const double caption = number_after(renderer.caption(), QStringLiteral("max |v| = "));
    const double wheel = number_after(renderer.wheel_caption(), QStringLiteral("0 to "));
    ASSERT_TRUE(std::isfinite(caption)) << renderer.caption().toStdString();
    EXPECT_EQ(caption, wheel) << renderer.wheel_caption().toStdString();
    // The largest magnitude is at least that of a dense grid over the plane's corners'
    // neighbourhood and of the arrow grid (independent samples of the same part).
    const double dense = max_flow_magnitude(sample_flow_grid(context, part, 4.0));
    EXPECT_GE(renderer.shown_max_magnitude(), 0.97 * dense) << flow_part_key(part);
  }
}

}  // namespace
}  // namespace oflab::test
