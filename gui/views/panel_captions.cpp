#include "views/panel_captions.h"

#include <QObject>
#include <algorithm>
#include <cmath>

#include "adapters/frame_images.h"
#include "views/reprojection_controls.h"

namespace oflab {
namespace {

// "202 k", "8.4 M": a pixel count for a caption, short enough for a projector's panel.
QString count_text(double n) {
  if (n >= 1e6) return QString::number(n / 1e6, 'f', 1) + QStringLiteral(" M");
  if (n >= 1e3) return QString::number(n / 1e3, 'f', 0) + QStringLiteral(" k");
  return QString::number(n, 'f', 0);
}

}  // namespace

QString affine_view_line(const AnimationFrame& frame, const ReusePolicy& policy) {
  if (policy.initial_view != InitialView::kAffinePart) return {};
  double view = 0.0, reuse = 0.0;
  bool drawn = false;
  for (const FrameReport& r : frame.layer_reports) {
    if (!r.visible) continue;
    drawn = true;
    view = std::max(view, r.affine_view_error_px);
    if (std::isfinite(r.reuse_error_px)) reuse = std::max(reuse, r.reuse_error_px);
  }
  if (!drawn) return {};
  return QObject::tr("affine view %1 px off · reuse adds %2 px")
      .arg(view, 0, 'f', 2)
      .arg(reuse, 0, 'f', 2);
}

QStringList run_caption(const AnimationFrame& frame, const ReusePolicy& policy,
                        const EngineSettings& settings, double run_pixels, double run_ms,
                        double run_warped) {
  QStringList levels;
  for (int k = 0; k < kLevelCount; ++k) {
    const int n = frame.levels[size_t(k)];
    if (n == 0) continue;
    const QString name = QString::fromLatin1(level_word(policy, Level(k)));
    levels << (frame.layers > 1 ? QStringLiteral("%1 %2").arg(name).arg(n) : name);
  }
  if (levels.isEmpty()) levels << QObject::tr("nothing drawn");
  QStringList lines{QObject::tr("%1 · corner error %2 px")
                        .arg(levels.join(QStringLiteral(", ")))
                        .arg(frame.max_measured_error_px, 0, 'f', 2)};
  const int rendered = frame.levels[size_t(Level::kRerender)];
  if (policy.schedule == Schedule::kCadence && rendered > 0 && levels.size() == 1) {
    lines << QObject::tr("a render frame: rendered, not reprojected");
  }
  const QString view = affine_view_line(frame, policy);
  if (!view.isEmpty()) lines << view;
  if (policy.frame_plane == FramePlane::kStabilization) {
    lines << ReprojectionControls::plane_text(settings.stabilization);
  }
  lines << QObject::tr("%1 px, %2 ms (run %3 px, %4 ms)")
               .arg(count_text(double(frame.pixels_written)))
               .arg(frame.time_ms, 0, 'f', 1)
               .arg(count_text(run_pixels))
               .arg(run_ms, 0, 'f', 0);
  if (settings.warp_area == WarpArea::kVisible) {
    lines << QObject::tr("warped, what shows only: %1 px (run %2 px)")
                 .arg(count_text(double(frame.pixels_written - frame.pixels_not_warped)))
                 .arg(count_text(run_warped));
  }
  return lines;
}

QStringList sub_pixel_note(const AnimationFrame& frame) {
  if (frame.drawn() == 0 || !(frame.max_measured_error_px <= 1.0)) return {};
  return {QObject::tr("lit edges: sub-pixel shifts, resampling")};
}

QStringList agreement_caption(const Image& shown, const Image& exact) {
  return agreement_caption(frame_agreement(shown, exact));
}

QStringList agreement_caption(const FrameAgreement& a) {
  const QString psnr = std::isfinite(a.psnr_db)
                           ? QString::number(a.psnr_db, 'f', 1) + QStringLiteral(" dB")
                           : QObject::tr("equal");
  return {QObject::tr("coverage IoU %1 · PSNR %2").arg(a.mask_iou, 0, 'f', 3).arg(psnr)};
}

}  // namespace oflab
