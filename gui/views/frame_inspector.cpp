#include "views/frame_inspector.h"

#include <QStringList>
#include <cmath>

#include "flow/flow_field.h"

namespace oflab {
namespace {

QString px(double value) { return QString::number(value, 'f', 2); }

QString scene_summary(const FrameRecord& r) {
  QStringList counts;
  for (int k = 0; k < kLevelCount; ++k) {
    counts << QStringLiteral("%1 %2").arg(r.levels[size_t(k)]).arg(level_name(Level(k)));
  }
  return QStringLiteral(
             "<b>Frame %1</b>: %2 polygons drawn (%3).<br>%4% approximated; largest measured "
             "error %5 px.<br>Each polygon has its own engine and its own error books; the "
             "level of each is the colour of its outline.")
      .arg(r.frame)
      .arg(r.drawn)
      .arg(counts.join(QStringLiteral(", ")))
      .arg(r.approximated_percent, 0, 'f', 0)
      .arg(std::isnan(r.measured_error_px) ? QStringLiteral("-") : px(r.measured_error_px));
}

}  // namespace

QString explain_frame(const FrameRecord& record, const EngineSettings& settings) {
  if (!record.has_books) return scene_summary(record);
  const FrameReport& r = record.plane;
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

QString pixel_readout(const AnimationSession& session, const Vec2& pixel, const Image& exact) {
  const int x = static_cast<int>(std::floor(pixel.x)), y = static_cast<int>(std::floor(pixel.y));
  const Image& shown = session.frame_image();
  if (x < 0 || y < 0 || x >= shown.width() || y >= shown.height()) return QString();
  QString text = QStringLiteral("pixel (%1, %2)").arg(x).arg(y);
  const auto colour = [](const Image& image, int i, int j) {
    if (i >= image.width() || j >= image.height()) return QStringLiteral("-");
    const Pixel p = image.row(j)[i];
    return QStringLiteral("(%1 %2 %3 %4)").arg(p.r).arg(p.g).arg(p.b).arg(p.a);
  };
  if (session.source().is_scene() || !session.current().plane.visible) {
    return text + QStringLiteral(": engine %1, exact %2").arg(colour(shown, x, y), colour(exact, x, y));
  }
  const Camera& camera = session.source().camera();
  const Vec2 centre(x + 0.5, y + 0.5);
  const Vec2 texel = apply_homography(glm::inverse(session.displayed_warp()), centre);
  const PlanePose pose = session.plane_pose();
  const bool inside = texel.x >= 0 && texel.y >= 0 && texel.x <= pose.texture_size.x &&
                      texel.y <= pose.texture_size.y;
  if (!inside) return text + QStringLiteral(": outside the plane");
  const Vec2 flow = flow_at(planar_flow_coefficients(camera, pose, session.plane_motion()),
                            pixel_to_centred(camera, centre));
  const Vec2 truth = apply_homography(session.exact_warp(), texel);
  return text + QStringLiteral(": flow (%1, %2) px/frame, level %3, error %4 px")
                    .arg(px(flow.x), px(flow.y))
                    .arg(level_name(session.current().plane.level))
                    .arg(px(glm::length(truth - centre)));
}

}  // namespace oflab
