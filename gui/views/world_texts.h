// The texts of the world view (gui/views/world_view.h), painted by Qt over VTK's picture:
// the labels naming points of the 3D world (eye, image plane, U, N, V, Omega), the legend at
// the top left and the caption at the bottom. Labels are placed next to the projection of
// their point so that none covers another, the legend or the caption
// (gui/adapters/label_layout.h), and so that they cover none of the drawn content that matters
// (`content`: the image plane's picture and the textured plane, as projected) where a place
// next to their point is clear of it, else the least of it; a label pushed away from its point gets
// a leader line. The caption is wrapped to the picture's width, so no line is cut.
//
// Units: canvas pixels (the picture's), top-left origin, y down; label points in world
// units of the world view's frame.
#pragma once

#include <QColor>
#include <QFont>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QSize>
#include <QString>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "adapters/view_theme.h"
#include "flow/geometry.h"

class QPainter;

namespace oflab {

// A label naming a point of the world.
struct WorldLabel {
  std::string text;
  Vec3 at{0.0};  // world units
  RgbF colour{0.0, 0.0, 0.0};
  bool shown = true;
};

// The labels, in the order they are placed (the first placed keeps its wanted place).
enum WorldLabelId { kEyeLabel, kImageLabel, kUpLabel, kNormalLabel, kVelocityLabel, kOmegaLabel };
constexpr int kWorldLabelCount = 6;

class WorldTexts {
 public:
  // Where a world point lands on the canvas (canvas pixels); false when it is behind the
  // camera or outside the canvas (its label is then left out).
  using Projector = std::function<bool(const Vec3& world, QPointF* canvas)>;

  std::array<WorldLabel, kWorldLabelCount> labels;
  std::string caption;  // paragraphs separated by "\n"
  std::string legend = "World: the cause of the flow";
  // The outlines of the drawn pictures the labels should leave clear (canvas pixels), set
  // before lay_out.
  std::vector<QPolygonF> content;

  // Places every text for a canvas of `size` (not empty) in `base`'s family at the theme's
  // sizes (legend font_size bold, labels label_size bold, caption label_size), the labels at
  // the points `project` gives.
  void lay_out(const QSize& size, const QFont& base, const ViewTheme& theme,
               const Projector& project);
  // Paints the texts as last laid out, each over a translucent patch of the theme's
  // background so that it reads over lines and textures.
  void paint(QPainter& painter) const;
  // The picture's band between the legend and the caption as last laid out (the whole
  // width; canvas pixels): where the world is seen whole; empty before a lay_out.
  QRectF free_area() const { return free_area_; }
  // The labels as last laid out (not the legend or caption) whose box, less a pixel each
  // side, covers a square pixel or more of `content`, each as "TEXT covers N px of the pictures".
  std::vector<QString> labels_over_content() const;

 private:
  // The parts of lay_out, in its order; each adds its texts to drawn_ and the boxes the
  // labels must not cover to `taken`. The legend at the top left, in the legend font.
  void lay_out_legend(const QFont& base, const ViewTheme& theme, std::vector<QRectF>& taken);
  // The caption's lines, wrapped to the canvas's width, at the bottom left.
  void lay_out_caption(const QSize& size, const QFont& base, const ViewTheme& theme,
                       std::vector<QRectF>& taken);
  // Each shown label whose point `project` puts on the canvas, placed clear of `taken` and
  // of each other, with a leader line when pushed away from its point.
  void lay_out_labels(const QSize& size, const QFont& base, const ViewTheme& theme,
                      const Projector& project, const std::vector<QRectF>& taken);

  struct Drawn {
    QString text;
    QRectF box;  // from the ascent to the descent, as wide as the text's advance
    QFont font;
    QColor colour;
    bool leader = false;  // a line from `anchor` to the box
    QPointF anchor;
    bool label = false;  // names a point (not the legend or the caption)
  };
  std::vector<Drawn> drawn_;
  QRectF free_area_;
  // The caption's lines and their advances as last wrapped, with what they were wrapped of
  // (the caption, the font's key, the width to the bit): the same caption laid out again is
  // not shaped again (wrap_text measures each word's line as it grows).
  struct WrappedCaption {
    QString text;
    QString font_key;
    double width = -1.0;
    std::vector<QString> lines;
    std::vector<double> advances;
  };
  WrappedCaption wrapped_caption_;
  QColor patch_;
  double leader_width_ = 1.0;
};

}  // namespace oflab
