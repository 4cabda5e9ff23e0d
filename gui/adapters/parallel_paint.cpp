#include "adapters/parallel_paint.h"

#include <QImage>
#include <QPaintDevice>
#include <algorithm>

#include "image/thread_pool.h"

namespace oflab {

bool paint_in_windows(QPainter& painter, const std::vector<QRect>& windows,
                      const std::function<void(QPainter&, int)>& paint) {
  return paint_in_windows(painter, windows, QRectF(), paint);
}

namespace {

// paint_in_windows's loop on the memory of `canvas` (a 32-bit format), its windows clipped to
// `clip` unless it is null.
bool paint_windows_of(QImage& canvas, const std::vector<QRect>& windows, const QRectF& clip,
                      const std::function<void(QPainter&, int)>& paint) {
  for (size_t a = 0; a < windows.size(); ++a) {
    for (size_t b = a + 1; b < windows.size(); ++b) {
      if (windows[a].intersects(windows[b])) return false;  // two threads would share pixels
    }
  }
  uchar* bits = canvas.bits();  // detached already (by the active painter, or the caller)
  const qsizetype line = canvas.bytesPerLine();
  const QRect bounds = canvas.rect();
  const QImage::Format format = canvas.format();
  for_each_band(int(windows.size()), 1, [&](int, int begin, int end) {
    for (int k = begin; k < end; ++k) {
      const QRect window = windows[size_t(k)].intersected(bounds);
      if (window.isEmpty()) continue;
      QImage part(bits + window.y() * line + window.x() * 4, window.width(), window.height(), line,
                  format);
      QPainter on_part(&part);
      if (!clip.isNull()) on_part.setClipRect(clip.translated(-window.x(), -window.y()));
      on_part.translate(-window.x(), -window.y());
      paint(on_part, k);
    }
  });
  return true;
}

}  // namespace

bool paint_in_windows(QPainter& painter, const std::vector<QRect>& windows, const QRectF& clip,
                      const std::function<void(QPainter&, int)>& paint) {
  QPaintDevice* device = painter.device();
  if (!device || device->devType() != QInternal::Image || !painter.transform().isIdentity())
    return false;
  QImage* canvas = static_cast<QImage*>(device);
  if (canvas->format() != QImage::Format_RGB32) return false;
  return paint_windows_of(*canvas, windows, clip, paint);
}

bool paint_image_in_windows(QImage& image, const std::vector<QRect>& windows,
                            const std::function<void(QPainter&, int)>& paint) {
  const QImage::Format format = image.format();
  if (format != QImage::Format_RGB32 && format != QImage::Format_ARGB32 &&
      format != QImage::Format_ARGB32_Premultiplied) {
    return false;
  }
  return paint_windows_of(image, windows, QRectF(), paint);
}

std::vector<QRect> row_strips(const QRect& rect, int count) {
  std::vector<QRect> strips;
  const int n = std::max(1, std::min(count, rect.height()));
  for (int k = 0; k < n; ++k) {
    const int top = rect.top() + rect.height() * k / n;
    const int bottom = rect.top() + rect.height() * (k + 1) / n;
    if (bottom > top) strips.emplace_back(rect.left(), top, rect.width(), bottom - top);
  }
  return strips;
}

}  // namespace oflab
