#include "views/frame_inspector.h"

#include <QStringList>
#include <cmath>
#include <vector>

#include "models/animation_model.h"

namespace oflab {
namespace {

QString px(double value) { return QString::number(value, 'f', 2); }

QString layers_summary(const AnimationFrame& f, const ReusePolicy& policy) {
  // One count per word of the policy's own (a cadence policy's four warp levels are all
  // "reprojected").
  QStringList words;
  std::vector<int> sums;
  for (int k = 0; k < kLevelCount; ++k) {
    const QString word = QString::fromLatin1(level_word(policy, Level(k)));
    const int at = int(words.indexOf(word));
    if (at < 0) {
      words << word;
      sums.push_back(f.levels[size_t(k)]);
    } else {
      sums[size_t(at)] += f.levels[size_t(k)];
    }
  }
  QStringList counts;
  for (int k = 0; k < int(words.size()); ++k) {
    counts << QStringLiteral("%1 %2").arg(sums[size_t(k)]).arg(words[k]);
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
  const QString reason = not_drawn_reason(f);
  if (!reason.isEmpty())
    text += QStringLiteral("<br>Nothing is drawn: %1.").arg(reason.toHtmlEscaped());
  if (policy.initial_view == InitialView::kAffinePart && f.levels[size_t(Level::kRerender)] > 0) {
    text += QStringLiteral(
                "<br>Re-rendered layers show the %1 policy's affine initial view "
                "(section 6.5), not the exact projection.")
                .arg(QString::fromUtf8(policy.name));
  }
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

// What a reuse level of `policy` does to the previous image, in a few words.
QString reuse_words(const ReusePolicy& policy, Level level) {
  if (policy.pixel_motion == PixelMotion::kMotionVectors) {
    return QStringLiteral(
        "the last render, each pixel moved along its motion vector, "
        "extrapolated");
  }
  if (policy.pixel_motion == PixelMotion::kBetweenRenders) {
    return QStringLiteral("the renders before and after, each pixel moved by its depth");
  }
  if (policy.pixel_motion == PixelMotion::kFarMesh) {
    return QStringLiteral("the near part rendered, the far part's depth mesh drawn from here");
  }
  if (policy.frame_warp == FrameWarp::kPerPixelDepth) {
    return QStringLiteral("the last render, each pixel moved by its depth");
  }
  if (policy.schedule == Schedule::kCadence) {
    return QStringLiteral("the last render, reprojected by the %1 policy's homography")
        .arg(QString::fromUtf8(policy.name));
  }
  switch (level) {
    case Level::kNone:
      return QStringLiteral("the previous image, unchanged");
    case Level::kTranslate:
      return QStringLiteral("the previous image moved by whole pixels");
    case Level::kAffine:
      return QStringLiteral("an affine warp of the perspective cache");
    case Level::kPerspective:
      return QStringLiteral("a new perspective cache, then its affine warp");
    default:
      return QStringLiteral("a re-render");
  }
}

// The note of the first layer that is not visible, empty when every layer is.
QString hidden_layer_note(const AnimationFrame& f) {
  for (const FrameReport& r : f.layer_reports) {
    if (!r.visible) {
      return r.note.empty() ? QStringLiteral("not visible") : QString::fromStdString(r.note);
    }
  }
  return QString();
}

}  // namespace

QString scene_panel_note(const AnimationModel& model) {
  const AnimationSourceKind& kind = model.source_kind();
  if (kind.follows_scene_panel) return QString();
  const SourceChoice& source = model.source();
  QString playing = QString::fromStdString(fill_pattern(kind.label, source.name));
  if (kind.uses_viewer && !source.viewer.empty()) {
    playing += QObject::tr(" (viewer script %1)").arg(QString::fromStdString(source.viewer));
  }
  return QObject::tr(
             "This view plays %1, not the plane of this panel: the plane, motion and "
             "camera below apply to the flow and basis views.")
      .arg(playing);
}

QString not_drawn_reason(const AnimationFrame& frame) {
  if (frame.drawn() > 0) return QString();
  const QString note = hidden_layer_note(frame);
  if (!note.isEmpty()) return note;
  if (frame.outside_frustum > 0) return QStringLiteral("outside the image");
  if (frame.back_facing > 0) return QStringLiteral("seen from behind or edge-on");
  if (!frame.note.empty()) return QString::fromStdString(frame.note);
  return frame.layers > 0 ? QStringLiteral("every layer is hidden") : QStringLiteral("no layers");
}

QString describe_shown_view(const FrameReport& r, const ReusePolicy& policy) {
  const double error = r.measured_error_px;
  const QString off = std::isfinite(error) && error < kExactTolerancePx
                          ? QStringLiteral("exact: %1 px from the exact projection").arg(px(error))
                          : QStringLiteral("%1 px off the exact projection").arg(px(error));
  if (r.level != Level::kRerender)
    return QStringLiteral("%1: %2").arg(reuse_words(policy, r.level), off);
  const QString how = r.frame == 0 ? QStringLiteral("rendered") : QStringLiteral("re-rendered");
  if (policy.initial_view == InitialView::kAffinePart) {
    return QStringLiteral(
               "%1 as the %2 policy's affine initial view of section 6.5 (the affine "
               "part of the exact warp about the texture centre): %3; the affine view "
               "alone is %4 px off")
        .arg(how, QString::fromUtf8(policy.name), off, px(r.affine_view_error_px));
  }
  return QStringLiteral("%1 from the texture with the exact projection: %2").arg(how, off);
}

QString explain_frame(const AnimationFrame& frame, const EngineSettings& settings) {
  if (frame.layer_reports.size() != 1) return layers_summary(frame, *settings.policy);
  const FrameReport& r = frame.layer_reports.front();
  if (!r.visible) {
    return QStringLiteral("<b>Frame %1</b>: the plane is not drawn (%2).")
        .arg(r.frame)
        .arg(r.note.empty() ? QStringLiteral("not visible") : QString::fromStdString(r.note));
  }
  QString text = QStringLiteral("<b>Frame %1: %2</b><br>Shown: %3.")
                     .arg(r.frame)
                     .arg(QString::fromLatin1(level_word(*settings.policy, r.level)))
                     .arg(describe_shown_view(r, *settings.policy).toHtmlEscaped());
  if (r.frame == 0) return text;
  if (settings.policy->schedule == Schedule::kCadence) {
    text += QStringLiteral(
                "<br>The %1 policy renders one frame in %2 and reprojects the frames between, "
                "whatever their error. Algorithm 1's choice, for comparison:<br>")
                .arg(QString::fromUtf8(settings.policy->name))
                .arg(settings.cadence);
  } else {
    text += QStringLiteral(
        "<br>The cheapest level whose neglected error stays within its "
        "threshold wins:<br>");
  }
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
  text += QStringLiteral(
              "Flow this frame (translation, affine, perspective, higher): "
              "%1, %2, %3, %4 px<br>")
              .arg(px(r.flow[0]), px(r.flow[1]), px(r.flow[2]), px(r.flow[3]));
  text += QStringLiteral("Carried in: %1, %2, %3, %4 px; carried on: %5, %6, %7, %8 px<br>")
              .arg(px(r.carried[0]), px(r.carried[1]), px(r.carried[2]), px(r.carried[3]))
              .arg(px(r.accumulated[0]), px(r.accumulated[1]), px(r.accumulated[2]),
                   px(r.accumulated[3]));
  text += QStringLiteral(
              "Estimated error %1 px; measured (corners against the exact "
              "projection) %2 px; engine time %3 ms.")
              .arg(px(r.estimated_error_px), px(r.measured_error_px))
              .arg(r.time_ms, 0, 'f', 2);
  if (settings.policy->initial_view == InitialView::kAffinePart) {
    text += QStringLiteral(
                "<br>Why they differ: the estimate bounds the error against the %1 policy's "
                "own affine view of the pose; that view alone is %2 px off the exact "
                "projection (an affine view has no foreshortening), and reuse adds %3 px.")
                .arg(QString::fromUtf8(settings.policy->name), px(r.affine_view_error_px),
                     px(r.reuse_error_px));
  }
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
  const Vec2 centred = pixel_to_centred(animator.camera(), Vec2(x + 0.5, y + 0.5));
  return QStringLiteral("pixel (%1, %2) px from the principal point: %3, engine %4, exact %5")
      .arg(centred.x, 0, 'f', 1)
      .arg(centred.y, 0, 'f', 1)
      .arg(level, colour(shown, x, y), colour(exact, x, y));
}

}  // namespace oflab
