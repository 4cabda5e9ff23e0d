#include "views/frame_inspector.h"

#include <QStringList>
#include <cmath>

#include "models/animation_model.h"

namespace oflab {
namespace {

QString px(double value) { return QString::number(value, 'f', 2); }

QString layers_summary(const AnimationFrame& f) {
  QStringList counts;
  for (int k = 0; k < kLevelCount; ++k) {
    counts << QStringLiteral("%1 %2").arg(f.levels[size_t(k)]).arg(level_name(Level(k)));
  }
  QString text = QStringLiteral(
                     "<b>Frame %1</b>: %2 of %3 layers drawn (%4).<br>%5% approximated; "
                     "largest measured error %6 px.<br>Culled %7, hidden %8.")
                     .arg(f.frame)
                     .arg(f.drawn())
                     .arg(f.layers)
                     .arg(counts.join(QStringLiteral(", ")))
                     .arg(approximated_percent(f), 0, 'f', 0)
                     .arg(f.drawn() > 0 ? px(f.max_measured_error_px) : QStringLiteral("-"))
                     .arg(f.culled())
                     .arg(f.hidden);
  text += QStringLiteral("<br>The level of each layer is the colour of its outline.");
  if (!f.note.empty()) text += QStringLiteral("<br>Note: %1").arg(QString::fromStdString(f.note));
  return text;
}

// Whether `outline` (image pixels) holds `point`, by the crossing rule.
bool holds(const LayerOutline& outline, const Vec2& point) {
  bool inside = false;
  const std::vector<Vec2>& p = outline.points;
  for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].y > point.y) != (p[j].y > point.y) &&
        point.x < (p[j].x - p[i].x) * (point.y - p[i].y) / (p[j].y - p[i].y) + p[i].x) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace

QString explain_frame(const AnimationFrame& frame, const EngineSettings& settings) {
  if (frame.layer_reports.size() != 1) return layers_summary(frame);
  const FrameReport& r = frame.layer_reports.front();
  if (!r.visible) {
    return QStringLiteral("<b>Frame %1</b>: the plane is not drawn (%2).")
        .arg(r.frame)
        .arg(QString::fromStdString(r.note));
  }
  QString text = QStringLiteral("<b>Frame %1: %2</b>").arg(r.frame).arg(level_name(r.level));
  if (r.frame == 0) return text + QStringLiteral(" (the first frame is rendered exactly).");
  text += QStringLiteral("<br>The cheapest level whose neglected error stays within its "
                         "threshold wins:<br>");
  for (int level = 0; level < kTermCount; ++level) {
    const double error = neglected_error(r.carried, r.flow, Level(level));
    const double limit = settings.thresholds[size_t(level)];
    const QString banned =
        settings.policy->allows(Level(level))
            ? QString()
            : QStringLiteral(" (not allowed by the %1 policy)").arg(settings.policy->name);
    text += QStringLiteral("&nbsp;&nbsp;%1: leaves %2 px %3 %4 px%5<br>")
                .arg(level_name(Level(level)))
                .arg(px(error))
                .arg(error <= limit ? QStringLiteral("&le;") : QStringLiteral("&gt;"))
                .arg(px(limit))
                .arg(banned);
  }
  if (!r.note.empty()) text += QStringLiteral("Note: %1<br>").arg(QString::fromStdString(r.note));
  text += QStringLiteral("Flow this frame (translation, affine, perspective, higher): "
                         "%1, %2, %3, %4 px<br>")
              .arg(px(r.flow[0]), px(r.flow[1]), px(r.flow[2]), px(r.flow[3]));
  text += QStringLiteral("Carried in: %1, %2, %3, %4 px; carried on: %5, %6, %7, %8 px<br>")
              .arg(px(r.carried[0]), px(r.carried[1]), px(r.carried[2]), px(r.carried[3]))
              .arg(px(r.accumulated[0]), px(r.accumulated[1]), px(r.accumulated[2]),
                   px(r.accumulated[3]));
  text += QStringLiteral("Estimated error %1 px; measured (corners against the exact "
                         "projection) %2 px; engine time %3 ms.")
              .arg(px(r.estimated_error_px), px(r.measured_error_px))
              .arg(r.time_ms, 0, 'f', 2);
  return text;
}

QString pixel_readout(const Animator& animator, const Vec2& pixel, const Image& exact) {
  const int x = static_cast<int>(std::floor(pixel.x)), y = static_cast<int>(std::floor(pixel.y));
  const Image& shown = animator.image();
  if (x < 0 || y < 0 || x >= shown.width() || y >= shown.height()) return QString();
  const auto colour = [](const Image& image, int i, int j) {
    if (i >= image.width() || j >= image.height()) return QStringLiteral("-");
    const Pixel p = image.row(j)[i];
    return QStringLiteral("(%1 %2 %3 %4)").arg(p.r).arg(p.g).arg(p.b).arg(p.a);
  };
  QString level = QStringLiteral("no layer");
  for (const LayerOutline& outline : animator.outlines()) {  // back to front: the last wins
    if (holds(outline, pixel)) level = QStringLiteral("level %1").arg(level_name(outline.level));
  }
  return QStringLiteral("pixel (%1, %2): %3, engine %4, exact %5")
      .arg(x)
      .arg(y)
      .arg(level, colour(shown, x, y), colour(exact, x, y));
}

}  // namespace oflab
